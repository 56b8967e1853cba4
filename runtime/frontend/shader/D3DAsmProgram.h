#pragma once
// A Direct3D 9 assembly shader (vs_1_1 … vs_3_0, ps_1_1 … ps_3_0) as D3DAsmParser reads it: the
// version and one instruction per statement, each with the line of the code it came from.

#include <array>
#include <string>
#include <vector>

namespace rmfx::d3dasm {

// A problem found in the code, at a line of it (1 = the code's first line).
struct Message {
    bool error = true;
    int line = 0;
    std::string text;
};

enum class RegisterType {
    Input,        // v#
    Temp,         // r#
    Const,        // c#
    ConstInt,     // i#
    ConstBool,    // b#
    Address,      // a0
    Texture,      // t#: vs_1_1… a texture coordinate input of a pixel shader, or a texture register
    Sampler,      // s#
    Loop,         // aL
    Predicate,    // p0
    OutPosition,  // oPos
    OutColor,     // oD0, oD1
    OutTexcoord,  // oT0 … oT7
    OutFog,       // oFog
    OutPointSize, // oPts
    OutPixel,     // oC0 … oC3
    OutDepth,     // oDepth
    Output,       // o# (vs_3_0)
    Face,         // vFace
    PixelPosition // vPos
};

enum class SourceModifier {
    None,
    Negate,      // -r0
    Bias,        // r0_bias: x - 0.5
    BiasNegate,  // -r0_bias
    Sign,        // r0_bx2: 2x - 1
    SignNegate,  // -r0_bx2
    Complement,  // 1-r0
    Times2,      // r0_x2 (ps_1_4)
    Times2Negate,
    Abs,         // r0_abs
    AbsNegate,
    DivideZ,     // r0_dz (ps_1_4 texld/texcrd): xy / z
    DivideW,     // r0_dw: xy / w
};

struct Source {
    RegisterType type = RegisterType::Temp;
    int index = 0;
    // c[a0.x + n]: the address register's component (0…3), or -1 when not relative
    int relativeComponent = -1;
    bool relativeToLoop = false;  // c[aL + n]
    std::array<int, 4> swizzle{0, 1, 2, 3};
    bool swizzled = false;  // a swizzle was written (scalar instructions read .w without one in vs_1_x)
    SourceModifier modifier = SourceModifier::None;
};

struct Destination {
    RegisterType type = RegisterType::Temp;
    int index = 0;
    unsigned mask = 0xF;  // bit 0 x … bit 3 w
};

// dcl_texcoord1 v2, dcl_2d s0, dcl t0.xy
struct Declaration {
    std::string usage;  // "position", "texcoord", "2d", "cube", "volume"; empty for a plain dcl
    int usageIndex = 0;
};

struct Instruction {
    std::string opcode;  // lower case, without modifiers: "mad", "dcl", "texm3x3pad"
    int line = 0;
    bool coissued = false;   // + prefix
    bool saturate = false;   // _sat
    int shift = 0;           // _x2 1, _x4 2, _x8 3, _d2 -1, _d4 -2, _d8 -3
    bool hasDestination = false;
    Destination destination;
    std::vector<Source> sources;
    std::array<float, 4> values{};  // def, defi, defb (defb: 0 or 1 in values[0])
    Declaration declaration;
    std::string comparison;  // setp_gt, if_lt…: "gt", "lt", …
};

struct Program {
    bool pixel = false;
    int major = 1, minor = 1;
    int line = 0;  // of the version token
    std::vector<Instruction> instructions;
};

}  // namespace rmfx::d3dasm
