#pragma once
// rmfx render --input scene=shot/frame.%04d.exr -o out/frame.%04d.png: one rendered frame per
// image of a sequence, in frame order, with dt = 1 / fps, so light adaptation and every
// frame="previous" target carry across frames as they do in a live run. Needs a current GL context.

#include <functional>
#include <optional>
#include <string>
#include <utility>

#include <glm/vec2.hpp>

#include "core/Result.h"
#include "gl/GlExecutor.h"
#include "io/image/ImageIO.h"
#include "model/Workspace.h"
#include "validation/ImageInputs.h"
#include "validation/Validation.h"

namespace rmfx {

struct SequenceSettings {
    std::string input;          // the <input> the frames fill; empty: the workspace's only input
    std::string inputPattern;   // shot/frame.%04d.exr (io/media/ImageSequence.h)
    std::string layer;          // an EXR part or layer of every frame; empty: the default
    std::vector<InputArgument> staticInputs;  // images for other <input>s, the same for every frame
    std::string outputPattern;  // out/frame.%04d.png: each frame keeps its input's number
    std::string target;         // what is written; empty: the workspace's output
    WriteOptions write;
    double fps = 24.0;
    // The step between frames; none: 1 / fps.
    std::optional<double> deltaTime;
    // Frames of warm-up before the first frame written, so that light adaptation and every
    // frame="previous" target start settled on the shot. Without a frame range: the first image
    // rendered `preroll` times (time runs from -preroll · dt, so the written frames keep their
    // times). With one: the chunk's warm-up, the last `preroll` frames of that whole run before the
    // range's first frame (io/media/SequenceChunk.h).
    int preroll = 0;
    // The frames written, by the numbers in their file names, first and last included; none: all.
    // Each frame runs at the time the whole shot's run gives it (its place in the shot · dt).
    std::optional<std::pair<int, int>> frameRange;
    std::optional<glm::ivec2> size;  // the viewport; none: the first frame's size
    // Read the next image and write the last while the GPU renders (off: one after the other,
    // for the benchmark's comparison).
    bool overlap = true;
    // Seconds a frame may take, GPU work included (FrameWatchdog, as RunSettings); 0: no limit.
    double frameBudgetSeconds = 0.0;
    std::function<void(const std::string&)> onFrameBudget;
    // The programs validation assembled for the workspace (compile/RunPreparation.h's LoadedRun),
    // so that they are not assembled again; null: assembled here.
    const CheckedPrograms* programs = nullptr;
};

struct SequenceProgress {
    int done = 0;   // frames written
    int total = 0;
    double seconds = 0.0;  // since the first frame was read
};

// Wall-clock seconds summed over the frames, per stage, and the whole run's.
struct SequenceTimes {
    int frames = 0;       // written
    int warmUpFrames = 0;  // rendered before the first written: pre-roll and the frames before a range
    double read = 0.0;    // decoding (and resampling) each image, the first included
    double render = 0.0;  // uploading the image, the frame's passes, reading the target back
    double write = 0.0;   // encoding and writing each output file
    double total = 0.0;   // from the start (finding the files, building the workspace) to the last write
};

// Fails naming the file of the first frame that cannot be read or written, after every earlier
// frame was written; the files written stay. Warnings: how the first image was decoded.
Result<SequenceTimes> renderSequence(const Workspace& ws, const SequenceSettings& settings, ExecutorOptions options,
                                     const std::function<void(const SequenceProgress&)>& progress = {});

}  // namespace rmfx
