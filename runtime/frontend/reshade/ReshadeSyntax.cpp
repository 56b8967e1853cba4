#include "frontend/reshade/ReshadeSyntax.h"

#include <cmath>
#include <cstdio>

namespace rmfx {
namespace {

std::string spell(double x, ReshadeValue::Kind kind) {
    if (kind == ReshadeValue::Kind::Bool) return x != 0 ? "true" : "false";
    if (kind != ReshadeValue::Kind::Float) return std::to_string(static_cast<long long>(x));
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", x);
    std::string text = buffer;
    if (text.find_first_of(".ein") == std::string::npos) text += ".0";
    return text;
}

}  // namespace

std::string ReshadeValue::describe() const {
    if (kind == Kind::String) {
        std::string out = "\"";
        for (char c : text) {
            if (c == '\0') out += "\\0";
            else if (c == '"' || c == '\\') out += std::string("\\") + c;
            else if (c == '\n') out += "\\n";
            else out += c;
        }
        return out + "\"";
    }
    if (components.size() == 1) return spell(components[0], kind);
    std::string out = "{";
    for (size_t i = 0; i < components.size(); ++i) out += (i ? ", " : "") + spell(components[i], kind);
    return out + "}";
}

const ReshadeAnnotation* findAnnotation(const ReshadeAnnotations& annotations, std::string_view name) {
    for (const ReshadeAnnotation& a : annotations)
        if (a.name == name) return &a;
    return nullptr;
}

}  // namespace rmfx
