#pragma once
// Direct3D 9's effect-framework texture variables (`texture grass;`, bound in a
// `sampler s = sampler_state { Texture = <grass>; … }`): fxc compiled a shader that declared them
// and ignored them, and RenderMonkey bound the sampler's texture from its RmTextureObject. glslang's
// HLSL front end knows no `texture` type and stops at the declaration ('declaration' : Expected;
// wrdn's HLSLACW.rfx), and cannot initialise a `sampler` from a sampler_state block. This step
// blanks both; the filtering and addressing come from the RmTextureObject's states, as they did.

#include <string>

namespace rmfx {

// `code` with each file-scope declaration whose type is the word `texture` (with or without a
// semantic, register or annotation) and each `= sampler_state { … }` turned into spaces, newlines
// kept: `sampler s = sampler_state { … };` becomes `sampler s;`.
std::string blankEffectTextures(const std::string& code);

}  // namespace rmfx
