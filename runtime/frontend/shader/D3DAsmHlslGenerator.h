#pragma once
// The generator behind translateAssembly (D3DAsmToHlsl.h): one Direct3D 9 assembly program to
// HLSL, line for line. Its declarations, operands and results are in D3DAsmToHlsl.cpp, its
// instructions (arithmetic, texture sampling, flow control) and the function's end in
// D3DAsmHlslInstructions.cpp. Internal to the frontend's shader code.

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "frontend/shader/D3DAsmToHlsl.h"

namespace rmfx::d3dasm::generation {

// A float as HLSL reads it back exactly (a ".0" where it has no point or exponent).
std::string number(float v);
std::string upper(std::string s);
// ".xyz" and so on without the dot: the components of a write mask.
const char* maskText(unsigned mask);
// Helpers the generated code calls, all on its first line.
extern const char* const kHelpers;

class Generator {
public:
    Generator(const Program& p, const std::vector<ConstantBinding>& constants, const std::vector<SamplerBinding>& samplers,
              const std::vector<InputRegister>& streams)
        : p_(p), constants_(constants), samplerBindings_(samplers), streams_(streams) {
        ps1x_ = p.pixel && p.major == 1;
        ps13_ = ps1x_ && p.minor <= 3;
        ps14_ = ps1x_ && p.minor == 4;
        vs1x_ = !p.pixel && p.major == 1;
    }

    HlslFromAsm run();

private:
    // --- messages -------------------------------------------------------------------------
    void error(int line, const std::string& text) { messages_.push_back({true, line, text}); }
    void warning(int line, const std::string& text) { messages_.push_back({false, line, text}); }
    void emit(const std::string& code) { emitAt(line_, code); }
    void emitAt(int line, const std::string& code);

    // --- declarations ---------------------------------------------------------------------
    static std::string usageSemantic(const Declaration& d);

    SamplerKind declaredKind(const std::string& usage);

    void declarations();

    void use(RegisterType t, int index, bool written, const Instruction& in);

    static const char* hlslType(ValueType t);

    // The constant registers a binding fills, and their values.
    std::vector<std::string> registersOf(const ConstantBinding& b);

    const SamplerBinding* binding(int stage) const;

    std::array<float, 4> bumpMatrix(int stage) const;

    std::string samplerName(int stage);

    SamplerKind samplerKind(int stage);

    // Declarations and the function's start, on line 1; the statements follow on their lines.
    void finishDeclarations(std::string& head, std::string& body);

    // How many constant registers the code can read: those it names, and with relative
    // addressing every one a variable or def fills.
    void countConstants();

    static bool scalarOutput(RegisterType t);

    std::string outputName(RegisterType t, int index) const;

    std::string outputSemantic(RegisterType t, int index);

    std::string parameters();

    // ps_1_1…1_3 read texture coordinate sets through texture instructions, t# being the texture
    // registers; the other versions read t# as the coordinates themselves.
    std::string texcoordName(int t) const { return ps13_ ? "rm_tc" + std::to_string(t) : "t" + std::to_string(t); }
    std::string texcoord(int t);

    // --- operands -------------------------------------------------------------------------
    std::string registerRead(const Source& s, int offset = 0);

    // The range of ps_1_x temporaries and texture registers: ±PixelShader1xMaxValue, which is 8 on
    // the hardware RenderMonkey ran on (ATI's since the R200, and every Direct3D 9 card, which
    // runs ps_1_4 and must reach 8 there), for ps_1_1…1_3 too (RAZD's PTM shader reaches 2).
    std::string range(bool low) const { return low ? "-8.0" : "8.0"; }

    std::string source(const Source& s, int offset = 0);

    // The component a scalar instruction reads: the replicated one, .w when none is written.
    std::string scalar(const Source& s) { return "(" + source(s) + ")." + (s.swizzled ? "x" : "w"); }

    // --- results --------------------------------------------------------------------------
    void write(const Instruction& in, std::string value, unsigned opMask = 0xF);

    bool need(const Instruction& in, size_t sources, bool destination = true);

    // --- sampling -------------------------------------------------------------------------
    enum class Fetch { Plain, Projected, Bias, Lod, Gradient };

    std::string sample(int stage, const std::string& coord, Fetch fetch = Fetch::Plain, const std::string& ddx = "",
                       const std::string& ddy = "");

    // ps_1_1…1_3 texture address instructions that take the coordinates of their own stage.
    std::string texcoordDot(const Instruction& in);

    bool texRegister(const Instruction& in, size_t sources);

    // --- instructions ---------------------------------------------------------------------
    void instruction(const Instruction& in);

    void matrix(const Instruction& in);

    bool texture(const Instruction& in);

    std::string compare(const std::string& c);

    bool flow(const Instruction& in);

    void finish();

    const Program& p_;
    const std::vector<ConstantBinding>& constants_;
    const std::vector<SamplerBinding>& samplerBindings_;
    const std::vector<InputRegister>& streams_;
    bool ps1x_ = false, ps13_ = false, ps14_ = false, vs1x_ = false;
    std::vector<std::string> lines_;
    int lastLine_ = 1, line_ = 1, constCount_ = 1;
    std::vector<std::pair<std::string, int>> blocks_;  // open if/rep/loop and their lines
    std::vector<Message> messages_;
    std::map<int, std::string> inputSemantics_, outputSemantics_;
    std::map<int, SamplerKind> samplerKinds_;
    std::map<int, std::array<float, 4>> defined_, intDefined_;
    std::map<int, bool> boolDefined_;
    std::set<int> temps_, constUsed_, inputs_, textures_, texcoords_, texcoordInputs_, samplersUsed_;
    std::map<int, int> firstConstLine_, firstInputLine_, samplerLines_;
    std::set<std::pair<RegisterType, int>> outputs_;
    int relativeReach_ = 0;
    bool relative_ = false, addressUsed_ = false, faceUsed_ = false, positionUsed_ = false;
};

}  // namespace rmfx::d3dasm::generation
