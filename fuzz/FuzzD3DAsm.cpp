// Fuzz target "d3d_asm": Direct3D 9 shader assembly through D3DAsmParser and D3DAsmToHlsl, with
// constants, samplers and stream registers bound as an RmShader's would be. Properties: every
// message names a line of the input; the HLSL keeps the input's lines (as many lines as the last
// one holding a statement or the version), so compiler messages map back.

#include <algorithm>

#include "frontend/shader/D3DAsmParser.h"
#include "frontend/shader/D3DAsmToHlsl.h"
#include "fuzz/FuzzEntries.h"

namespace rmfx::fuzz {

void fuzzD3DAsm(const std::uint8_t* data, std::size_t size) {
    const std::string code(reinterpret_cast<const char*>(data), size);
    const int lines = static_cast<int>(std::count(code.begin(), code.end(), '\n')) + 1;
    auto checkLines = [&](const std::vector<d3dasm::Message>& messages) {
        for (const d3dasm::Message& m : messages)
            fuzzCheck(m.line >= 1 && m.line <= lines,
                      "message at line " + std::to_string(m.line) + " of " + std::to_string(lines) + ": " + m.text);
    };
    d3dasm::ParseResult parsed = d3dasm::parseAssembly(code);
    checkLines(parsed.messages);
    if (!parsed.ok()) return;
    const std::vector<d3dasm::ConstantBinding> constants = {
        {"wvp", 0, ValueType::Mat4, 0}, {"light", 4, ValueType::Vec4, 0},
        {"scale", 5, ValueType::Float, 0}, {"stored", 6, ValueType::Mat4, 0},
        {"offset", 10, ValueType::Vec3, 0}};
    const std::vector<d3dasm::SamplerBinding> samplers = {
        {"base", 0, d3dasm::SamplerKind::Texture2D}, {"env", 1, d3dasm::SamplerKind::Cube}, {"vol", 2, d3dasm::SamplerKind::Volume}};
    const std::vector<d3dasm::InputRegister> streams = {{0, "POSITION0"}, {1, "NORMAL0"}, {2, "TEXCOORD0"}, {3, "TANGENT0"}};
    d3dasm::HlslFromAsm hlsl = d3dasm::translateAssembly(parsed.program, constants, samplers, streams);
    checkLines(hlsl.messages);
    int last = std::max(1, parsed.program.line);
    for (const d3dasm::Instruction& in : parsed.program.instructions) last = std::max(last, in.line);
    const int hlslLines = static_cast<int>(std::count(hlsl.hlsl.begin(), hlsl.hlsl.end(), '\n'));
    fuzzCheck(hlslLines == last, "the HLSL has " + std::to_string(hlslLines) + " lines, the assembly's last statement is on line " +
                                     std::to_string(last));
}

}  // namespace rmfx::fuzz
