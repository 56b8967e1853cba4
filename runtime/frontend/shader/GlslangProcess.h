#pragma once
// glslang's process-wide set-up, done once before the first in-process parse (validation's GLSL
// checks, the GLSL 1.20 retry); the HLSL worker, a program of its own, does its own.

namespace rmfx {

void initializeGlslangOnce();

}  // namespace rmfx
