#include "frontend/shader/D3DAsmParser.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <optional>
#include <string_view>

namespace rmfx::d3dasm {
namespace {

bool identStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool identChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
std::string lower(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

struct Statement {
    std::string text;
    int line = 0;
};

// The code without comments, cut into statements (one a line), macros expanded.
class Lines {
public:
    explicit Lines(const std::string& code, std::vector<Message>& messages) : messages_(messages) {
        std::string current;
        int line = 1;
        bool block = false;
        for (size_t i = 0; i <= code.size(); ++i) {
            char ch = i < code.size() ? code[i] : '\n';
            if (block) {
                if (ch == '*' && i + 1 < code.size() && code[i + 1] == '/') {
                    block = false;
                    ++i;
                } else if (ch == '\n') {
                    finish(current, line++);
                }
                continue;
            }
            if (ch == '/' && i + 1 < code.size() && code[i + 1] == '*') {
                block = true;
                ++i;
                continue;
            }
            if (ch == ';' || (ch == '/' && i + 1 < code.size() && code[i + 1] == '/')) {
                while (i < code.size() && code[i] != '\n') ++i;
                ch = '\n';
            }
            if (ch == '\n') {
                finish(current, line++);
                continue;
            }
            if (ch == '\r') continue;
            current += ch;
        }
    }
    std::vector<Statement> statements;

private:
    void finish(std::string& text, int line) {
        size_t b = text.find_first_not_of(" \t\f\v");
        std::string s = b == std::string::npos ? "" : text.substr(b);
        text.clear();
        while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
        if (s.empty()) return;
        if (s[0] == '#') {
            directive(s, line);
            return;
        }
        if (macros_.empty()) statements.push_back({s, line});
        else if (std::string e = expand(s, line); !e.empty()) statements.push_back({e, line});
    }

    void directive(const std::string& s, int line) {
        size_t i = 1;
        while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
        size_t b = i;
        while (i < s.size() && identChar(s[i])) ++i;
        std::string word = s.substr(b, i - b);
        if (word == "define") {
            while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
            b = i;
            while (i < s.size() && identChar(s[i])) ++i;
            std::string name = s.substr(b, i - b);
            if (name.empty() || (i < s.size() && s[i] == '(')) {
                messages_.push_back({true, line, "#define: only object-like macros (#define NAME text) are supported"});
                return;
            }
            size_t v = s.find_first_not_of(" \t", i);
            macros_[name] = v == std::string::npos ? "" : s.substr(v);
        } else if (word == "undef") {
            while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
            b = i;
            while (i < s.size() && identChar(s[i])) ++i;
            macros_.erase(s.substr(b, i - b));
        } else {
            messages_.push_back({true, line, "preprocessor directive #" + word + " is not supported in assembly"});
        }
    }

    // As the C preprocessor: a macro is not expanded inside its own expansion. The result is
    // capped, since macros that each use the next twice grow exponentially.
    std::string expand(const std::string& s, int line) {
        std::set<std::string> active;
        std::string out;
        if (!expandInto(s, active, out)) {
            messages_.push_back({true, line, "the macros expand this line to more than " + std::to_string(kMaxExpansion) +
                                                 " characters"});
            return "";
        }
        return out;
    }

    static constexpr size_t kMaxExpansion = 65536;

    bool expandInto(const std::string& s, std::set<std::string>& active, std::string& out) const {
        for (size_t i = 0; i < s.size();) {
            if (out.size() > kMaxExpansion) return false;
            if (identStart(s[i]) && (i == 0 || !identChar(s[i - 1]))) {
                size_t b = i;
                while (i < s.size() && identChar(s[i])) ++i;
                std::string word = s.substr(b, i - b);
                auto m = macros_.find(word);
                if (m == macros_.end() || active.count(word)) {
                    out += word;
                } else {
                    active.insert(word);
                    const bool ok = expandInto(m->second, active, out);
                    active.erase(word);
                    if (!ok) return false;
                }
            } else {
                out += s[i++];
            }
        }
        return out.size() <= kMaxExpansion;
    }

    std::vector<Message>& messages_;
    std::map<std::string, std::string> macros_;
};

class StatementParser {
public:
    StatementParser(const Statement& s, Program& program, std::vector<Message>& messages)
        : s_(s.text), line_(s.line), program_(program), messages_(messages) {}

    void parse() {
        Instruction in;
        in.line = line_;
        skipSpace();
        if (peek() == '+') {
            in.coissued = true;
            ++at_;
            skipSpace();
        }
        size_t b = at_;
        while (at_ < s_.size() && (identChar(s_[at_]) || s_[at_] == '.')) ++at_;
        std::string word = lower(s_.substr(b, at_ - b));
        if (word.empty()) return fail("expected an instruction, found '" + s_ + "'");
        if (version(word)) return;
        if (!versionSeen_()) return fail("'" + word + "' before the version token (vs_1_1, ps_2_0…)");
        if (!opcode(word, in)) return;
        skipSpace();
        if (in.opcode == "def" || in.opcode == "defi" || in.opcode == "defb") return define(in);
        if (at_ < s_.size()) {
            std::vector<std::string> operands = splitOperands();
            for (size_t k = 0; k < operands.size(); ++k) {
                const bool dest = k == 0 && hasDestination(in.opcode);
                if (dest) {
                    auto d = destination(operands[k]);
                    if (!d) return;
                    in.destination = *d;
                    in.hasDestination = true;
                } else {
                    auto src = source(operands[k]);
                    if (!src) return;
                    in.sources.push_back(*src);
                }
            }
        }
        program_.instructions.push_back(std::move(in));
    }

private:
    char peek() const { return at_ < s_.size() ? s_[at_] : '\0'; }
    void skipSpace() {
        while (at_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[at_]))) ++at_;
    }
    void fail(const std::string& message) { messages_.push_back({true, line_, message}); }
    bool versionSeen_() const { return program_.line != 0; }

    bool version(const std::string& word) {
        if (word.size() < 4 || (word.rfind("vs", 0) != 0 && word.rfind("ps", 0) != 0) || (word[2] != '.' && word[2] != '_'))
            return false;
        if (versionSeen_()) {
            fail("a second version token '" + word + "'");
            return true;
        }
        const char sep = word[2];
        size_t second = word.find(sep, 3);
        std::string major = word.substr(3, second == std::string::npos ? std::string::npos : second - 3);
        std::string minor = second == std::string::npos ? "0" : word.substr(second + 1);
        program_.pixel = word[0] == 'p';
        program_.line = line_;
        if (major.size() != 1 || major[0] < '1' || major[0] > '3') {
            fail("unknown shader version '" + word + "'");
            return true;
        }
        program_.major = major[0] - '0';
        if (minor.size() == 1 && std::isdigit(static_cast<unsigned char>(minor[0]))) program_.minor = minor[0] - '0';
        else if (program_.major == 2 && (minor == "x" || minor == "sw" || minor == "a" || minor == "b")) program_.minor = 1;
        else if (program_.major == 3 && minor == "sw") program_.minor = 0;
        else fail("unknown shader version '" + word + "'");
        const int v = program_.major * 10 + program_.minor;
        const bool known = program_.pixel ? (v >= 11 && v <= 14) || v == 20 || v == 21 || v == 30
                                          : v == 10 || v == 11 || v == 20 || v == 21 || v == 30;
        if (!known) fail("unknown shader version '" + word + "'");
        return true;
    }

    bool opcode(const std::string& word, Instruction& in) {
        size_t u = word.find('_');
        in.opcode = word.substr(0, u);
        if (in.opcode.find('.') != std::string::npos) {
            fail("unknown instruction '" + word + "'");
            return false;
        }
        if (in.opcode == "dcl") {
            if (u != std::string::npos) {
                std::string usage = word.substr(u + 1);
                // dcl_texcoord0_centroid, dcl_pp t0: modifiers after the usage are ignored.
                for (const char* m : {"_centroid", "_pp"})
                    if (size_t at = usage.find(m); at != std::string::npos) usage.erase(at, std::string(m).size());
                if (usage == "pp" || usage == "centroid") usage.clear();
                size_t d = usage.size();
                while (d > 0 && std::isdigit(static_cast<unsigned char>(usage[d - 1]))) --d;
                // dcl_2d: the digit belongs to the name
                if (d == 0 || usage.substr(0, d) == "2d") d = usage.size();
                in.declaration.usage = usage.substr(0, d);
                if (d < usage.size()) in.declaration.usageIndex = std::atoi(usage.c_str() + d);
            }
            return true;
        }
        static const std::map<std::string, int> shifts = {{"x2", 1}, {"x4", 2}, {"x8", 3}, {"d2", -1}, {"d4", -2}, {"d8", -3}};
        static const char* comparisons[] = {"gt", "lt", "ge", "le", "eq", "ne"};
        while (u != std::string::npos) {
            size_t next = word.find('_', u + 1);
            std::string m = word.substr(u + 1, next == std::string::npos ? std::string::npos : next - u - 1);
            u = next;
            if (m == "sat") in.saturate = true;
            else if (m == "pp" || m == "centroid") {
            } else if (auto s = shifts.find(m); s != shifts.end()) in.shift = s->second;
            else if (std::find(std::begin(comparisons), std::end(comparisons), m) != std::end(comparisons)) in.comparison = m;
            else {
                fail("unknown instruction modifier '_" + m + "' in '" + word + "'");
                return false;
            }
        }
        return true;
    }

    static bool hasDestination(const std::string& op) {
        static const char* none[] = {"texkill", "nop", "if", "else", "endif", "rep", "endrep", "loop", "endloop",
                                     "break", "breakc", "breakp", "call", "callnz", "ret", "label", "phase"};
        for (const char* n : none)
            if (op == n) return false;
        return true;
    }

    std::vector<std::string> splitOperands() {
        std::vector<std::string> out;
        std::string current;
        int depth = 0;
        for (; at_ < s_.size(); ++at_) {
            char ch = s_[at_];
            if (ch == '[') ++depth;
            if (ch == ']') --depth;
            if (ch == ',' && depth == 0) {
                out.push_back(current);
                current.clear();
            } else {
                current += ch;
            }
        }
        out.push_back(current);
        for (std::string& o : out) {
            size_t b = o.find_first_not_of(" \t");
            size_t e = o.find_last_not_of(" \t");
            o = b == std::string::npos ? "" : o.substr(b, e - b + 1);
        }
        return out;
    }

    void define(Instruction& in) {
        std::vector<std::string> operands = at_ < s_.size() ? splitOperands() : std::vector<std::string>{};
        const size_t count = in.opcode == "defb" ? 2 : 5;
        if (operands.size() != count) {
            fail(in.opcode + ": expected a register and " + (count == 2 ? "one value" : "four values") + ", found " +
                 std::to_string(operands.empty() ? 0 : operands.size() - 1) + " operands");
            return;
        }
        auto d = destination(operands[0]);
        if (!d) return;
        in.destination = *d;
        in.hasDestination = true;
        for (size_t k = 1; k < operands.size(); ++k) {
            std::string v = lower(operands[k]);
            if (in.opcode == "defb") {
                if (v != "true" && v != "false") return fail("defb: expected true or false, found '" + operands[k] + "'");
                in.values[0] = v == "true" ? 1.0f : 0.0f;
                continue;
            }
            if (!v.empty() && v.back() == 'f') v.pop_back();
            char* end = nullptr;
            double x = std::strtod(v.c_str(), &end);
            if (v.empty() || end != v.c_str() + v.size()) return fail(in.opcode + ": '" + operands[k] + "' is not a number");
            if (!std::isfinite(static_cast<float>(x))) return fail(in.opcode + ": '" + operands[k] + "' is out of range");
            if (in.opcode == "defi" && (x != std::floor(x) || x < -2147483648.0 || x > 2147483647.0))
                return fail("defi: '" + operands[k] + "' is not a 32-bit integer");
            in.values[k - 1] = static_cast<float>(x);
        }
        program_.instructions.push_back(std::move(in));
    }

    // Register name and index, with c[a0.x + n] / c3[a0.x] relative forms.
    bool registerName(std::string_view text, size_t& i, RegisterType& type, int& index, int* relative, bool* loop,
                      const std::string& operand) {
        size_t b = i;
        while (i < text.size() && std::isalpha(static_cast<unsigned char>(text[i]))) ++i;
        std::string name = lower(text.substr(b, i - b));
        size_t db = i;
        while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
        std::string digits(text.substr(db, i - db));
        index = digits.empty() ? 0 : std::atoi(digits.c_str());
        if (digits.size() > 4) {
            fail("register index too large in '" + operand + "'");
            return false;
        }
        static const std::map<std::string, RegisterType> names = {
            {"v", RegisterType::Input},       {"r", RegisterType::Temp},         {"c", RegisterType::Const},
            {"i", RegisterType::ConstInt},    {"b", RegisterType::ConstBool},    {"a", RegisterType::Address},
            {"t", RegisterType::Texture},     {"s", RegisterType::Sampler},      {"al", RegisterType::Loop},
            {"p", RegisterType::Predicate},   {"opos", RegisterType::OutPosition}, {"od", RegisterType::OutColor},
            {"ot", RegisterType::OutTexcoord}, {"ofog", RegisterType::OutFog},   {"opts", RegisterType::OutPointSize},
            {"oc", RegisterType::OutPixel},   {"odepth", RegisterType::OutDepth}, {"o", RegisterType::Output},
            {"vface", RegisterType::Face},    {"vpos", RegisterType::PixelPosition}};
        auto n = names.find(name);
        const bool numbered = !(name == "opos" || name == "ofog" || name == "opts" || name == "odepth" || name == "al" ||
                                name == "vface" || name == "vpos");
        if (n == names.end() || (numbered && digits.empty() && !(name == "c" && i < text.size() && text[i] == '['))) {
            fail("unknown register '" + operand + "'");
            return false;
        }
        type = n->second;
        if (i < text.size() && text[i] == '[') {
            if (!relative) {
                fail("relative addressing is not allowed here: '" + operand + "'");
                return false;
            }
            size_t close = text.find(']', i);
            if (close == std::string::npos) {
                fail("missing ']' in '" + operand + "'");
                return false;
            }
            if (!relativeIndex(text.substr(i + 1, close - i - 1), index, *relative, *loop, operand)) return false;
            i = close + 1;
        }
        return true;
    }

    // "a0.x + 3", "3 + a0.x", "a0.x", "aL + 2": adds the constant part to index.
    bool relativeIndex(std::string_view inside, int& index, int& component, bool& loop, const std::string& operand) {
        std::string t;
        for (char ch : inside)
            if (!std::isspace(static_cast<unsigned char>(ch))) t += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        component = -1;
        int offset = 0;
        size_t k = 0;
        while (k < t.size()) {
            int sign = 1;
            if (t[k] == '+' || t[k] == '-') {
                sign = t[k] == '-' ? -1 : 1;
                ++k;
            }
            if (t.compare(k, 2, "a0") == 0) {
                k += 2;
                component = 0;
                if (k < t.size() && t[k] == '.') {
                    static const std::string comps = "xyzw";
                    if (k + 1 >= t.size() || comps.find(t[k + 1]) == std::string::npos) {
                        fail("bad address register component in '" + operand + "'");
                        return false;
                    }
                    component = static_cast<int>(comps.find(t[k + 1]));
                    k += 2;
                }
                if (sign < 0) {
                    fail("the address register cannot be subtracted in '" + operand + "'");
                    return false;
                }
            } else if (t.compare(k, 2, "al") == 0) {
                k += 2;
                loop = true;
                component = 0;
            } else if (k < t.size() && std::isdigit(static_cast<unsigned char>(t[k]))) {
                size_t b = k;
                while (k < t.size() && std::isdigit(static_cast<unsigned char>(t[k]))) ++k;
                if (k - b > 4) {
                    fail("offset too large in '" + operand + "'");
                    return false;
                }
                offset += sign * std::atoi(t.c_str() + b);
            } else {
                fail("cannot read the relative address in '" + operand + "'");
                return false;
            }
        }
        if (component < 0) {
            index += offset;  // c[3]: not relative at all
        } else {
            index += offset;
        }
        if (index < 0) {
            fail("negative register index in '" + operand + "'");
            return false;
        }
        return true;
    }

    static int component(char ch) {
        switch (std::tolower(static_cast<unsigned char>(ch))) {
            case 'x': case 'r': return 0;
            case 'y': case 'g': return 1;
            case 'z': case 'b': return 2;
            case 'w': case 'a': return 3;
            default: return -1;
        }
    }

    std::optional<Destination> destination(const std::string& operand) {
        Destination d;
        size_t i = 0;
        int relative = -1;
        bool loop = false;
        if (operand.empty()) {
            fail("missing destination register");
            return std::nullopt;
        }
        if (!registerName(operand, i, d.type, d.index, &relative, &loop, operand)) return std::nullopt;
        if (relative >= 0 || loop) {
            fail("relative addressing of a destination is not supported: '" + operand + "'");
            return std::nullopt;
        }
        if (i < operand.size() && operand[i] == '.') {
            ++i;
            d.mask = 0;
            int last = -1;
            for (; i < operand.size() && component(operand[i]) >= 0; ++i) {
                int c = component(operand[i]);
                if (c <= last) {
                    fail("write mask components must be in order (xyzw) in '" + operand + "'");
                    return std::nullopt;
                }
                last = c;
                d.mask |= 1u << c;
            }
            if (d.mask == 0) {
                fail("empty write mask in '" + operand + "'");
                return std::nullopt;
            }
        }
        if (i != operand.size()) {
            fail("cannot read destination '" + operand + "'");
            return std::nullopt;
        }
        return d;
    }

    bool sourceSuffix(const std::string& operand, size_t& i, Source& s, bool negate) {
        if (i >= operand.size() || operand[i] != '_') return true;
        size_t b = ++i;
        while (i < operand.size() && identChar(operand[i])) ++i;
        std::string m = lower(operand.substr(b, i - b));
        if (s.modifier != SourceModifier::None && s.modifier != SourceModifier::Negate) {
            fail("two source modifiers in '" + operand + "'");
            return false;
        }
        if (m == "bias") s.modifier = negate ? SourceModifier::BiasNegate : SourceModifier::Bias;
        else if (m == "bx2") s.modifier = negate ? SourceModifier::SignNegate : SourceModifier::Sign;
        else if (m == "x2") s.modifier = negate ? SourceModifier::Times2Negate : SourceModifier::Times2;
        else if (m == "abs") s.modifier = negate ? SourceModifier::AbsNegate : SourceModifier::Abs;
        else if ((m == "dz" || m == "db") && !negate) s.modifier = SourceModifier::DivideZ;
        else if ((m == "dw" || m == "da") && !negate) s.modifier = SourceModifier::DivideW;
        else {
            fail("unknown source modifier '_" + m + "' in '" + operand + "'");
            return false;
        }
        return true;
    }

    std::optional<Source> source(const std::string& operand) {
        Source s;
        size_t i = 0;
        bool negate = false;
        if (operand.empty()) {
            fail("missing source operand");
            return std::nullopt;
        }
        if (operand[0] == '-') {
            negate = true;
            ++i;
        } else if (operand[0] == '1') {
            size_t k = 1;
            while (k < operand.size() && std::isspace(static_cast<unsigned char>(operand[k]))) ++k;
            if (k < operand.size() && operand[k] == '-') {
                s.modifier = SourceModifier::Complement;
                i = k + 1;
            }
        }
        while (i < operand.size() && std::isspace(static_cast<unsigned char>(operand[i]))) ++i;
        if (negate) s.modifier = SourceModifier::Negate;
        if (!registerName(operand, i, s.type, s.index, &s.relativeComponent, &s.relativeToLoop, operand)) return std::nullopt;
        if (!sourceSuffix(operand, i, s, negate)) return std::nullopt;
        if (i < operand.size() && operand[i] == '.') {
            ++i;
            int n = 0;
            std::array<int, 4> sw{};
            for (; i < operand.size() && component(operand[i]) >= 0; ++i) {
                if (n == 4) {
                    fail("more than four swizzle components in '" + operand + "'");
                    return std::nullopt;
                }
                sw[n++] = component(operand[i]);
            }
            if (n == 0) {
                fail("empty swizzle in '" + operand + "'");
                return std::nullopt;
            }
            for (int k = n; k < 4; ++k) sw[k] = sw[n - 1];  // .xy reads .xyyy
            s.swizzle = sw;
            s.swizzled = true;
        }
        if (!sourceSuffix(operand, i, s, negate)) return std::nullopt;
        if (i != operand.size()) {
            fail("cannot read source '" + operand + "'");
            return std::nullopt;
        }
        return s;
    }

    const std::string& s_;
    int line_;
    Program& program_;
    std::vector<Message>& messages_;
    size_t at_ = 0;
};

}  // namespace

bool ParseResult::ok() const {
    for (const Message& m : messages)
        if (m.error) return false;
    return true;
}

ParseResult parseAssembly(const std::string& code) {
    ParseResult r;
    Lines lines(code, r.messages);
    for (const Statement& s : lines.statements) StatementParser(s, r.program, r.messages).parse();
    if (r.program.line == 0 && r.ok()) r.messages.push_back({true, 1, "no version token (vs_1_1, ps_2_0…) in the shader"});
    return r;
}

}  // namespace rmfx::d3dasm
