#include "core/Value.h"

#include <charconv>
#include <cmath>
#include <vector>

namespace rmfx {

Value Value::ofFloat(float v) {
    Value value;
    value.type = ValueType::Float;
    value.data[0] = v;
    return value;
}

Value Value::ofInt(int v) {
    Value value;
    value.type = ValueType::Int;
    value.data[0] = static_cast<float>(v);
    return value;
}

Value Value::ofBool(bool v) {
    Value value;
    value.type = ValueType::Bool;
    value.data[0] = v ? 1.0f : 0.0f;
    return value;
}

bool Value::operator==(const Value& other) const {
    if (type != other.type) return false;
    for (int i = 0; i < componentCount(type); ++i)
        if (data[i] != other.data[i]) return false;
    return true;
}

int componentCount(ValueType type) {
    switch (type) {
        case ValueType::Float:
        case ValueType::Int:
        case ValueType::Bool: return 1;
        case ValueType::Vec2: return 2;
        case ValueType::Vec3:
        case ValueType::Color3: return 3;
        case ValueType::Vec4:
        case ValueType::Color4: return 4;
        case ValueType::Mat2: return 4;
        case ValueType::Mat3: return 9;
        case ValueType::Mat4: return 16;
    }
    return 1;
}

const char* valueTypeName(ValueType type) {
    switch (type) {
        case ValueType::Float: return "float";
        case ValueType::Int: return "int";
        case ValueType::Bool: return "bool";
        case ValueType::Vec2: return "vec2";
        case ValueType::Vec3: return "vec3";
        case ValueType::Vec4: return "vec4";
        case ValueType::Color3:
        case ValueType::Color4: return "color";
        case ValueType::Mat2: return "mat2";
        case ValueType::Mat3: return "mat3";
        case ValueType::Mat4: return "mat4";
    }
    return "?";
}

const char* glslTypeName(ValueType type) {
    switch (type) {
        case ValueType::Float: return "float";
        case ValueType::Int: return "int";
        case ValueType::Bool: return "bool";
        case ValueType::Vec2: return "vec2";
        case ValueType::Vec3:
        case ValueType::Color3: return "vec3";
        case ValueType::Vec4:
        case ValueType::Color4: return "vec4";
        case ValueType::Mat2: return "mat2";
        case ValueType::Mat3: return "mat3";
        case ValueType::Mat4: return "mat4";
    }
    return "?";
}

std::optional<ValueType> valueTypeFromElement(std::string_view element) {
    if (element == "float") return ValueType::Float;
    if (element == "int") return ValueType::Int;
    if (element == "bool") return ValueType::Bool;
    if (element == "vec2") return ValueType::Vec2;
    if (element == "vec3") return ValueType::Vec3;
    if (element == "vec4") return ValueType::Vec4;
    if (element == "color") return ValueType::Color4;  // narrowed to Color3 by the value's count
    if (element == "mat4") return ValueType::Mat4;
    return std::nullopt;
}

static std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

std::optional<float> parseFloat(std::string_view text) {
    text = trim(text);
    if (text.empty()) return std::nullopt;
    if (text.front() == '+') text.remove_prefix(1);
    float value = 0.0f;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    if (!std::isfinite(value)) return std::nullopt;
    return value;
}

std::optional<std::vector<float>> parseFloatList(std::string_view text) {
    std::vector<float> values;
    size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && (std::isspace(static_cast<unsigned char>(text[i])) || text[i] == ',')) ++i;
        if (i == text.size()) break;
        size_t start = i;
        while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i])) && text[i] != ',') ++i;
        auto value = parseFloat(text.substr(start, i - start));
        if (!value) return std::nullopt;
        values.push_back(*value);
    }
    return values;
}

Result<Value> parseValue(ValueType type, std::string_view text) {
    auto fail = [](std::string message) { return Result<Value>(Error{std::move(message)}); };
    Value value;
    value.type = type;
    std::string_view t = trim(text);
    if (type == ValueType::Bool) {
        if (t == "true" || t == "1") return Value::ofBool(true);
        if (t == "false" || t == "0") return Value::ofBool(false);
        return fail("expected true or false, got '" + std::string(t) + "'");
    }
    auto numbers = parseFloatList(t);
    if (!numbers) return fail("expected numbers, got '" + std::string(t) + "'");
    size_t count = numbers->size();
    if (type == ValueType::Color3 || type == ValueType::Color4) {
        if (count != 3 && count != 4)
            return fail("a color takes 3 (rgb) or 4 (rgba) numbers, got " + std::to_string(count));
        value.type = count == 3 ? ValueType::Color3 : ValueType::Color4;
    } else if (count != static_cast<size_t>(componentCount(type))) {
        return fail(std::string("a ") + valueTypeName(type) + " takes " + std::to_string(componentCount(type)) +
                    (componentCount(type) == 1 ? " number" : " numbers") + ", got " + std::to_string(count));
    }
    if (type == ValueType::Int) {
        float f = (*numbers)[0];
        if (f != std::floor(f) || std::fabs(f) > 16777216.0f)
            return fail("expected an integer, got '" + std::string(t) + "'");
    }
    for (size_t i = 0; i < count; ++i) value.data[i] = (*numbers)[i];
    return value;
}

static std::string formatFloat(float v) {
    char buffer[32];
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
    return std::string(buffer, ec == std::errc() ? end : buffer);
}

std::string formatValue(const Value& value) {
    if (value.type == ValueType::Bool) return value.asBool() ? "true" : "false";
    if (value.type == ValueType::Int) return std::to_string(value.asInt());
    std::string out;
    for (int i = 0; i < componentCount(value.type); ++i) {
        if (i) out += ' ';
        out += formatFloat(value.data[i]);
    }
    return out;
}

}  // namespace rmfx
