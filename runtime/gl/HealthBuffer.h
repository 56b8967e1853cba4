#pragma once
// The storage buffer the health check (GlHealthCheck.h) counts into, as 32-bit words: the GPU
// writes it from two kinds of shader (the check's own inspection draws, and the passes' fragment
// shaders made to count what they write: HealthInstrumentation.h), the CPU reads it once a frame.
//
//   entries: per pass position p and kind k, at word (p * 5 + k) * kEntryWords:
//            count of pixels, first pixel (y * width + x, GL's row 0 at the bottom), records taken, 0
//   records: from word recordsBase(capacity), per (p, k) kRecordSlots slots of kRecordWords:
//            pixel, 0, 0, 0, value (4 floats), inputs' texels (kMaxInputs x 4 floats)
//
// A fragment that lowers the first pixel takes the next record slot and writes its pixel, value
// and inputs there: with thousands of fragments in flight no single slot could be written
// without a race, and the one holding the first pixel is picked on reading. A pixel found only
// after all the slots went to earlier improvements leaves its value unrecorded (HealthFinding).
// Rasterisers work from GL's row 0 upwards, so "first" counts rows from the bottom: in reading
// order (top row first) every row drawn after the last lowers the first pixel again, and a
// 256x256 target of NaN took more than 32 slots on llvmpipe; counted from the bottom, a few.

#include <cstddef>

#include "model/TargetHealth.h"

namespace rmfx {

inline constexpr int kHealthEntryWords = 4;
inline constexpr int kHealthRecordSlots = 32;
inline constexpr int kHealthMaxInputs = 8;
inline constexpr int kHealthRecordWords = 8 + 4 * kHealthMaxInputs;

// The first word of the records when the buffer holds `passes` pass positions.
constexpr std::size_t healthRecordsBase(std::size_t passes) { return passes * healthKindCount * kHealthEntryWords; }

// The binding point of the buffer in every shader that writes it: the last one the context has,
// which a workspace's own shaders are least likely to use. Needs a current GL context.
int healthBufferBinding();

}  // namespace rmfx
