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

std::string trimmed(std::string_view s) {
    size_t a = s.find_first_not_of(" \t\r\n"), b = s.find_last_not_of(" \t\r\n");
    return a == std::string_view::npos ? std::string() : std::string(s.substr(a, b - a + 1));
}

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

// "1", "-0.5", "2.f", "1e-3h", ".25": a number with an optional sign and HLSL suffix.
std::optional<double> number(std::string s) {
    s = trimmed(s);
    if (s == "true") return 1.0;
    if (s == "false") return 0.0;
    bool negative = false;
    while (!s.empty() && (s[0] == '-' || s[0] == '+')) {
        negative ^= s[0] == '-';
        s = trimmed(s.substr(1));
    }
    while (!s.empty() && std::string("fFhHlLuU").find(s.back()) != std::string::npos &&
           !(s.size() >= 2 && (s[s.size() - 2] == 'e' || s[s.size() - 2] == 'E')))
        s.pop_back();
    if (s.empty()) return std::nullopt;
    double value = 0.0;
    auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
    if (error != std::errc() || end != s.data() + s.size() || !std::isfinite(value)) return std::nullopt;  // "inf", "nan"
    return negative ? -value : value;
}

// A comma-separated list of numbers.
std::optional<std::vector<double>> numbers(const std::string& list) {
    std::vector<double> out;
    size_t from = 0;
    while (from <= list.size()) {
        size_t comma = list.find(',', from);
        if (comma == std::string::npos) comma = list.size();
        std::string item = trimmed(list.substr(from, comma - from));
        if (item.empty() && comma == list.size() && !out.empty()) break;  // {1, 2, 3,}
        auto n = number(item);
        if (!n) return std::nullopt;
        out.push_back(*n);
        from = comma + 1;
    }
    return out;
}

// `2.0`, `float4(1, 2, 3, 4)`, `{1, 2, 3, 4}`, `true`; nullopt for anything else (an expression,
// a nested constructor, another variable's name).
std::optional<std::vector<double>> constantValues(std::string_view initializer) {
    std::string s = trimmed(initializer);
    if (s.empty()) return std::nullopt;
    if (s.front() == '{' && s.back() == '}') return numbers(s.substr(1, s.size() - 2));
    size_t open = s.find('(');
    if (open != std::string::npos && s.back() == ')') {
        std::string type = trimmed(s.substr(0, open));
        if (type.empty() || !std::all_of(type.begin(), type.end(), isIdentifierChar)) return std::nullopt;
        std::string inside = s.substr(open + 1, s.size() - open - 2);
        if (inside.find_first_of("()") != std::string::npos) return std::nullopt;
        return numbers(inside);
    }
    if (auto n = number(s)) return std::vector<double>{*n};
    return std::nullopt;
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
    const std::string code = blankedHlsl(source);
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
    for (size_t i = 0; i < code.size(); ++i) {
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
