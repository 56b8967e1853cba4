#include "frontend/shader/D3DAsmToHlsl.h"

#include <cctype>
#include <sstream>

#include "frontend/shader/D3DAsmHlslGenerator.h"
#include "frontend/shader/D3DAsmHlslNames.h"

namespace rmfx::d3dasm {
namespace generation {

std::string number(float v) {
    std::ostringstream s;
    s.precision(9);
    s << v;
    std::string t = s.str();
    if (t.find_first_of(".eEn") == std::string::npos) t += ".0";
    return t;
}

std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

const char* maskText(unsigned mask) {
    static const char* texts[16] = {"",   "x",   "y",   "xy",   "z",   "xz",   "yz",   "xyz",
                                    "w",  "xw",  "yw",  "xyw",  "zw",  "xzw",  "yzw",  "xyzw"};
    return texts[mask & 0xF];
}

const char* const kHelpers =
    "float4 rm_rep(float x) { return float4(x, x, x, x); } "
    "float4 rm_cmp(float4 a, float4 b, float4 c) { return float4(a.x >= 0.0 ? b.x : c.x, a.y >= 0.0 ? b.y : c.y, "
    "a.z >= 0.0 ? b.z : c.z, a.w >= 0.0 ? b.w : c.w); } "
    "float4 rm_cnd(float4 a, float4 b, float4 c) { return float4(a.x > 0.5 ? b.x : c.x, a.y > 0.5 ? b.y : c.y, "
    "a.z > 0.5 ? b.z : c.z, a.w > 0.5 ? b.w : c.w); } "
    "float4 rm_lit(float4 s) { float4 d = float4(1.0, 0.0, 0.0, 1.0); float p = clamp(s.w, -127.9961, 127.9961); "
    "if (s.x > 0.0) { d.y = s.x; if (s.y > 0.0) d.z = pow(s.y, p); } return d; } "
    "float4 rm_nrm(float4 v) { return v * (1.0 / sqrt(dot(v.xyz, v.xyz))); } "
    "float4 rm_expp(float x) { float f = floor(x); return float4(exp2(f), x - f, exp2(x), 1.0); } "
    "float4 rm_logp(float x) { float a = abs(x); if (a == 0.0) return float4(-1e38, 1.0, -1e38, 1.0); "
    "float e = floor(log2(a)); return float4(e, a / exp2(e), log2(a), 1.0); } ";

HlslFromAsm Generator::run() {
    HlslFromAsm out;
    out.profile = p_.pixel ? "ps_3_0" : "vs_3_0";
    lastLine_ = std::max(1, p_.line);
    for (const Instruction& in : p_.instructions) lastLine_ = std::max(lastLine_, in.line);
    lines_.assign(static_cast<size_t>(lastLine_) + 1, "");
    declarations();
    countConstants();
    for (const Instruction& in : p_.instructions) {
        line_ = in.line;
        instruction(in);
    }
    if (!blocks_.empty()) error(blocks_.back().second, blocks_.back().first + " is never closed (no matching end)");
    finish();
    out.messages = std::move(messages_);
    std::string text;
    for (size_t k = 1; k < lines_.size(); ++k) {
        text += lines_[k];
        text += '\n';
    }
    out.hlsl = std::move(text);
    return out;
}

void Generator::emitAt(int line, const std::string& code) {
    std::string& l = lines_[static_cast<size_t>(std::clamp(line, 1, lastLine_))];
    if (!l.empty()) l += ' ';
    l += code;
}

std::string Generator::usageSemantic(const Declaration& d) {
    std::string u = upper(d.usage);
    return u + std::to_string(d.usageIndex);
}

SamplerKind Generator::declaredKind(const std::string& usage) {
    if (usage == "2d") return SamplerKind::Texture2D;
    if (usage == "cube") return SamplerKind::Cube;
    if (usage == "volume") return SamplerKind::Volume;
    return SamplerKind::Unknown;
}

void Generator::declarations() {
    // Semantics of inputs and outputs from dcl, constants from def*, registers in use.
    for (const Instruction& in : p_.instructions) {
        if (in.opcode == "dcl") {
            const Destination& d = in.destination;
            if (!in.hasDestination) continue;
            if (d.type == RegisterType::Sampler) {
                SamplerKind k = declaredKind(in.declaration.usage);
                if (k == SamplerKind::Unknown) {
                    error(in.line, "dcl_" + in.declaration.usage + ": unknown sampler type (2d, cube, volume)");
                    continue;
                }
                samplerKinds_[d.index] = k;
            } else if (d.type == RegisterType::Input && !p_.pixel) {
                if (in.declaration.usage.empty()) error(in.line, "dcl of a vertex input needs a usage (dcl_position v0…)");
                else inputSemantics_[d.index] = usageSemantic(in.declaration);
            } else if (d.type == RegisterType::Input && p_.pixel && p_.major >= 3) {
                inputSemantics_[d.index] = in.declaration.usage.empty() ? "COLOR" + std::to_string(d.index)
                                                                        : usageSemantic(in.declaration);
            } else if (d.type == RegisterType::Output) {
                outputSemantics_[d.index] = usageSemantic(in.declaration);
            }
            continue;
        }
        if (in.opcode == "def" || in.opcode == "defi" || in.opcode == "defb") {
            const RegisterType want = in.opcode == "def" ? RegisterType::Const
                                      : in.opcode == "defi" ? RegisterType::ConstInt : RegisterType::ConstBool;
            if (in.destination.type != want) {
                error(in.line, in.opcode + " defines " + std::string(in.opcode == "def" ? "c#" : in.opcode == "defi" ? "i#" : "b#") +
                                   " registers");
                continue;
            }
            if (want == RegisterType::Const) defined_[in.destination.index] = in.values;
            else if (want == RegisterType::ConstInt) intDefined_[in.destination.index] = in.values;
            else boolDefined_[in.destination.index] = in.values[0] != 0.0f;
            continue;
        }
        if (in.hasDestination) use(in.destination.type, in.destination.index, true, in);
        for (size_t k = 0; k < in.sources.size(); ++k) {
            const Source& s = in.sources[k];
            int rows = 1;
            if (k == 1 && in.opcode.size() == 4 && in.opcode[0] == 'm' && in.opcode[2] == 'x') rows = in.opcode[3] - '0';
            const bool relative = s.relativeComponent >= 0 || s.relativeToLoop;
            relative_ = relative_ || relative;
            // A relative read may reach any register: it counts towards their number, and is
            // not warned about as an unset one.
            for (int r = 0; r < rows; ++r) {
                if (relative && s.type == RegisterType::Const) relativeReach_ = std::max(relativeReach_, s.index + r + 1);
                else use(s.type, s.index + r, false, in);
            }
        }
    }
}

void Generator::use(RegisterType t, int index, bool written, const Instruction& in) {
    // Direct3D 9's largest register files: 256 constants (vs), 32 temporaries, 16 of the others.
    const int limit = t == RegisterType::Const ? 256 : t == RegisterType::Temp ? 32 : 16;
    if (index >= limit) {
        error(in.line, "register index " + std::to_string(index) + " is beyond Direct3D 9's " + std::to_string(limit) +
                           " registers of its kind");
        return;
    }
    switch (t) {
        case RegisterType::Temp: temps_.insert(index); break;
        case RegisterType::Const:
            if (written) error(in.line, "c" + std::to_string(index) + " is a constant register: it cannot be written");
            constUsed_.insert(index);
            firstConstLine_.try_emplace(index, in.line);
            break;
        case RegisterType::Input:
            if (written) error(in.line, "v" + std::to_string(index) + " is an input register: it cannot be written");
            inputs_.insert(index);
            firstInputLine_.try_emplace(index, in.line);
            break;
        case RegisterType::Texture:
            if (!p_.pixel) {
                error(in.line, "t# registers exist only in pixel shaders");
                break;
            }
            if (ps13_) textures_.insert(index);
            else if (written && !ps14_) error(in.line, "t" + std::to_string(index) + " is an input register: it cannot be written");
            if (!ps13_) texcoords_.insert(index);
            break;
        case RegisterType::Sampler:
            break;
        case RegisterType::OutPosition: case RegisterType::OutColor: case RegisterType::OutTexcoord:
        case RegisterType::OutFog: case RegisterType::OutPointSize: case RegisterType::Output:
            if (p_.pixel) error(in.line, "a vertex shader output register in a pixel shader");
            else if (!written) error(in.line, "output registers cannot be read");
            else outputs_.insert({t, index});
            break;
        case RegisterType::OutPixel: case RegisterType::OutDepth:
            if (!p_.pixel) error(in.line, "a pixel shader output register in a vertex shader");
            else if (!written) error(in.line, "output registers cannot be read");
            else if (ps1x_) error(in.line, "ps_1_x writes its colour to r0, not to oC#/oDepth");
            else outputs_.insert({t, index});
            break;
        case RegisterType::Address:
            if (p_.pixel) error(in.line, "the address register a0 exists only in vertex shaders");
            addressUsed_ = true;
            break;
        case RegisterType::ConstInt: case RegisterType::ConstBool: case RegisterType::Loop:
            if (written) error(in.line, "this register cannot be written");
            break;
        case RegisterType::Predicate:
            error(in.line, "predicate registers (p0) are not supported");
            break;
        case RegisterType::Face: case RegisterType::PixelPosition:
            if (!p_.pixel) error(in.line, "vFace and vPos exist only in pixel shaders");
            else if (t == RegisterType::Face) faceUsed_ = true;
            else positionUsed_ = true;
            break;
    }
}

const char* Generator::hlslType(ValueType t) {
    switch (t) {
        case ValueType::Float: return "float";
        case ValueType::Int: return "int";
        case ValueType::Bool: return "bool";
        case ValueType::Vec2: return "float2";
        case ValueType::Vec3: case ValueType::Color3: return "float3";
        case ValueType::Vec4: case ValueType::Color4: return "float4";
        case ValueType::Mat2: return "float2x2";
        case ValueType::Mat3: return "float3x3";
        case ValueType::Mat4: return "float4x4";
    }
    return "float4";
}

std::vector<std::string> Generator::registersOf(const ConstantBinding& b) {
    const std::string& n = b.name;
    switch (b.type) {
        case ValueType::Float: case ValueType::Int: case ValueType::Bool:
            return {"float4(float(" + n + "), 0.0, 0.0, 0.0)"};
        case ValueType::Vec2: return {"float4(" + n + ", 0.0, 0.0)"};
        case ValueType::Vec3: case ValueType::Color3: return {"float4(" + n + ", 0.0)"};
        case ValueType::Vec4: case ValueType::Color4: return {n};
        case ValueType::Mat2: case ValueType::Mat3: case ValueType::Mat4: {
            const int size = b.type == ValueType::Mat2 ? 2 : b.type == ValueType::Mat3 ? 3 : 4;
            std::vector<std::string> rows;
            for (int i = 0; i < size; ++i) {
                std::string parts;
                for (int j = 0; j < 4; ++j) {
                    if (j) parts += ", ";
                    if (j >= size) parts += "0.0";
                    // HLSL row i: VALUE_4i… of a stored matrix, row i of a semantic one.
                    else parts += n + "[" + std::to_string(i) + "][" + std::to_string(j) + "]";
                }
                rows.push_back("float4(" + parts + ")");
            }
            return rows;
        }
    }
    return {};
}

const SamplerBinding* Generator::binding(int stage) const {
    for (const SamplerBinding& b : samplerBindings_)
        if (b.stage == stage) return &b;
    return nullptr;
}

std::array<float, 4> Generator::bumpMatrix(int stage) const {
    const SamplerBinding* b = binding(stage);
    return b ? b->bumpMatrix : std::array<float, 4>{};
}

std::string Generator::samplerName(int stage) {
    for (const SamplerBinding& b : samplerBindings_)
        if (b.stage == stage) return b.name;
    return "rm_asm_sampler" + std::to_string(stage);
}

SamplerKind Generator::samplerKind(int stage) {
    if (auto k = samplerKinds_.find(stage); k != samplerKinds_.end()) return k->second;
    for (const SamplerBinding& b : samplerBindings_)
        if (b.stage == stage && b.kind != SamplerKind::Unknown) return b.kind;
    return SamplerKind::Texture2D;
}

void Generator::finishDeclarations(std::string& head, std::string& body) {
    head += kHelpers;
    // Globals: the bound variables, then the samplers in use.
    std::set<std::string> declared;
    std::vector<std::pair<int, std::string>> bound;
    for (const ConstantBinding& b : constants_) {
        std::vector<std::string> regs = registersOf(b);
        if (b.firstRegister < 0 || b.firstRegister + static_cast<int>(regs.size()) > 256) {
            error(b.line > 0 ? b.line : 1, "constant '" + b.name + "' at register c" + std::to_string(b.firstRegister) +
                                               " is outside c0…c255");
            continue;
        }
        if (!hlslIdentifier(b.name)) {
            error(b.line > 0 ? b.line : 1, "the variable '" + b.name + "' of register c" + std::to_string(b.firstRegister) +
                                               " cannot be an HLSL global of that name (a keyword, a register's name "
                                               "or not an identifier), through which rmfx would bind it");
            continue;
        }
        if (declared.insert(b.name).second) head += std::string(hlslType(b.type)) + " " + b.name + "; ";
        for (size_t i = 0; i < regs.size(); ++i) bound.push_back({b.firstRegister + static_cast<int>(i), regs[i]});
    }
    for (int stage : samplersUsed_) {
        const char* type = "sampler2D";
        SamplerKind k = samplerKind(stage);
        if (k == SamplerKind::Cube) type = "samplerCUBE";
        else if (k == SamplerKind::Volume) type = "sampler3D";
        std::string name = samplerName(stage);
        if (!hlslIdentifier(name) && name.rfind("rm_asm_sampler", 0) != 0) {
            error(samplerLines_[stage], "the sampler '" + name + "' of stage " + std::to_string(stage) +
                                            " cannot be an HLSL global of that name");
            continue;
        }
        if (name.rfind("rm_asm_sampler", 0) == 0)
            warning(samplerLines_[stage], "no texture object is bound to sampler stage " + std::to_string(stage) +
                                              " (an RmTextureObject or RmSampler of register " + std::to_string(stage) + ")");
        if (declared.insert(name).second) head += std::string(type) + " " + name + "; ";
    }
    // The constant registers: bound variables first; def wins, as in Direct3D.
    body += "float4 c[" + std::to_string(constCount_) + "]; for (int rm_k = 0; rm_k < " + std::to_string(constCount_) +
            "; ++rm_k) c[rm_k] = float4(0.0, 0.0, 0.0, 0.0); ";
    std::set<int> set;
    for (auto& [reg, value] : bound) {
        if (reg >= constCount_) continue;
        body += "c[" + std::to_string(reg) + "] = " + value + "; ";
        set.insert(reg);
    }
    for (auto& [reg, v] : defined_) {
        body += "c[" + std::to_string(reg) + "] = float4(" + number(v[0]) + ", " + number(v[1]) + ", " + number(v[2]) +
                ", " + number(v[3]) + "); ";
        set.insert(reg);
    }
    for (int reg : constUsed_)
        if (!set.count(reg))
            warning(firstConstLine_[reg], "c" + std::to_string(reg) +
                                              " is neither defined (def) nor set by an RmShaderConstant: Direct3D left it "
                                              "unset, so it reads 0");
    // defi values are whole numbers (the parser checks); kept as floats, the largest rounds up.
    auto integer = [](float f) {
        return std::to_string(static_cast<long long>(std::clamp<double>(f, -2147483648.0, 2147483647.0)));
    };
    for (auto& [reg, v] : intDefined_)
        body += "int4 i" + std::to_string(reg) + " = int4(" + integer(v[0]) + ", " + integer(v[1]) + ", " + integer(v[2]) +
                ", " + integer(v[3]) + "); ";
    for (auto& [reg, v] : boolDefined_) body += "bool b" + std::to_string(reg) + " = " + (v ? "true" : "false") + "; ";
    for (int r : temps_) body += "float4 r" + std::to_string(r) + " = float4(0.0, 0.0, 0.0, 0.0); ";
    for (int t : textures_) body += "float4 t" + std::to_string(t) + " = float4(0.0, 0.0, 0.0, 0.0); ";
    if (addressUsed_) body += "int4 a0 = int4(0, 0, 0, 0); ";
    for (auto [type, index] : outputs_) {
        if (scalarOutput(type)) body += outputName(type, index) + " = 0.0; ";
        else body += outputName(type, index) + " = float4(0.0, 0.0, 0.0, " + (type == RegisterType::OutPosition ? "1.0" : "0.0") + "); ";
    }
}

void Generator::countConstants() {
    int count = std::max(1, std::min(256, relativeReach_));
    for (int c : constUsed_) count = std::max(count, c + 1);
    for (auto& [c, v] : defined_) count = std::max(count, c + 1);
    if (relative_)
        for (const ConstantBinding& b : constants_)
            count = std::max(count, std::min(256, b.firstRegister + static_cast<int>(registersOf(b).size())));
    constCount_ = count;
}

bool Generator::scalarOutput(RegisterType t) {
    return t == RegisterType::OutFog || t == RegisterType::OutPointSize || t == RegisterType::OutDepth;
}

std::string Generator::outputName(RegisterType t, int index) const {
    switch (t) {
        case RegisterType::OutPosition: return "oPos";
        case RegisterType::OutColor: return "oD" + std::to_string(index);
        case RegisterType::OutTexcoord: return "oT" + std::to_string(index);
        case RegisterType::OutFog: return "oFog";
        case RegisterType::OutPointSize: return "oPts";
        case RegisterType::OutPixel: return "oC" + std::to_string(index);
        case RegisterType::OutDepth: return "oDepth";
        case RegisterType::Output: return "o" + std::to_string(index);
        default: return "?";
    }
}

std::string Generator::outputSemantic(RegisterType t, int index) {
    switch (t) {
        case RegisterType::OutPosition: return "POSITION";
        case RegisterType::OutColor: return "COLOR" + std::to_string(index);
        case RegisterType::OutTexcoord: return "TEXCOORD" + std::to_string(index);
        case RegisterType::OutFog: return "FOG";
        case RegisterType::OutPointSize: return "PSIZE";
        case RegisterType::OutPixel: return "COLOR" + std::to_string(index);
        case RegisterType::OutDepth: return "DEPTH";
        case RegisterType::Output: {
            auto s = outputSemantics_.find(index);
            if (s == outputSemantics_.end()) {
                error(p_.line, "o" + std::to_string(index) + " has no dcl_* giving its usage");
                return "TEXCOORD" + std::to_string(index);
            }
            return s->second == "POSITION0" ? "POSITION" : s->second;
        }
        default: return "";
    }
}

std::string Generator::parameters() {
    std::vector<std::string> params;
    for (int v : inputs_) {
        std::string semantic;
        if (!p_.pixel) {
            if (auto s = inputSemantics_.find(v); s != inputSemantics_.end()) semantic = s->second;
            else {
                for (const InputRegister& r : streams_)
                    if (r.index == v) semantic = r.semantic;
                if (semantic.empty()) {
                    error(firstInputLine_[v], "v" + std::to_string(v) +
                                                  " has no dcl_* and no stream channel of the pass has REGISTER=\"" +
                                                  std::to_string(v) + "\"");
                    semantic = "TEXCOORD" + std::to_string(v + 8);
                }
            }
        } else if (p_.major >= 3) {
            auto s = inputSemantics_.find(v);
            if (s == inputSemantics_.end()) {
                error(firstInputLine_[v], "v" + std::to_string(v) + " has no dcl_* giving its usage");
                semantic = "COLOR" + std::to_string(v);
            } else {
                semantic = s->second;
            }
        } else {
            semantic = "COLOR" + std::to_string(v);
        }
        params.push_back("float4 v" + std::to_string(v) + " : " + semantic);
    }
    std::set<int> texcoords = texcoords_;
    for (int t : texcoordInputs_) texcoords.insert(t);
    for (int t : texcoords)
        params.push_back("float4 " + texcoordName(t) + " : TEXCOORD" + std::to_string(t));
    if (faceUsed_) params.push_back("float vFace : VFACE");
    if (positionUsed_) params.push_back("float2 vPos : VPOS");
    if (ps1x_) params.push_back("out float4 oC0 : COLOR0");
    for (auto [type, index] : outputs_)
        params.push_back(std::string("out ") + (scalarOutput(type) ? "float " : "float4 ") + outputName(type, index) + " : " +
                         outputSemantic(type, index));
    std::string out;
    for (size_t k = 0; k < params.size(); ++k) out += (k ? ", " : "") + params[k];
    return out;
}

std::string Generator::texcoord(int t) {
    if (ps13_) texcoordInputs_.insert(t);
    else texcoords_.insert(t);
    return texcoordName(t);
}

std::string Generator::registerRead(const Source& s, int offset) {
    const int index = s.index + offset;
    const std::string i = std::to_string(index);
    switch (s.type) {
        case RegisterType::Temp: return "r" + i;
        case RegisterType::Const: {
            std::string at = i;
            if (s.relativeComponent >= 0 || s.relativeToLoop) {
                std::string a = s.relativeToLoop ? "aL" : std::string("a0.") + "xyzw"[s.relativeComponent];
                at = "clamp(" + a + " + " + i + ", 0, " + std::to_string(constCount_ - 1) + ")";
            }
            std::string v = "c[" + at + "]";
            // ps_1_x constant registers hold [-1, 1] in every version, ps_1_4's included (its
            // temporaries reach ±8, its constants do not).
            return ps1x_ ? "clamp(" + v + ", -1.0, 1.0)" : v;
        }
        // ps_1_x colour registers hold [0, 1]; an HLSL vertex shader may have written more.
        case RegisterType::Input: return ps1x_ ? "saturate(v" + i + ")" : "v" + i;
        case RegisterType::Texture: return ps13_ ? "t" + i : texcoord(index);
        case RegisterType::Address: return "float4(a0)";
        case RegisterType::ConstInt: return "float4(i" + i + ")";
        case RegisterType::ConstBool: return "rm_rep(b" + i + " ? 1.0 : 0.0)";
        case RegisterType::Loop: return "rm_rep(float(aL))";
        case RegisterType::Face: return "rm_rep(vFace)";
        case RegisterType::PixelPosition: return "float4(vPos, 0.0, 0.0)";
        default: return "rm_rep(0.0)";
    }
}

std::string Generator::source(const Source& s, int offset) {
    std::string x = registerRead(s, offset);
    if (s.swizzle != std::array<int, 4>{0, 1, 2, 3}) {
        x += '.';
        for (int c : s.swizzle) x += "xyzw"[c];
    }
    switch (s.modifier) {
        case SourceModifier::None: return x;
        case SourceModifier::Negate: return "(-" + x + ")";
        case SourceModifier::Bias: return "(" + x + " - 0.5)";
        case SourceModifier::BiasNegate: return "(0.5 - " + x + ")";
        case SourceModifier::Sign: return "(2.0 * " + x + " - 1.0)";
        case SourceModifier::SignNegate: return "(1.0 - 2.0 * " + x + ")";
        case SourceModifier::Complement: return "(1.0 - " + x + ")";
        case SourceModifier::Times2: return "(2.0 * " + x + ")";
        case SourceModifier::Times2Negate: return "(-2.0 * " + x + ")";
        case SourceModifier::Abs: return "abs(" + x + ")";
        case SourceModifier::AbsNegate: return "(-abs(" + x + "))";
        case SourceModifier::DivideZ: return "rm_divz(" + x + ")";
        case SourceModifier::DivideW: return "rm_divw(" + x + ")";
    }
    return x;
}

void Generator::write(const Instruction& in, std::string value, unsigned opMask) {
    const Destination& d = in.destination;
    unsigned mask = d.mask & opMask;
    if (mask == 0) {
        error(in.line, in.opcode + ": the write mask writes none of the components this instruction produces");
        return;
    }
    static const char* scales[] = {"0.125", "0.25", "0.5", "", "2.0", "4.0", "8.0"};
    if (in.shift != 0) value = "(" + value + ") * " + scales[in.shift + 3];
    // Direct3D clamps the colour outputs of vertex shaders before vs_3_0 to [0, 1].
    if (in.saturate || (d.type == RegisterType::OutColor && p_.major < 3)) value = "saturate(" + value + ")";
    else if (ps1x_ && (d.type == RegisterType::Temp || d.type == RegisterType::Texture))
        value = "clamp(" + value + ", " + range(true) + ", " + range(false) + ")";
    std::string target;
    switch (d.type) {
        case RegisterType::Temp: target = "r" + std::to_string(d.index); break;
        case RegisterType::Texture:
            if (!ps13_) {
                error(in.line, "t" + std::to_string(d.index) + " cannot be written in this shader version");
                return;
            }
            target = "t" + std::to_string(d.index);
            break;
        case RegisterType::Address: {
            // mova, and vs_1_1's mov to a0, round to nearest (Direct3D 9's asm reference).
            emit("a0." + std::string(maskText(mask)) + " = int4(floor((" + value + ") + 0.5))." + maskText(mask) + ";");
            return;
        }
        case RegisterType::OutPosition: case RegisterType::OutColor: case RegisterType::OutTexcoord:
        case RegisterType::OutPixel: case RegisterType::Output:
            target = outputName(d.type, d.index);
            break;
        case RegisterType::OutFog: case RegisterType::OutPointSize: case RegisterType::OutDepth:
            emit(outputName(d.type, d.index) + " = (" + value + ")." + maskText(mask)[0] + ";");
            return;
        default:
            return;  // reported by use()
    }
    if (mask == 0xF) emit(target + " = " + value + ";");
    else emit(target + "." + maskText(mask) + " = (" + value + ")." + maskText(mask) + ";");
}

bool Generator::need(const Instruction& in, size_t sources, bool destination) {
    if (in.sources.size() != sources || in.hasDestination != destination) {
        const size_t found = in.sources.size() + (in.hasDestination ? 1 : 0);
        error(in.line, in.opcode + ": expected " + std::to_string(sources + (destination ? 1 : 0)) + " operand" +
                           (sources + (destination ? 1 : 0) == 1 ? "" : "s") + ", found " + std::to_string(found));
        return false;
    }
    return true;
}

}  // namespace generation

bool HlslFromAsm::ok() const {
    for (const Message& m : messages)
        if (m.error) return false;
    return true;
}

HlslFromAsm translateAssembly(const Program& program, const std::vector<ConstantBinding>& constants,
                              const std::vector<SamplerBinding>& samplers, const std::vector<InputRegister>& streams) {
    return generation::Generator(program, constants, samplers, streams).run();
}

}  // namespace rmfx::d3dasm
