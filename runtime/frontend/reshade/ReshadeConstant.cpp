#include "frontend/reshade/ReshadeConstant.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>

namespace rmfx {
namespace {

using Kind = ReshadeValue::Kind;
using TK = ReshadeToken::Kind;

constexpr int kMaxDepth = 200;
constexpr size_t kMaxComponents = 1 << 16;

int64_t toInt64(double v) {
    if (std::isnan(v)) return 0;
    if (v >= 9.2e18) return INT64_MAX;
    if (v <= -9.2e18) return INT64_MIN;
    return static_cast<int64_t>(v);
}

// A number as a `kind` holds it: ints wrap to 32 bits.
double fit(double v, Kind kind) {
    switch (kind) {
        case Kind::Bool: return v != 0 ? 1 : 0;
        case Kind::Int: return static_cast<double>(static_cast<int32_t>(static_cast<uint32_t>(toInt64(v))));
        case Kind::Uint: return static_cast<double>(static_cast<uint32_t>(toInt64(v)));
        default: return v;
    }
}

Kind widest(Kind a, Kind b) {
    if (a == Kind::Float || b == Kind::Float) return Kind::Float;
    if (a == Kind::Uint || b == Kind::Uint) return Kind::Uint;
    return Kind::Int;
}

int precedence(std::string_view op) {
    if (op == "||") return 1;
    if (op == "&&") return 2;
    if (op == "|") return 3;
    if (op == "^") return 4;
    if (op == "&") return 5;
    if (op == "==" || op == "!=") return 6;
    if (op == "<" || op == ">" || op == "<=" || op == ">=") return 7;
    if (op == "<<" || op == ">>") return 8;
    if (op == "+" || op == "-") return 9;
    if (op == "*" || op == "/" || op == "%") return 10;
    return 0;
}

int swizzleIndex(char c) {
    switch (c) {
        case 'x': case 'r': return 0;
        case 'y': case 'g': return 1;
        case 'z': case 'b': return 2;
        case 'w': case 'a': return 3;
        default: return -1;
    }
}

class Evaluator {
public:
    Evaluator(ReshadeCursor& cursor, const ReshadeNameLookup& lookup, std::string& error, bool stopAtGreater)
        : c_(cursor), lookup_(lookup), error_(error), stopAtGreater_(stopAtGreater) {}

    std::optional<ReshadeValue> ternary() {
        if (!enter()) return std::nullopt;
        std::optional<ReshadeValue> condition = binary(1);
        if (condition && c_.accept("?")) {
            std::optional<ReshadeValue> a = ternary();
            if (!a || !expect(":")) return leave(std::nullopt);
            std::optional<ReshadeValue> b = ternary();
            if (!b) return leave(std::nullopt);
            if (!condition->isNumber()) return leave(fail("a string cannot be a condition"));
            condition = condition->at() != 0 ? a : b;
        }
        return leave(condition);
    }

private:
    bool enter() {
        if (++depth_ <= kMaxDepth) return true;
        --depth_;
        fail("the expression is nested too deep");
        return false;
    }
    std::optional<ReshadeValue> leave(std::optional<ReshadeValue> v) {
        --depth_;
        return v;
    }
    std::nullopt_t fail(std::string message) {
        if (error_.empty()) error_ = std::move(message);
        return std::nullopt;
    }
    bool expect(std::string_view spelling) {
        if (c_.accept(spelling)) return true;
        fail("expected '" + std::string(spelling) + "', found " + c_.describe(c_.peek()));
        return false;
    }

    std::optional<ReshadeValue> binary(int minPrecedence) {
        std::optional<ReshadeValue> left = unary();
        while (left) {
            const ReshadeToken& t = c_.peek();
            if (t.kind != TK::Punct) break;
            const std::string op(c_.text(t));
            if (stopAtGreater_ && (op == ">" || op == ">=" || op == ">>")) break;
            const int p = precedence(op);
            if (p == 0 || p < minPrecedence) break;
            c_.next();
            if (!enter()) return std::nullopt;
            std::optional<ReshadeValue> right = binary(p + 1);
            --depth_;
            if (!right) return std::nullopt;
            left = apply(op, *left, *right);
        }
        return left;
    }

    std::optional<ReshadeValue> apply(const std::string& op, const ReshadeValue& a, const ReshadeValue& b) {
        if (!a.isNumber() || !b.isNumber()) return fail("operator '" + op + "' cannot take a string");
        const size_t n = a.components.size() == 1 ? b.components.size()
                         : b.components.size() == 1 ? a.components.size()
                                                    : std::min(a.components.size(), b.components.size());
        const bool logical = op == "&&" || op == "||";
        const bool comparison = op == "==" || op == "!=" || op == "<" || op == ">" || op == "<=" || op == ">=";
        const bool bitwise = op == "&" || op == "|" || op == "^" || op == "<<" || op == ">>" || op == "%";
        const Kind kind = widest(a.kind, b.kind);
        if (bitwise && op != "%" && kind == Kind::Float) return fail("operator '" + op + "' cannot take a float");
        ReshadeValue out;
        out.kind = logical || comparison ? Kind::Bool : kind;
        for (size_t i = 0; i < n; ++i) {
            const double x = a.at(a.components.size() == 1 ? 0 : i), y = b.at(b.components.size() == 1 ? 0 : i);
            const int64_t ix = toInt64(x), iy = toInt64(y);
            double r = 0;
            if (op == "+") r = x + y;
            else if (op == "-") r = x - y;
            else if (op == "*") r = x * y;
            else if (op == "/" || op == "%") {
                if (kind != Kind::Float) {
                    if (iy == 0) return fail("division by zero");
                    r = static_cast<double>(op == "/" ? ix / iy : ix % iy);
                } else {
                    r = op == "/" ? x / y : std::fmod(x, y);
                }
            } else if (op == "<<") r = static_cast<double>(static_cast<uint32_t>(ix) << (iy & 31));
            else if (op == ">>") r = kind == Kind::Uint ? static_cast<double>(static_cast<uint32_t>(ix) >> (iy & 31))
                                                        : static_cast<double>(static_cast<int32_t>(ix) >> (iy & 31));
            else if (op == "&") r = static_cast<double>(ix & iy);
            else if (op == "|") r = static_cast<double>(ix | iy);
            else if (op == "^") r = static_cast<double>(ix ^ iy);
            else if (op == "&&") r = x != 0 && y != 0;
            else if (op == "||") r = x != 0 || y != 0;
            else if (op == "==") r = x == y;
            else if (op == "!=") r = x != y;
            else if (op == "<") r = x < y;
            else if (op == ">") r = x > y;
            else if (op == "<=") r = x <= y;
            else if (op == ">=") r = x >= y;
            out.components.push_back(fit(r, out.kind));
        }
        return out;
    }

    std::optional<ReshadeValue> unary() {
        if (!enter()) return std::nullopt;
        for (std::string_view op : {"-", "+", "!", "~"}) {
            if (!c_.accept(op)) continue;
            std::optional<ReshadeValue> v = unary();
            if (!v) return leave(std::nullopt);
            if (!v->isNumber()) return leave(fail("operator '" + std::string(op) + "' cannot take a string"));
            if (op == "!") {
                for (double& x : v->components) x = x == 0 ? 1 : 0;
                v->kind = Kind::Bool;
            } else if (op == "~") {
                if (v->kind == Kind::Float) return leave(fail("operator '~' cannot take a float"));
                if (v->kind == Kind::Bool) v->kind = Kind::Int;
                for (double& x : v->components) x = fit(static_cast<double>(~toInt64(x)), v->kind);
            } else if (op == "-") {
                if (v->kind == Kind::Bool) v->kind = Kind::Int;
                for (double& x : v->components) x = fit(-x, v->kind);
            }
            return leave(v);
        }
        // A cast: '(' type ')' value
        if (c_.is("(") && c_.isKind(TK::Identifier, 1) && c_.is(")", 2)) {
            if (std::optional<ReshadeType> type = reshadeNumericType(c_.peekText(1))) {
                c_.next(), c_.next(), c_.next();
                std::optional<ReshadeValue> v = unary();
                if (!v) return leave(std::nullopt);
                return leave(construct(*type, {*v}));
            }
        }
        std::optional<ReshadeValue> v = primary();
        while (v && c_.is(".") && c_.isKind(TK::Identifier, 1)) {
            c_.next();
            const std::string_view letters = c_.text(c_.next());
            ReshadeValue picked{v->kind, {}, {}};
            for (char ch : letters) {
                const int i = swizzleIndex(ch);
                if (i < 0 || static_cast<size_t>(i) >= v->components.size() || letters.size() > 4)
                    return leave(fail("'." + std::string(letters) + "' is not a swizzle of this value"));
                picked.components.push_back(v->components[static_cast<size_t>(i)]);
            }
            v = std::move(picked);
        }
        return leave(v);
    }

    std::optional<ReshadeValue> construct(const ReshadeType& type, const std::vector<ReshadeValue>& args) {
        const Kind kind = type.base == ReshadeBaseType::Bool  ? Kind::Bool
                          : type.base == ReshadeBaseType::Int ? Kind::Int
                          : type.base == ReshadeBaseType::Uint ? Kind::Uint
                                                               : Kind::Float;
        ReshadeValue out{kind, {}, {}};
        for (const ReshadeValue& a : args) {
            if (!a.isNumber()) return fail("'" + type.name + "' cannot take a string");
            for (double x : a.components) out.components.push_back(fit(x, kind));
        }
        const size_t want = static_cast<size_t>(type.rows * type.cols);
        if (out.components.size() == 1 && want > 1) out.components.assign(want, out.components[0]);
        if (want == 1 && out.components.size() > 1) out.components.resize(1);  // a cast to a scalar
        if (out.components.size() != want)
            return fail("'" + type.name + "' takes " + std::to_string(want) + " values, not " + std::to_string(out.components.size()));
        return out;
    }

    std::optional<std::vector<ReshadeValue>> arguments(std::string_view close) {
        std::vector<ReshadeValue> args;
        while (!c_.is(close)) {
            if (!args.empty() && !expect(",")) return std::nullopt;
            if (close == "}" && c_.is("}")) break;  // a trailing comma
            std::optional<ReshadeValue> v = ternaryNoStop();
            if (!v) return std::nullopt;
            args.push_back(std::move(*v));
        }
        if (!expect(close)) return std::nullopt;
        return args;
    }
    // Inside brackets '>' compares again.
    std::optional<ReshadeValue> ternaryNoStop() {
        const bool saved = stopAtGreater_;
        stopAtGreater_ = false;
        std::optional<ReshadeValue> v = ternary();
        stopAtGreater_ = saved;
        return v;
    }

    std::optional<ReshadeValue> intrinsic(const std::string& name, const std::vector<ReshadeValue>& args);

    std::optional<ReshadeValue> primary() {
        const ReshadeToken& t = c_.peek();
        const std::string text(c_.text(t));
        switch (t.kind) {
            case TK::Int: {
                c_.next();
                std::string digits = text;
                bool isUnsigned = false;
                while (!digits.empty() && std::string_view("uUlL").find(digits.back()) != std::string_view::npos) {
                    isUnsigned = isUnsigned || digits.back() == 'u' || digits.back() == 'U';
                    digits.pop_back();
                }
                const int base = digits.size() > 1 && digits[0] == '0' ? (digits[1] == 'x' || digits[1] == 'X' ? 16 : 8) : 10;
                char* end = nullptr;
                const unsigned long long n = std::strtoull(digits.c_str(), &end, base);
                if (end == nullptr || *end != '\0') return fail("'" + text + "' is not a number");
                const Kind kind = isUnsigned || n > 0x7FFFFFFFull ? Kind::Uint : Kind::Int;
                return ReshadeValue::number(kind, fit(static_cast<double>(n), kind));
            }
            case TK::Float: {
                c_.next();
                std::string digits = text;
                while (!digits.empty() && std::string_view("fFhHlL").find(digits.back()) != std::string_view::npos) digits.pop_back();
                return ReshadeValue::number(Kind::Float, std::strtod(digits.c_str(), nullptr));
            }
            case TK::String: {
                std::string joined;
                while (c_.isKind(TK::String)) joined += decodeReshadeString(c_.text(c_.next()));
                return ReshadeValue::string(std::move(joined));
            }
            case TK::Char: {
                c_.next();
                const std::string decoded = decodeReshadeString(text);
                return ReshadeValue::number(Kind::Int, decoded.empty() ? 0 : static_cast<unsigned char>(decoded[0]));
            }
            case TK::Punct: {
                if (c_.accept("(")) {
                    std::optional<ReshadeValue> v = ternaryNoStop();
                    while (v && c_.accept(",")) v = ternaryNoStop();  // the comma operator: the last value
                    if (!v || !expect(")")) return std::nullopt;
                    return v;
                }
                if (c_.accept("{")) {
                    std::optional<std::vector<ReshadeValue>> elements = arguments("}");
                    if (!elements) return std::nullopt;
                    ReshadeValue out{elements->empty() ? Kind::Int : elements->front().kind, {}, {}};
                    for (const ReshadeValue& e : *elements) {
                        if (!e.isNumber()) return fail("an array of strings is not a constant rmfx reads");
                        if (e.kind != out.kind) out.kind = widest(out.kind, e.kind);
                    }
                    for (const ReshadeValue& e : *elements)
                        for (double x : e.components) out.components.push_back(fit(x, out.kind));
                    if (out.components.size() > kMaxComponents) return fail("the array is too large");
                    return out;
                }
                if (!c_.is("::")) break;
                [[fallthrough]];
            }
            case TK::Identifier: {
                if (text == "true" || text == "false" || text == "TRUE" || text == "FALSE") {  // TRUE, FALSE: as in D3D's effects
                    c_.next();
                    return ReshadeValue::number(Kind::Bool, text == "true" || text == "TRUE" ? 1 : 0);
                }
                if (c_.is("(", 1)) {
                    c_.next(), c_.next();
                    std::optional<std::vector<ReshadeValue>> args = arguments(")");
                    if (!args) return std::nullopt;
                    if (std::optional<ReshadeType> type = reshadeNumericType(text)) return construct(*type, *args);
                    return intrinsic(text, *args);
                }
                std::string name;
                if (c_.accept("::")) name = "::";
                for (;;) {
                    if (!c_.isKind(TK::Identifier)) return fail("expected a name after '::', found " + c_.describe(c_.peek()));
                    name += c_.text(c_.next());
                    if (!c_.is("::")) break;
                    c_.next();
                    name += "::";
                }
                if (std::optional<ReshadeValue> v = lookup_ ? lookup_(name) : std::nullopt) return v;
                return fail("'" + name + "' is not a constant");
            }
            default: break;
        }
        return fail("expected a value, found " + c_.describe(t));
    }

    ReshadeCursor& c_;
    const ReshadeNameLookup& lookup_;
    std::string& error_;
    bool stopAtGreater_;
    int depth_ = 0;
};

std::optional<ReshadeValue> Evaluator::intrinsic(const std::string& name, const std::vector<ReshadeValue>& args) {
    struct Intrinsic {
        std::string_view name;
        size_t arity;
        bool keepsKind;  // min, max, abs, clamp, sign keep ints ints
    };
    static constexpr Intrinsic kIntrinsics[] = {
        {"min", 2, true},   {"max", 2, true},   {"abs", 1, true},   {"clamp", 3, true}, {"sign", 1, true},
        {"saturate", 1, false}, {"floor", 1, false}, {"ceil", 1, false}, {"round", 1, false}, {"trunc", 1, false},
        {"frac", 1, false}, {"sqrt", 1, false}, {"rcp", 1, false},  {"pow", 2, false},  {"exp", 1, false},
        {"exp2", 1, false}, {"log", 1, false},  {"log2", 1, false}, {"sin", 1, false},  {"cos", 1, false},
        {"tan", 1, false},  {"lerp", 3, false}};
    const Intrinsic* found = nullptr;
    for (const Intrinsic& i : kIntrinsics)
        if (i.name == name) found = &i;
    if (!found) return fail("'" + name + "' is not a function rmfx computes in a constant");
    if (args.size() != found->arity)
        return fail("'" + name + "' takes " + std::to_string(found->arity) + " arguments, not " + std::to_string(args.size()));
    size_t n = 1;
    Kind kind = Kind::Int;
    for (const ReshadeValue& a : args) {
        if (!a.isNumber()) return fail("'" + name + "' cannot take a string");
        n = std::max(n, a.components.size());
        kind = widest(kind, a.kind);
    }
    if (!found->keepsKind) kind = Kind::Float;
    ReshadeValue out{kind, {}, {}};
    for (size_t i = 0; i < n; ++i) {
        auto arg = [&](size_t k) { return args[k].at(args[k].components.size() == 1 ? 0 : i); };
        const double x = arg(0);
        double r = 0;
        if (name == "min") r = std::min(x, arg(1));
        else if (name == "max") r = std::max(x, arg(1));
        else if (name == "abs") r = std::fabs(x);
        else if (name == "clamp") r = std::min(std::max(x, arg(1)), arg(2));
        else if (name == "sign") r = x > 0 ? 1 : x < 0 ? -1 : 0;
        else if (name == "saturate") r = std::min(std::max(x, 0.0), 1.0);
        else if (name == "floor") r = std::floor(x);
        else if (name == "ceil") r = std::ceil(x);
        else if (name == "round") r = std::round(x);
        else if (name == "trunc") r = std::trunc(x);
        else if (name == "frac") r = x - std::floor(x);
        else if (name == "sqrt") r = std::sqrt(x);
        else if (name == "rcp") r = 1.0 / x;
        else if (name == "pow") r = std::pow(x, arg(1));
        else if (name == "exp") r = std::exp(x);
        else if (name == "exp2") r = std::exp2(x);
        else if (name == "log") r = std::log(x);
        else if (name == "log2") r = std::log2(x);
        else if (name == "sin") r = std::sin(x);
        else if (name == "cos") r = std::cos(x);
        else if (name == "tan") r = std::tan(x);
        else if (name == "lerp") r = x + (arg(1) - x) * arg(2);
        out.components.push_back(fit(r, kind));
    }
    return out;
}

}  // namespace

std::optional<ReshadeValue> readReshadeConstant(ReshadeCursor& cursor, const ReshadeNameLookup& lookup, std::string& error,
                                                bool stopAtGreater) {
    error.clear();
    Evaluator evaluator(cursor, lookup, error, stopAtGreater);
    std::optional<ReshadeValue> v = evaluator.ternary();
    if (!v && error.empty()) error = "not a constant";
    return v;
}

std::optional<ReshadeType> reshadeNumericType(std::string_view name) {
    struct Base {
        std::string_view prefix;
        ReshadeBaseType base;
    };
    static constexpr Base kBases[] = {{"bool", ReshadeBaseType::Bool},     {"int", ReshadeBaseType::Int},
                                      {"uint", ReshadeBaseType::Uint},     {"dword", ReshadeBaseType::Uint},
                                      {"float", ReshadeBaseType::Float},   {"half", ReshadeBaseType::Float},
                                      {"double", ReshadeBaseType::Float},  {"min16float", ReshadeBaseType::Float},
                                      {"min10float", ReshadeBaseType::Float}, {"min16int", ReshadeBaseType::Int},
                                      {"min12int", ReshadeBaseType::Int},  {"min16uint", ReshadeBaseType::Uint}};
    for (const Base& b : kBases) {
        if (name.substr(0, b.prefix.size()) != b.prefix) continue;
        std::string_view rest = name.substr(b.prefix.size());
        ReshadeType type;
        type.base = b.base;
        type.name = std::string(name);
        auto dim = [](char c) { return c >= '1' && c <= '4' ? c - '0' : 0; };
        if (rest.empty()) return type;
        if (rest.size() == 1 && dim(rest[0])) {
            type.rows = dim(rest[0]);
            return type;
        }
        if (rest.size() == 3 && dim(rest[0]) && rest[1] == 'x' && dim(rest[2])) {
            type.rows = dim(rest[0]);
            type.cols = dim(rest[2]);
            return type;
        }
    }
    return std::nullopt;
}

std::string decodeReshadeString(std::string_view literal) {
    if (literal.size() >= 2 && (literal.front() == '"' || literal.front() == '\'')) {
        literal.remove_prefix(1);
        if (!literal.empty() && (literal.back() == '"' || literal.back() == '\'')) literal.remove_suffix(1);
    }
    std::string out;
    for (size_t i = 0; i < literal.size(); ++i) {
        const char c = literal[i];
        if (c != '\\' || i + 1 >= literal.size()) {
            out += c;
            continue;
        }
        const char e = literal[++i];
        switch (e) {
            case 'n': out += '\n'; break;
            case 't': out += '\t'; break;
            case 'r': out += '\r'; break;
            case 'a': out += '\a'; break;
            case 'b': out += '\b'; break;
            case 'f': out += '\f'; break;
            case 'v': out += '\v'; break;
            case 'x': {
                unsigned value = 0;
                size_t k = i + 1;
                while (k < literal.size() && k < i + 3 && std::isxdigit(static_cast<unsigned char>(literal[k])))
                    value = value * 16 + static_cast<unsigned>(std::stoi(std::string(1, literal[k++]), nullptr, 16));
                out += static_cast<char>(value);
                i = k - 1;
                break;
            }
            default:
                if (e >= '0' && e <= '7') {
                    unsigned value = 0;
                    size_t k = i;
                    while (k < literal.size() && k < i + 3 && literal[k] >= '0' && literal[k] <= '7') value = value * 8 + static_cast<unsigned>(literal[k++] - '0');
                    out += static_cast<char>(value);
                    i = k - 1;
                } else {
                    out += e;  // \\, \", \', and any other character as itself
                }
        }
    }
    return out;
}

ReshadeValue convertReshadeValue(const ReshadeValue& value, ReshadeValue::Kind kind) {
    if (!value.isNumber() || kind == ReshadeValue::Kind::String) return value;
    ReshadeValue out{kind, {}, {}};
    for (double x : value.components) out.components.push_back(fit(kind == Kind::Float ? x : std::trunc(x), kind));
    return out;
}

}  // namespace rmfx
