#pragma once
// Direct3D 9 HLSL's untyped `sampler`: fxc let the texture function a shader reads it with give it
// its type (texCUBE a cube map, tex3D a volume), and RenderMonkey bound whatever texture its
// RmTextureObject named. glslang's HLSL front end takes every `sampler` for a 2D one, so a cube map
// read with texCUBE fails the pass. This step writes the type the reads imply before glslang
// reads the code.

#include <string>

namespace rmfx {

// `code` with each global `sampler NAME` that the shader reads only with texCUBE… (or only with
// tex3D…) declared samplerCUBE (sampler3D). One read only with tex1D(NAME, u) stays a 2D sampler
// and each read becomes tex2D(NAME, float2(u, 0.5)): Direct3D 9 has no 1D textures, RenderMonkey's
// are images one texel high (with tex1Dlod and the like among its reads it becomes sampler1D,
// which rmfx does not bind). A sampler read with tex2D…, with functions of two kinds, or not at
// all keeps `sampler`. Lines keep their place.
std::string typeGenericSamplers(const std::string& code);

}  // namespace rmfx
