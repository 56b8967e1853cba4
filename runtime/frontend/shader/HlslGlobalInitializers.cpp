#include "frontend/shader/HlslGlobalInitializers.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <set>
#include <string_view>

#include "core/IdentifierSearch.h"
#include "frontend/shader/HlslBlankedCode.h"

namespace rmfx {
namespace {

std::vector<std::string> words(std::string_view s) {
    std::vector<std::string> out;
    for (size_t i = 0; i < s.size();) {
        if (isIdentifierChar(s[i])) {
            size_t j = i;
            while (j < s.size() && isIdentifierChar(s[j])) ++j;
            out.push_back(std::string(s.substr(i, j - i)));
            i = j;
        } else if (!std::isspace(static_cast<unsigned char>(s[i]))) {
            out.push_back(std::string(1, s[i++]));
        } else {
            ++i;
        }
    }
    return out;
}

// The values of a constant initializer, flattened: numbers and true/false, arithmetic on them
// (+ - * / and parentheses; fxc folded `1.0 / 64.0` into the constant's default), constructors
// (`float4(1, 2, 3, 4)`, nested) and brace lists (`{1, 2, 3, 4}`, `{ {1, 2}, {3, 4} }`), an
// operation between a vector and a scalar or two vectors of one size applying per component.
// Nothing else (another variable, a function) is constant: nullopt.
class ConstantReader {
public:
    explicit ConstantReader(std::string_view text) : text_(text) {}

    std::optional<std::vector<double>> read() {
        std::optional<std::vector<double>> values = item();
        skipSpace();
        if (!values || at_ != text_.size()) return std::nullopt;
        return values;
    }

private:
    using Values = std::optional<std::vector<double>>;

    // Initializers nest a few levels; this bounds the recursion on hostile input.
    static constexpr int kMaxDepth = 64;

    void skipSpace() {
        while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
    }
    bool take(char c) {
        skipSpace();
        if (at_ < text_.size() && text_[at_] == c) {
            ++at_;
            return true;
        }
        return false;
    }

    Values item() {
        if (++depth_ > kMaxDepth) return std::nullopt;
        Values out = take('{') ? list('}') : expression();
        --depth_;
        return out;
    }

    // Items up to `close`, flattened; a trailing comma is allowed before it.
    Values list(char close) {
        std::vector<double> out;
        if (take(close)) return out;
        while (true) {
            Values v = item();
            if (!v) return std::nullopt;
            out.insert(out.end(), v->begin(), v->end());
            if (take(close)) return out;
            if (!take(',')) return std::nullopt;
            if (take(close)) return out;
        }
    }

    static Values combine(const Values& a, const Values& b, char op) {
        if (!a || !b || a->empty() || b->empty()) return std::nullopt;
        if (a->size() != b->size() && a->size() != 1 && b->size() != 1) return std::nullopt;
        std::vector<double> out(std::max(a->size(), b->size()));
        for (size_t i = 0; i < out.size(); ++i) {
            const double x = (*a)[a->size() == 1 ? 0 : i], y = (*b)[b->size() == 1 ? 0 : i];
            out[i] = op == '+' ? x + y : op == '-' ? x - y : op == '*' ? x * y : x / y;
            if (!std::isfinite(out[i])) return std::nullopt;
        }
        return out;
    }

    Values expression() {
        Values left = term();
        while (left) {
            skipSpace();
            if (at_ >= text_.size() || (text_[at_] != '+' && text_[at_] != '-')) break;
            const char op = text_[at_++];
            left = combine(left, term(), op);
        }
        return left;
    }

    Values term() {
        Values left = unary();
        while (left) {
            skipSpace();
            if (at_ >= text_.size() || (text_[at_] != '*' && text_[at_] != '/')) break;
            const char op = text_[at_++];
            left = combine(left, unary(), op);
        }
        return left;
    }

    Values unary() {
        if (++depth_ > kMaxDepth) return std::nullopt;
        Values out;
        if (take('-')) out = combine(std::vector<double>{0.0}, unary(), '-');
        else if (take('+')) out = unary();
        else out = primary();
        --depth_;
        return out;
    }

    Values primary() {
        skipSpace();
        if (at_ >= text_.size()) return std::nullopt;
        const char c = text_[at_];
        if (c == '(') {
            ++at_;
            Values inside = expression();
            return take(')') ? inside : std::nullopt;
        }
        if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return numberHere();
        if (!isIdentifierChar(c)) return std::nullopt;
        size_t end = at_;
        while (end < text_.size() && isIdentifierChar(text_[end])) ++end;
        const std::string_view word = text_.substr(at_, end - at_);
        at_ = end;
        if (word == "true") return std::vector<double>{1.0};
        if (word == "false") return std::vector<double>{0.0};
        // A constructor: float4(…), half3(…), float(…); a function (sqrt(2)) is not folded.
        if (!isNumericType(word) || !take('(')) return std::nullopt;
        return list(')');
    }

    // float, half3, int2x2…: a scalar type, then nothing, N or NxM (1 to 4).
    static bool isNumericType(std::string_view word) {
        for (std::string_view base : {"float", "half", "double", "int", "uint", "bool", "dword", "min16float", "min10float",
                                      "min16int", "min12int", "min16uint"}) {
            if (!word.starts_with(base)) continue;
            const std::string_view rest = word.substr(base.size());
            auto dimension = [](char c) { return c >= '1' && c <= '4'; };
            if (rest.empty() || (rest.size() == 1 && dimension(rest[0])) ||
                (rest.size() == 3 && dimension(rest[0]) && rest[1] == 'x' && dimension(rest[2])))
                return true;
        }
        return false;
    }

    // 1, 2.5, .25, 1e-3, 2.f, 3h: digits, a point, an exponent, then HLSL's suffixes.
    Values numberHere() {
        size_t end = at_;
        while (end < text_.size() && (std::isdigit(static_cast<unsigned char>(text_[end])) || text_[end] == '.')) ++end;
        if (end < text_.size() && (text_[end] == 'e' || text_[end] == 'E')) {
            size_t exponent = end + 1;
            if (exponent < text_.size() && (text_[exponent] == '+' || text_[exponent] == '-')) ++exponent;
            if (exponent < text_.size() && std::isdigit(static_cast<unsigned char>(text_[exponent]))) {
                end = exponent;
                while (end < text_.size() && std::isdigit(static_cast<unsigned char>(text_[end]))) ++end;
            }
        }
        double value = 0.0;
        auto [parsed, error] = std::from_chars(text_.data() + at_, text_.data() + end, value);
        if (error != std::errc() || parsed != text_.data() + end || !std::isfinite(value)) return std::nullopt;
        while (end < text_.size() && std::string_view("fFhHlLuU").find(text_[end]) != std::string_view::npos) ++end;
        at_ = end;
        return std::vector<double>{value};
    }

    std::string_view text_;
    size_t at_ = 0;
    int depth_ = 0;
};

std::optional<std::vector<double>> constantValues(std::string_view initializer) {
    std::optional<std::vector<double>> values = ConstantReader(initializer).read();
    if (values && values->empty()) return std::nullopt;
    return values;
}

const std::set<std::string>& modifiers() {
    static const std::set<std::string> m = {"uniform", "extern", "shared", "volatile", "row_major", "column_major",
                                            "precise", "nointerpolation"};
    return m;
}

// Line numbers by offset, found by binary search over the newlines (counting them per
// declaration made the scan quadratic).
class LineIndex {
public:
    explicit LineIndex(const std::string& code) {
        for (size_t i = 0; i < code.size(); ++i)
            if (code[i] == '\n') newlines_.push_back(i);
    }
    int lineOf(size_t offset) const {
        return 1 + static_cast<int>(std::lower_bound(newlines_.begin(), newlines_.end(), offset) - newlines_.begin());
    }

private:
    std::vector<size_t> newlines_;
};

// One statement at declaration scope, `text` starting at `offset` in the code.
std::optional<HlslGlobalInitializer> declaration(const LineIndex& lines, size_t offset, std::string_view text) {
    size_t equals = text.find('=');
    if (equals == std::string_view::npos) return std::nullopt;
    std::string_view left = text.substr(0, equals);
    if (size_t annotation = left.find('<'); annotation != std::string_view::npos) left = left.substr(0, annotation);
    if (size_t colon = left.find(':'); colon != std::string_view::npos) left = left.substr(0, colon);  // semantic, register(c3)
    if (left.find_first_of("(){}") != std::string_view::npos) return std::nullopt;  // not a variable
    std::vector<std::string> w = words(left);
    HlslGlobalInitializer init;
    if (size_t bracket = left.find('['); bracket != std::string_view::npos) {
        init.array = true;
        w = words(left.substr(0, bracket));
    }
    std::vector<std::string> declarators;
    for (const std::string& word : w) {
        if (word == "static" || word == "const") return std::nullopt;  // not a constant the application sets
        if (!modifiers().count(word)) declarators.push_back(word);
    }
    if (declarators.size() != 2 || !isIdentifierChar(declarators[0][0]) || !isIdentifierChar(declarators[1][0]))
        return std::nullopt;
    init.declaredType = declarators[0];
    init.name = declarators[1];
    if (auto values = constantValues(text.substr(equals + 1))) {
        init.constant = true;
        init.values = std::move(*values);
    }
    // The line of the name: its last occurrence as a whole word before '='.
    size_t at = offset;
    for (size_t p = left.find(init.name); p != std::string_view::npos; p = left.find(init.name, p + 1)) {
        bool before = p == 0 || !isIdentifierChar(left[p - 1]);
        bool after = p + init.name.size() >= left.size() || !isIdentifierChar(left[p + init.name.size()]);
        if (before && after) at = offset + p;
    }
    init.line = lines.lineOf(at);
    return init;
}

}  // namespace

std::vector<HlslGlobalInitializer> findHlslGlobalInitializers(const std::string& source) {
    return findHlslGlobalInitializers(BlankedHlsl(source));
}

std::vector<HlslGlobalInitializer> findHlslGlobalInitializers(const BlankedHlsl& blanked) {
    const std::string& code = blanked.text;
    const LineIndex lines(code);
    enum class Scope { Buffer, Initializer, Other };
    std::vector<Scope> scopes;
    std::vector<HlslGlobalInitializer> out;
    size_t start = 0;  // of the statement being read at declaration scope
    size_t lastEquals = std::string::npos;
    auto atDeclarationScope = [&] { return scopes.empty() || scopes.back() == Scope::Buffer; };
    // Every step below looks at the statement so far in constant time, or at text that the
    // statement then leaves behind, so the scan stays linear (`a = 1 {}{}{}…` once took seconds).
    auto firstWordIsBuffer = [&](size_t end) {
        size_t first = code.find_first_not_of(" \t\r\n", start);
        if (first >= end) return false;
        size_t last = first;
        while (last < end && isIdentifierChar(code[last])) ++last;
        std::string_view word(code.data() + first, last - first);
        return word == "cbuffer" || word == "tbuffer";
    };
    // From one of the characters below to the next (a library search rather than a step per byte,
    // which under the fuzzers' instrumentation is a callback per comparison).
    for (size_t i = code.find_first_of("={};"); i < code.size(); i = code.find_first_of("={};", i + 1)) {
        const char c = code[i];
        if (c == '=') {
            lastEquals = i;
        } else if (c == '{') {
            if (!atDeclarationScope()) {
                scopes.push_back(Scope::Other);
                continue;
            }
            if (lastEquals != std::string::npos && lastEquals >= start) {
                scopes.push_back(Scope::Initializer);
            } else if (firstWordIsBuffer(i)) {
                scopes.push_back(Scope::Buffer);
                start = i + 1;
            } else {
                scopes.push_back(Scope::Other);
            }
        } else if (c == '}') {
            if (scopes.empty()) continue;  // unbalanced: the compiler reports it
            Scope closed = scopes.back();
            scopes.pop_back();
            if (closed != Scope::Initializer && atDeclarationScope()) start = i + 1;  // after a body
        } else if (c == ';' && atDeclarationScope()) {
            if (auto init = declaration(lines, start, std::string_view(code).substr(start, i - start)))
                out.push_back(std::move(*init));
            start = i + 1;
        }
    }
    return out;
}

}  // namespace rmfx
