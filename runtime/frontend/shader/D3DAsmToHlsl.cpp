#include "frontend/shader/D3DAsmToHlsl.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <sstream>

#include "frontend/shader/D3DAsmHlslNames.h"

namespace rmfx::d3dasm {
namespace {

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

// Helpers the generated code calls, all on the first line.
const char* kHelpers =
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

    HlslFromAsm run() {
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

private:
    // --- messages -------------------------------------------------------------------------
    void error(int line, const std::string& text) { messages_.push_back({true, line, text}); }
    void warning(int line, const std::string& text) { messages_.push_back({false, line, text}); }
    void emit(const std::string& code) { emitAt(line_, code); }
    void emitAt(int line, const std::string& code) {
        std::string& l = lines_[static_cast<size_t>(std::clamp(line, 1, lastLine_))];
        if (!l.empty()) l += ' ';
        l += code;
    }

    // --- declarations ---------------------------------------------------------------------
    static std::string usageSemantic(const Declaration& d) {
        std::string u = upper(d.usage);
        return u + std::to_string(d.usageIndex);
    }

    SamplerKind declaredKind(const std::string& usage) {
        if (usage == "2d") return SamplerKind::Texture2D;
        if (usage == "cube") return SamplerKind::Cube;
        if (usage == "volume") return SamplerKind::Volume;
        return SamplerKind::Unknown;
    }

    void declarations() {
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

    void use(RegisterType t, int index, bool written, const Instruction& in) {
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

    static const char* hlslType(ValueType t) {
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

    // The constant registers a binding fills, and their values.
    std::vector<std::string> registersOf(const ConstantBinding& b) {
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

    const SamplerBinding* binding(int stage) const {
        for (const SamplerBinding& b : samplerBindings_)
            if (b.stage == stage) return &b;
        return nullptr;
    }

    std::array<float, 4> bumpMatrix(int stage) const {
        const SamplerBinding* b = binding(stage);
        return b ? b->bumpMatrix : std::array<float, 4>{};
    }

    std::string samplerName(int stage) {
        for (const SamplerBinding& b : samplerBindings_)
            if (b.stage == stage) return b.name;
        return "rm_asm_sampler" + std::to_string(stage);
    }

    SamplerKind samplerKind(int stage) {
        if (auto k = samplerKinds_.find(stage); k != samplerKinds_.end()) return k->second;
        for (const SamplerBinding& b : samplerBindings_)
            if (b.stage == stage && b.kind != SamplerKind::Unknown) return b.kind;
        return SamplerKind::Texture2D;
    }

    // Declarations and the function's start, on line 1; the statements follow on their lines.
    void finishDeclarations(std::string& head, std::string& body) {
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

    // How many constant registers the code can read: those it names, and with relative
    // addressing every one a variable or def fills.
    void countConstants() {
        int count = std::max(1, std::min(256, relativeReach_));
        for (int c : constUsed_) count = std::max(count, c + 1);
        for (auto& [c, v] : defined_) count = std::max(count, c + 1);
        if (relative_)
            for (const ConstantBinding& b : constants_)
                count = std::max(count, std::min(256, b.firstRegister + static_cast<int>(registersOf(b).size())));
        constCount_ = count;
    }

    static bool scalarOutput(RegisterType t) {
        return t == RegisterType::OutFog || t == RegisterType::OutPointSize || t == RegisterType::OutDepth;
    }

    std::string outputName(RegisterType t, int index) const {
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

    std::string outputSemantic(RegisterType t, int index) {
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

    std::string parameters() {
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

    // ps_1_1…1_3 read texture coordinate sets through texture instructions, t# being the texture
    // registers; the other versions read t# as the coordinates themselves.
    std::string texcoordName(int t) const { return ps13_ ? "rm_tc" + std::to_string(t) : "t" + std::to_string(t); }
    std::string texcoord(int t) {
        if (ps13_) texcoordInputs_.insert(t);
        else texcoords_.insert(t);
        return texcoordName(t);
    }

    // --- operands -------------------------------------------------------------------------
    std::string registerRead(const Source& s, int offset = 0) {
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

    // The range of ps_1_x temporaries and texture registers: ±PixelShader1xMaxValue, which is 8 on
    // the hardware RenderMonkey ran on (ATI's since the R200, and every Direct3D 9 card, which
    // runs ps_1_4 and must reach 8 there), for ps_1_1…1_3 too (RAZD's PTM shader reaches 2).
    std::string range(bool low) const { return low ? "-8.0" : "8.0"; }

    std::string source(const Source& s, int offset = 0) {
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

    // The component a scalar instruction reads: the replicated one, .w when none is written.
    std::string scalar(const Source& s) { return "(" + source(s) + ")." + (s.swizzled ? "x" : "w"); }

    // --- results --------------------------------------------------------------------------
    void write(const Instruction& in, std::string value, unsigned opMask = 0xF) {
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

    bool need(const Instruction& in, size_t sources, bool destination = true) {
        if (in.sources.size() != sources || in.hasDestination != destination) {
            const size_t found = in.sources.size() + (in.hasDestination ? 1 : 0);
            error(in.line, in.opcode + ": expected " + std::to_string(sources + (destination ? 1 : 0)) + " operand" +
                               (sources + (destination ? 1 : 0) == 1 ? "" : "s") + ", found " + std::to_string(found));
            return false;
        }
        return true;
    }

    // --- sampling -------------------------------------------------------------------------
    enum class Fetch { Plain, Projected, Bias, Lod, Gradient };

    std::string sample(int stage, const std::string& coord, Fetch fetch = Fetch::Plain, const std::string& ddx = "",
                       const std::string& ddy = "") {
        if (stage < 0 || stage > 15) {
            error(line_, "sampler stage " + std::to_string(stage) + " is outside 0…15");
            stage = 0;
        }
        if (!samplersUsed_.count(stage)) samplerLines_[stage] = line_;
        samplersUsed_.insert(stage);
        const SamplerKind k = samplerKind(stage);
        const std::string name = samplerName(stage);
        const char* fn = k == SamplerKind::Cube ? "texCUBE" : k == SamplerKind::Volume ? "tex3D" : "tex2D";
        const char* part = k == SamplerKind::Texture2D || k == SamplerKind::Unknown ? ".xy" : ".xyz";
        switch (fetch) {
            case Fetch::Plain: return std::string(fn) + "(" + name + ", (" + coord + ")" + part + ")";
            case Fetch::Projected: return std::string(fn) + "proj(" + name + ", " + coord + ")";
            case Fetch::Bias: return std::string(fn) + "bias(" + name + ", " + coord + ")";
            case Fetch::Lod: return std::string(fn) + "lod(" + name + ", " + coord + ")";
            case Fetch::Gradient:
                return std::string(fn) + "grad(" + name + ", (" + coord + ")" + part + ", (" + ddx + ")" + part + ", (" +
                       ddy + ")" + part + ")";
        }
        return "";
    }

    // ps_1_1…1_3 texture address instructions that take the coordinates of their own stage.
    std::string texcoordDot(const Instruction& in) {
        return "dot(" + texcoord(in.destination.index) + ".xyz, (" + source(in.sources[0]) + ").xyz)";
    }

    bool texRegister(const Instruction& in, size_t sources) {
        if (!need(in, sources)) return false;
        if (!ps13_) {
            error(in.line, in.opcode + " exists only in ps_1_1 … ps_1_3");
            return false;
        }
        if (in.destination.type != RegisterType::Texture) {
            error(in.line, in.opcode + " writes a texture register t#");
            return false;
        }
        return true;
    }

    // --- instructions ---------------------------------------------------------------------
    void instruction(const Instruction& in) {
        const std::string& op = in.opcode;
        if (op == "dcl" || op == "def" || op == "defi" || op == "defb" || op == "nop" || op == "phase") return;
        auto S = [&](size_t k) { return source(in.sources[k]); };
        auto X = [&](size_t k) { return scalar(in.sources[k]); };

        static const std::map<std::string, int> arity = {
            {"mov", 1}, {"mova", 1}, {"add", 2}, {"sub", 2}, {"mul", 2}, {"mad", 3}, {"dp3", 2}, {"dp4", 2},
            {"dp2add", 3}, {"rcp", 1}, {"rsq", 1}, {"min", 2}, {"max", 2}, {"slt", 2}, {"sge", 2}, {"exp", 1},
            {"expp", 1}, {"log", 1}, {"logp", 1}, {"lit", 1}, {"dst", 2}, {"frc", 1}, {"abs", 1}, {"nrm", 1},
            {"pow", 2}, {"crs", 2}, {"lrp", 3}, {"cmp", 3}, {"cnd", 3}, {"sgn", 3}, {"dsx", 1}, {"dsy", 1},
            {"m4x4", 2}, {"m4x3", 2}, {"m3x4", 2}, {"m3x3", 2}, {"m3x2", 2}};
        if (auto a = arity.find(op); a != arity.end()) {
            if (!need(in, static_cast<size_t>(a->second))) return;
            // vs_1_1's mov to a0 reads the source's .w without a swizzle, as its scalar instructions do.
            if (op == "mov" && in.destination.type == RegisterType::Address && vs1x_) write(in, "rm_rep(" + X(0) + ")");
            else if (op == "mov" || op == "mova") write(in, S(0));
            else if (op == "add") write(in, S(0) + " + " + S(1));
            else if (op == "sub") write(in, S(0) + " - " + S(1));
            else if (op == "mul") write(in, S(0) + " * " + S(1));
            else if (op == "mad") write(in, S(0) + " * " + S(1) + " + " + S(2));
            else if (op == "dp3") write(in, "rm_rep(dot((" + S(0) + ").xyz, (" + S(1) + ").xyz))");
            else if (op == "dp4") write(in, "rm_rep(dot(" + S(0) + ", " + S(1) + "))");
            else if (op == "dp2add") write(in, "rm_rep(dot((" + S(0) + ").xy, (" + S(1) + ").xy) + " + X(2) + ")");
            else if (op == "rcp") write(in, "rm_rep(1.0 / " + X(0) + ")");
            else if (op == "rsq") write(in, "rm_rep(1.0 / sqrt(abs(" + X(0) + ")))");
            else if (op == "min") write(in, "min(" + S(0) + ", " + S(1) + ")");
            else if (op == "max") write(in, "max(" + S(0) + ", " + S(1) + ")");
            else if (op == "slt") write(in, "(1.0 - step(" + S(1) + ", " + S(0) + "))");
            else if (op == "sge") write(in, "step(" + S(1) + ", " + S(0) + ")");
            else if (op == "exp") write(in, "rm_rep(exp2(" + X(0) + "))");
            else if (op == "expp") write(in, vs1x_ ? "rm_expp(" + X(0) + ")" : "rm_rep(exp2(" + X(0) + "))");
            else if (op == "log") write(in, "rm_rep(log2(abs(" + X(0) + ")))");
            else if (op == "logp") write(in, vs1x_ ? "rm_logp(" + X(0) + ")" : "rm_rep(log2(abs(" + X(0) + ")))");
            else if (op == "lit") write(in, "rm_lit(" + S(0) + ")");
            else if (op == "dst") write(in, "float4(1.0, (" + S(0) + ").y * (" + S(1) + ").y, (" + S(0) + ").z, (" + S(1) + ").w)");
            else if (op == "frc") write(in, "frac(" + S(0) + ")");
            else if (op == "abs") write(in, "abs(" + S(0) + ")");
            else if (op == "nrm") write(in, "rm_nrm(" + S(0) + ")");
            else if (op == "pow") write(in, "rm_rep(pow(abs(" + X(0) + "), " + X(1) + "))");
            else if (op == "crs") write(in, "float4(cross((" + S(0) + ").xyz, (" + S(1) + ").xyz), 0.0)", 0x7);
            else if (op == "lrp") write(in, "lerp(" + S(2) + ", " + S(1) + ", " + S(0) + ")");
            else if (op == "cmp") write(in, "rm_cmp(" + S(0) + ", " + S(1) + ", " + S(2) + ")");
            else if (op == "cnd") {
                // ps_1_1…1_3 compare r0.a only; ps_1_4 and later per component.
                if (ps13_) write(in, "(" + X(0) + " > 0.5 ? " + S(1) + " : " + S(2) + ")");
                else write(in, "rm_cnd(" + S(0) + ", " + S(1) + ", " + S(2) + ")");
            } else if (op == "sgn") write(in, "sign(" + S(0) + ")");
            else if (op == "dsx") write(in, "ddx(" + S(0) + ")");
            else if (op == "dsy") write(in, "ddy(" + S(0) + ")");
            else matrix(in);
            return;
        }
        if (op == "sincos") {
            if (in.sources.empty() || in.sources.size() > 3 || !in.hasDestination) {
                error(in.line, "sincos: expected a destination and one source (and two constants before vs_3_0/ps_3_0)");
                return;
            }
            write(in, "float4(cos(" + X(0) + "), sin(" + X(0) + "), 0.0, 0.0)", 0x3);
            return;
        }
        if (texture(in)) return;
        if (flow(in)) return;
        static const std::set<std::string> unsupported = {"texm3x2depth", "texdepth",
                                                          "setp", "call", "callnz", "label", "ret", "breakp"};
        if (unsupported.count(op))
            error(in.line, "the instruction '" + op + "' is not supported by rmfx's assembly translation");
        else
            error(in.line, "unknown instruction '" + op + "'");
    }

    void matrix(const Instruction& in) {
        const std::string& op = in.opcode;
        const int columns = op[1] - '0', rows = op[3] - '0';
        const Source& m = in.sources[1];
        if (m.swizzled || m.modifier != SourceModifier::None) {
            error(in.line, op + ": the matrix operand takes no swizzle or modifier");
            return;
        }
        std::string v = "float4(";
        const std::string vec = columns == 4 ? source(in.sources[0]) : "(" + source(in.sources[0]) + ").xyz";
        for (int r = 0; r < 4; ++r) {
            if (r) v += ", ";
            if (r >= rows) v += "0.0";
            else v += "dot(" + vec + ", " + registerRead(m, r) + (columns == 4 ? "" : ".xyz") + ")";
        }
        write(in, v + ")", (1u << rows) - 1);
    }

    bool texture(const Instruction& in) {
        const std::string& op = in.opcode;
        const int d = in.destination.index;
        if (op == "texld" || op == "texldp" || op == "texldb" || op == "texldl" || op == "texldd") {
            if (ps14_) {
                // ps_1_4: texld r#, t#|r#, sampling stage # (the destination's number)
                if (!need(in, 1)) return true;
                write(in, sample(d, source(in.sources[0])));
                return true;
            }
            if (ps13_) {
                error(in.line, op + " exists from ps_1_4; ps_1_1 … ps_1_3 use tex");
                return true;
            }
            const size_t n = op == "texldd" ? 4 : 2;
            if (!need(in, n)) return true;
            if (in.sources[1].type != RegisterType::Sampler) {
                error(in.line, op + ": the second source must be a sampler s#");
                return true;
            }
            const int stage = in.sources[1].index;
            const std::string c = source(in.sources[0]);
            Fetch f = op == "texldp" ? Fetch::Projected : op == "texldb" ? Fetch::Bias
                      : op == "texldl" ? Fetch::Lod : op == "texldd" ? Fetch::Gradient : Fetch::Plain;
            std::string value = f == Fetch::Gradient ? sample(stage, c, f, source(in.sources[2]), source(in.sources[3]))
                                                     : sample(stage, c, f);
            if (in.sources[1].swizzled) {
                value = "(" + value + ").";
                for (int k : in.sources[1].swizzle) value += "xyzw"[k];
            }
            write(in, value);
            return true;
        }
        if (op == "texcrd") {
            if (!need(in, 1)) return true;
            if (!ps14_) {
                error(in.line, "texcrd exists only in ps_1_4");
                return true;
            }
            write(in, "float4((" + source(in.sources[0]) + ").xyz, 1.0)");
            return true;
        }
        if (op == "texkill") {
            if (!need(in, 1, false)) return true;
            const Source& s = in.sources[0];
            std::string x = ps13_ && s.type == RegisterType::Texture ? texcoord(s.index) : source(s);
            emit("clip((" + x + ")" + (p_.major < 2 ? ".xyz" : "") + ");");
            return true;
        }
        if (op == "tex") {
            if (!texRegister(in, 0)) return true;
            write(in, sample(d, texcoord(d)));
            return true;
        }
        if (op == "texcoord") {
            if (!texRegister(in, 0)) return true;
            write(in, "saturate(float4(" + texcoord(d) + ".xyz, 1.0))");
            return true;
        }
        if (op == "texreg2ar" || op == "texreg2gb" || op == "texreg2rgb") {
            if (!texRegister(in, 1)) return true;
            const std::string s = "(" + source(in.sources[0]) + ")";
            const std::string c = op == "texreg2ar" ? "float4(" + s + ".w, " + s + ".x, 0.0, 1.0)"
                                  : op == "texreg2gb" ? "float4(" + s + ".y, " + s + ".z, 0.0, 1.0)"
                                                      : "float4(" + s + ".xyz, 1.0)";
            write(in, sample(d, c));
            return true;
        }
        if (op == "texbem" || op == "texbeml") {
            // The coordinates of stage d moved by the stage's bump matrix times t(n).rg.
            if (!texRegister(in, 1)) return true;
            const std::string src = "(" + source(in.sources[0]) + ")";
            const std::array<float, 4> m = bumpMatrix(d);
            const std::string tc = texcoord(d);
            const std::string u = tc + ".x + " + number(m[0]) + " * " + src + ".x + " + number(m[2]) + " * " + src + ".y";
            const std::string v = tc + ".y + " + number(m[1]) + " * " + src + ".x + " + number(m[3]) + " * " + src + ".y";
            std::string texel = sample(d, "float4(" + u + ", " + v + ", 0.0, 1.0)");
            if (op == "texbeml") {
                const SamplerBinding* b = binding(d);
                texel = "(" + texel + ") * (" + src + ".z * " + number(b ? b->bumpScale : 0.0f) + " + " +
                        number(b ? b->bumpOffset : 0.0f) + ")";
            }
            write(in, texel);
            return true;
        }
        if (op == "bem") {
            // ps_1_4: dest.xy = src0.xy + the bump matrix of stage dest times src1.xy.
            if (!need(in, 2)) return true;
            if (!ps14_ || in.destination.type != RegisterType::Temp) {
                error(in.line, "bem exists only in ps_1_4, writing a temporary register r#");
                return true;
            }
            const std::string a = "(" + source(in.sources[0]) + ")", b = "(" + source(in.sources[1]) + ")";
            const std::array<float, 4> m = bumpMatrix(d);
            write(in, "float4(" + a + ".x + " + number(m[0]) + " * " + b + ".x + " + number(m[2]) + " * " + b + ".y, " + a +
                          ".y + " + number(m[1]) + " * " + b + ".x + " + number(m[3]) + " * " + b + ".y, 0.0, 0.0)",
                  0x3);
            return true;
        }
        if (op == "texm3x2pad" || op == "texm3x3pad") {
            if (!texRegister(in, 1)) return true;
            emit("t" + std::to_string(d) + ".x = " + texcoordDot(in) + ";");
            return true;
        }
        if (op == "texdp3tex" || op == "texdp3") {
            if (!texRegister(in, 1)) return true;
            if (op == "texdp3") write(in, "rm_rep(" + texcoordDot(in) + ")");
            else write(in, sample(d, "float4(" + texcoordDot(in) + ", 0.0, 0.0, 1.0)"));
            return true;
        }
        if (op == "texm3x2tex") {
            if (!texRegister(in, 1)) return true;
            write(in, sample(d, "float4(t" + std::to_string(d - 1) + ".x, " + texcoordDot(in) + ", 0.0, 1.0)"));
            return true;
        }
        if (op == "texm3x3tex" || op == "texm3x3" || op == "texm3x3vspec" || op == "texm3x3spec") {
            const bool spec = op == "texm3x3spec";
            if (!texRegister(in, spec ? 2 : 1)) return true;
            if (d < 2) {
                error(in.line, op + " follows two texm3x3pad: its register is at least t2");
                return true;
            }
            const std::string n = "float3(t" + std::to_string(d - 2) + ".x, t" + std::to_string(d - 1) + ".x, " + texcoordDot(in) + ")";
            if (op == "texm3x3") {
                write(in, "float4(" + n + ", 1.0)");
            } else if (op == "texm3x3tex") {
                write(in, sample(d, "float4(" + n + ", 1.0)"));
            } else {
                // The reflection of the eye vector about the normal n: 2·n·(n·e)/(n·n) − e.
                const std::string e = spec ? "(" + source(in.sources[1]) + ").xyz"
                                           : "float3(" + texcoord(d - 2) + ".w, " + texcoord(d - 1) + ".w, " + texcoord(d) + ".w)";
                emit("{ float3 rm_n = " + n + "; float3 rm_e = " + e + ";");
                write(in, sample(d, "float4(2.0 * rm_n * dot(rm_n, rm_e) / dot(rm_n, rm_n) - rm_e, 1.0)"));
                emit("}");
            }
            return true;
        }
        return false;
    }

    std::string compare(const std::string& c) {
        if (c == "gt") return ">";
        if (c == "lt") return "<";
        if (c == "ge") return ">=";
        if (c == "le") return "<=";
        if (c == "eq") return "==";
        if (c == "ne") return "!=";
        return "";
    }

    bool flow(const Instruction& in) {
        const std::string& op = in.opcode;
        if (op == "if") {
            if (!in.comparison.empty()) {
                if (!need(in, 2, false)) return true;
                emit("if (" + scalar(in.sources[0]) + " " + compare(in.comparison) + " " + scalar(in.sources[1]) + ") {");
            } else {
                if (!need(in, 1, false)) return true;
                if (in.sources[0].type != RegisterType::ConstBool) {
                    error(in.line, "if: expects a boolean register b# (or if_gt … with two sources)");
                    return true;
                }
                emit("if (b" + std::to_string(in.sources[0].index) + ") {");
            }
            blocks_.push_back({op, in.line});
        } else if (op == "else") {
            if (blocks_.empty() || blocks_.back().first != "if") {
                error(in.line, "else without an if");
                return true;
            }
            emit("} else {");
        } else if (op == "endif" || op == "endrep" || op == "endloop") {
            if (blocks_.empty()) {
                error(in.line, op + " without a matching block");
                return true;
            }
            const auto [opened, openedLine] = blocks_.back();
            blocks_.pop_back();
            if (op != "end" + opened)
                error(in.line, op + " closes the " + opened + " of line " + std::to_string(openedLine));
            emit(opened == "loop" ? "} }" : "}");  // a loop opened a block for aL too
        } else if (op == "rep" || op == "loop") {
            const size_t n = op == "loop" ? 2 : 1;
            if (!need(in, n, false)) return true;
            const Source& count = in.sources[n - 1];
            if (count.type != RegisterType::ConstInt) {
                error(in.line, op + ": the count must be an integer register i#");
                return true;
            }
            const std::string i = "i" + std::to_string(count.index);
            const std::string k = "rm_n" + std::to_string(blocks_.size());
            if (op == "rep") emit("for (int " + k + " = 0; " + k + " < " + i + ".x; ++" + k + ") {");
            else emit("{ int aL = " + i + ".y; for (int " + k + " = 0; " + k + " < " + i + ".x; ++" + k + ", aL += " + i + ".z) {");
            blocks_.push_back({op, in.line});
        } else if (op == "break") {
            if (std::none_of(blocks_.begin(), blocks_.end(), [](const auto& b) { return b.first != "if"; })) {
                error(in.line, "break outside a rep or loop");
                return true;
            }
            if (!in.comparison.empty()) {
                if (!need(in, 2, false)) return true;
                emit("if (" + scalar(in.sources[0]) + " " + compare(in.comparison) + " " + scalar(in.sources[1]) + ") break;");
            } else {
                emit("break;");
            }
        } else {
            return false;
        }
        return true;
    }

    void finish() {
        std::string head, body;
        finishDeclarations(head, body);
        bool wrotePosition = false;
        for (auto [t, i] : outputs_)
            if (t == RegisterType::OutPosition || (t == RegisterType::Output && outputSemantic(t, i) == "POSITION"))
                wrotePosition = true;
        if (!p_.pixel && !wrotePosition) error(p_.line > 0 ? p_.line : 1, "the vertex shader never writes oPos");
        if (ps1x_) head += "float4 rm_divz(float4 v) { return float4(v.xy / v.z, v.z, 1.0); } "
                           "float4 rm_divw(float4 v) { return float4(v.xy / v.w, v.zw); } ";
        else head += "float4 rm_divz(float4 v) { return v; } float4 rm_divw(float4 v) { return v; } ";
        head += "void rm_asm_main(" + parameters() + ") { ";
        lines_[1] = head + body + lines_[1];
        std::string tail;
        if (ps1x_) tail += "oC0 = r0; ";
        tail += "}";
        emitAt(lastLine_, tail);
    }

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

}  // namespace

bool HlslFromAsm::ok() const {
    for (const Message& m : messages)
        if (m.error) return false;
    return true;
}

HlslFromAsm translateAssembly(const Program& program, const std::vector<ConstantBinding>& constants,
                              const std::vector<SamplerBinding>& samplers, const std::vector<InputRegister>& streams) {
    return Generator(program, constants, samplers, streams).run();
}

}  // namespace rmfx::d3dasm
