#pragma once
// A Direct3D effect's RmShader (assembly) → an HLSL ShaderSource: the code is parsed
// (D3DAsmParser) and written as HLSL (D3DAsmToHlsl) with the pass's constants, samplers and
// stream registers, so that rmfx's HLSL path compiles it like an RmHLSLShader.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "frontend/rfx/detail/RfxElement.h"
#include "frontend/shader/D3DAsmToHlsl.h"
#include "model/Workspace.h"

namespace rmfx::rfx {

struct AssemblyContext {
    // The variable a constant of that name reads (pass, effect, group, workspace), or null.
    std::function<const Variable*(const std::string&)> variable;
    std::vector<d3dasm::SamplerBinding> samplers;  // the pass's texture objects, by STATE_INDEX
    std::vector<d3dasm::InputRegister> streams;    // the stream map's channels, by REGISTER
    bool passEnabled = true;  // a disabled pass's problems are warnings: it is left out
};

// The translated shader; nullopt when it cannot run, with `why` saying so for the pass's message.
// Problems in the code are reported at their line of the .rfx, naming the element.
std::optional<ShaderSource> readAssemblyShader(const RfxElement& shader, const AssemblyContext& context, std::string& why);

}  // namespace rmfx::rfx
