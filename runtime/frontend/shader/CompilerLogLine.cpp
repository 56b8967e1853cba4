#include "frontend/shader/CompilerLogLine.h"

#include <cctype>
#include <initializer_list>

namespace rmfx {
namespace {

// Consumes the parts of a line in order; each step fails without consuming when its part is not next.
class LineCursor {
public:
    explicit LineCursor(std::string_view line) : rest_(line) {}

    bool literal(std::string_view text) {
        if (!rest_.starts_with(text)) return false;
        rest_.remove_prefix(text.size());
        return true;
    }
    // One or more decimal digits.
    std::optional<std::string_view> digits() {
        size_t n = 0;
        while (n < rest_.size() && std::isdigit(static_cast<unsigned char>(rest_[n]))) ++n;
        if (n == 0) return std::nullopt;
        std::string_view out = rest_.substr(0, n);
        rest_.remove_prefix(n);
        return out;
    }
    // The first of `words` that comes next.
    std::optional<std::string_view> oneOf(std::initializer_list<std::string_view> words) {
        for (std::string_view word : words)
            if (literal(word)) return word;
        return std::nullopt;
    }
    void spaces() {
        while (!rest_.empty() && std::isspace(static_cast<unsigned char>(rest_.front()))) rest_.remove_prefix(1);
    }
    std::string_view rest() const { return rest_; }

private:
    std::string_view rest_;
};

// ERROR: 0:12: message
std::optional<CompilerLogLine> glslangStyle(std::string_view line) {
    LineCursor c(line);
    std::optional<std::string_view> severity = c.oneOf({"ERROR", "WARNING"});
    if (!severity || !c.literal(":")) return std::nullopt;
    c.spaces();
    if (!c.digits() || !c.literal(":")) return std::nullopt;
    std::optional<std::string_view> lineDigits = c.digits();
    if (!lineDigits || !c.literal(":")) return std::nullopt;
    c.spaces();
    return CompilerLogLine{*severity == "ERROR", *lineDigits, c.rest()};
}

// 0:12(5): error: message
std::optional<CompilerLogLine> mesaStyle(std::string_view line) {
    LineCursor c(line);
    if (!c.digits() || !c.literal(":")) return std::nullopt;
    std::optional<std::string_view> lineDigits = c.digits();
    if (!lineDigits || !c.literal("(") || !c.digits() || !c.literal("):")) return std::nullopt;
    c.spaces();
    std::optional<std::string_view> severity = c.oneOf({"error", "warning"});
    if (!severity || !c.literal(":")) return std::nullopt;
    c.spaces();
    return CompilerLogLine{*severity == "error", *lineDigits, c.rest()};
}

// 0(12) : error C1008: message
std::optional<CompilerLogLine> nvidiaStyle(std::string_view line) {
    LineCursor c(line);
    if (!c.digits() || !c.literal("(")) return std::nullopt;
    std::optional<std::string_view> lineDigits = c.digits();
    if (!lineDigits || !c.literal(")")) return std::nullopt;
    c.spaces();
    if (!c.literal(":")) return std::nullopt;
    c.spaces();
    std::optional<std::string_view> severity = c.oneOf({"error", "warning"});
    if (!severity) return std::nullopt;
    c.spaces();
    return CompilerLogLine{*severity == "error", *lineDigits, c.rest()};
}

}  // namespace

std::optional<CompilerLogLine> parseCompilerLogLine(std::string_view line) {
    if (std::optional<CompilerLogLine> parsed = glslangStyle(line)) return parsed;
    if (std::optional<CompilerLogLine> parsed = mesaStyle(line)) return parsed;
    return nvidiaStyle(line);
}

}  // namespace rmfx
