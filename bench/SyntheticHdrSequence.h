#pragma once
// A deterministic HDR image sequence for benchmarks: a dim room-like gradient lit by a few lights
// far above 1 (so a bright pass, a bloom and a star have work to do) that move from frame to
// frame, with a little per-pixel noise, as a rendered or filmed frame has (so EXR's compression
// has real work to do too). The same frame number and size give the same pixels.

#include <filesystem>
#include <string>

#include <glm/vec2.hpp>

#include "core/Result.h"
#include "model/Image.h"

namespace rmfx::bench {

// Frame `frame` as linear RGBA float, alpha 1.
Image syntheticHdrFrame(int frame, glm::ivec2 size);

// Writes frames 0 … count-1 as half-float RGBA EXR files folder/frame.0000.exr, … (the folder
// must exist) and returns their pattern, folder/frame.%04d.exr. Errors name the file.
Result<std::string> writeSyntheticHdrSequence(const std::filesystem::path& folder, int count, glm::ivec2 size);

}  // namespace rmfx::bench
