#pragma once
// A chunk of a shot rendered on its own (one render-farm task, one Dask task) so that its frames come
// out as one run of the whole shot gives them. The whole run with pre-roll N renders the first image
// N times at times -N·dt … -dt, then frame k (0-based in the shot) at k·dt. A chunk whose first
// written frame is k renders the last N frames of that timeline before k as its warm-up: the images
// of frames max(0, k - N) … k - 1 at their own times, and, where that reaches back before the shot,
// the first image at the negative times the whole run gives it. So every frame runs at the whole
// run's time with the whole run's image: an effect without frame-to-frame state gives the whole
// run's pixels bit for bit, and one with state (light adaptation, frame="previous" targets) starts N
// frames early from its initial values, which it forgets as its own maths says (docs/sequences.md).

namespace rmfx {

struct SequenceChunk {
    int start = 0;    // the first image the chunk reads (0-based in the shot): its warm-up's first
    int preroll = 0;  // frames of image `start` before it, at times (start - preroll … start - 1)·dt
    int skip = 0;     // frames start … start + skip - 1 rendered as warm-up, not written
};

// first: the chunk's first written frame (0-based in the shot, ≥ 0); preroll: the N of the whole run
// and of every chunk (≥ 0). The chunk with first 0 is the whole run's beginning: {0, N, 0}.
SequenceChunk planSequenceChunk(int first, int preroll);

}  // namespace rmfx
