// Direct3D 9 assembly to HLSL (D3DAsmHlslGenerator.h): the instructions, arithmetic, texture
// sampling and flow control, and the end of the generated function.

#include "frontend/shader/D3DAsmHlslGenerator.h"
#include "frontend/shader/D3DAsmHlslNames.h"

namespace rmfx::d3dasm::generation {

std::string Generator::sample(int stage, const std::string& coord, Fetch fetch, const std::string& ddx,
                   const std::string& ddy) {
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

std::string Generator::texcoordDot(const Instruction& in) {
    return "dot(" + texcoord(in.destination.index) + ".xyz, (" + source(in.sources[0]) + ").xyz)";
}

bool Generator::texRegister(const Instruction& in, size_t sources) {
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

void Generator::instruction(const Instruction& in) {
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

void Generator::matrix(const Instruction& in) {
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

bool Generator::texture(const Instruction& in) {
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

std::string Generator::compare(const std::string& c) {
    if (c == "gt") return ">";
    if (c == "lt") return "<";
    if (c == "ge") return ">=";
    if (c == "le") return "<=";
    if (c == "eq") return "==";
    if (c == "ne") return "!=";
    return "";
}

bool Generator::flow(const Instruction& in) {
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

void Generator::finish() {
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

}  // namespace rmfx::d3dasm::generation
