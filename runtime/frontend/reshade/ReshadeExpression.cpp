#include "frontend/reshade/ReshadeExpression.h"

#include <cctype>
#include <limits>

namespace rmfx {
namespace {

// Nesting a parser may go to (parentheses, unary operators, ?:) before it refuses the expression,
// so a line of 100000 '(' cannot exhaust the stack.
constexpr int kMaxDepth = 256;

class Parser {
public:
    explicit Parser(const PpTokens& tokens) {
        for (const PpToken& t : tokens)
            if (!t.isSpace()) tokens_.push_back(&t);
    }

    ExpressionValue run() {
        ExpressionValue result;
        if (tokens_.empty()) {
            result.error = "#if with no expression";
            return result;
        }
        result.value = conditional(0);
        if (error_.empty() && at_ < tokens_.size()) fail("unexpected '" + tokens_[at_]->text + "'");
        result.error = error_;
        if (!error_.empty()) result.value = 0;
        return result;
    }

private:
    const PpToken* peek() const { return at_ < tokens_.size() ? tokens_[at_] : nullptr; }
    bool accept(std::string_view punct) {
        if (const PpToken* t = peek(); t && t->isPunct(punct)) {
            ++at_;
            return true;
        }
        return false;
    }
    int64_t fail(const std::string& message) {
        if (error_.empty()) error_ = message;
        at_ = tokens_.size();
        return 0;
    }

    int64_t conditional(int depth) {
        if (depth > kMaxDepth) return fail("expression nested too deep");
        int64_t c = binary(0, depth);
        if (!accept("?")) return c;
        int64_t a = conditional(depth + 1);
        if (!accept(":")) return fail("expected ':' in ?: expression");
        int64_t b = conditional(depth + 1);
        return c ? a : b;
    }

    // Binary operators by precedence level, lowest first.
    static int levelOf(std::string_view op) {
        static const std::string_view levels[][4] = {{"||"}, {"&&"}, {"|"}, {"^"}, {"&"}, {"==", "!="},
                                                     {"<", "<=", ">", ">="}, {"<<", ">>"}, {"+", "-"},
                                                     {"*", "/", "%"}};
        for (int level = 0; level < 10; ++level)
            for (std::string_view candidate : levels[level])
                if (!candidate.empty() && candidate == op) return level;
        return -1;
    }

    int64_t binary(int level, int depth) {
        if (level == 10) return unary(depth);
        int64_t left = binary(level + 1, depth);
        while (const PpToken* t = peek()) {
            if (t->kind != PpToken::Kind::Punct || levelOf(t->text) != level) break;
            const std::string op = t->text;
            ++at_;
            int64_t right = binary(level + 1, depth);
            if (!error_.empty()) return 0;
            left = apply(op, left, right);
        }
        return left;
    }

    int64_t apply(const std::string& op, int64_t a, int64_t b) {
        using U = uint64_t;
        if (op == "||") return a || b;
        if (op == "&&") return a && b;
        if (op == "|") return a | b;
        if (op == "^") return a ^ b;
        if (op == "&") return a & b;
        if (op == "==") return a == b;
        if (op == "!=") return a != b;
        if (op == "<") return a < b;
        if (op == "<=") return a <= b;
        if (op == ">") return a > b;
        if (op == ">=") return a >= b;
        if (op == "<<") return b < 0 || b > 63 ? 0 : static_cast<int64_t>(U(a) << b);
        if (op == ">>") return b < 0 || b > 63 ? (a < 0 ? -1 : 0) : a >> b;
        if (op == "+") return static_cast<int64_t>(U(a) + U(b));
        if (op == "-") return static_cast<int64_t>(U(a) - U(b));
        if (op == "*") return static_cast<int64_t>(U(a) * U(b));
        if (b == 0) return fail(op == "/" ? "division by zero in #if" : "remainder by zero in #if");
        if (a == std::numeric_limits<int64_t>::min() && b == -1) return op == "/" ? a : 0;
        return op == "/" ? a / b : a % b;
    }

    int64_t unary(int depth) {
        if (depth > kMaxDepth) return fail("expression nested too deep");
        if (accept("-")) return static_cast<int64_t>(0 - uint64_t(unary(depth + 1)));
        if (accept("+")) return unary(depth + 1);
        if (accept("!")) return !unary(depth + 1);
        if (accept("~")) return ~unary(depth + 1);
        if (accept("(")) {
            int64_t v = conditional(depth + 1);
            if (!accept(")")) return fail("expected ')'");
            return v;
        }
        const PpToken* t = peek();
        if (!t) return fail("expression ends early");
        ++at_;
        switch (t->kind) {
        case PpToken::Kind::Identifier:
            return 0;  // an identifier no macro replaced
        case PpToken::Kind::Number:
            return number(t->text);
        case PpToken::Kind::Char:
            return character(t->text);
        default:
            return fail("unexpected '" + t->text + "'");
        }
    }

    int64_t number(const std::string& text) {
        size_t end = text.size();
        while (end > 0 && (text[end - 1] == 'u' || text[end - 1] == 'U' || text[end - 1] == 'l' || text[end - 1] == 'L'))
            --end;
        std::string digits = text.substr(0, end);
        int base = 10;
        size_t at = 0;
        if (digits.size() > 2 && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X')) {
            base = 16;
            at = 2;
        } else if (digits.size() > 1 && digits[0] == '0') {
            base = 8;
            at = 1;
        }
        uint64_t value = 0;
        for (; at < digits.size(); ++at) {
            char c = static_cast<char>(std::tolower(static_cast<unsigned char>(digits[at])));
            int d = std::isdigit(static_cast<unsigned char>(c)) ? c - '0' : (c >= 'a' && c <= 'f') ? c - 'a' + 10 : 99;
            if (d >= base) return fail("'" + text + "' is no integer");
            value = value * base + d;
        }
        return static_cast<int64_t>(value);
    }

    int64_t character(const std::string& text) {
        if (text.size() >= 3 && text[1] != '\\') return static_cast<unsigned char>(text[1]);
        if (text.size() >= 4 && text[1] == '\\') {
            switch (text[2]) {
            case 'n': return '\n';
            case 't': return '\t';
            case 'r': return '\r';
            case '0': return 0;
            default: return static_cast<unsigned char>(text[2]);
            }
        }
        return fail("invalid character constant " + text);
    }

    std::vector<const PpToken*> tokens_;
    size_t at_ = 0;
    std::string error_;
};

}  // namespace

ExpressionValue evaluateExpression(const PpTokens& tokens) { return Parser(tokens).run(); }

}  // namespace rmfx
