#pragma once
// Where a shader element of an .rfx keeps its code: an <RmShaderCode> child (RenderMonkey 1.5 and
// later), or, in RenderMonkey 1.0's files (ShaderX³'s CD, for one), the CODE attribute, with the
// shader's constants in a DECLARATION_BLOCK attribute that RenderMonkey compiled before it.

#include <optional>
#include <string>

#include "frontend/rfx/detail/RfxElement.h"

namespace rmfx::rfx {

struct RfxShaderCode {
    std::string code;
    int line = 0;  // of the code's first line in the file; attribute code: the element's line
};

// Nothing (and an error on the element) when it has neither.
std::optional<RfxShaderCode> shaderCodeOf(const RfxElement& shader);

}  // namespace rmfx::rfx
