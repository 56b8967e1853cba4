#pragma once
// Typed values of workspace variables and their text form ("0.5", "1 2 3", "true").

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/Result.h"

namespace rmfx {

// Mat2 and Mat3 come only from RenderMonkey imports (RmDynamicVariable); matrices are column-major.
enum class ValueType { Float, Int, Bool, Vec2, Vec3, Vec4, Color3, Color4, Mat2, Mat3, Mat4 };

struct Value {
    ValueType type = ValueType::Float;
    std::array<float, 16> data{};  // ints and bools are stored exactly as floats (ints up to 2^24)

    static Value ofFloat(float v);
    static Value ofInt(int v);
    static Value ofBool(bool v);

    float asFloat() const { return data[0]; }
    int asInt() const { return static_cast<int>(data[0]); }
    bool asBool() const { return data[0] != 0.0f; }

    bool operator==(const Value& other) const;
};

int componentCount(ValueType type);
// The name used in workspace files: "float", "vec3", "color" (both colour types), "mat4".
const char* valueTypeName(ValueType type);
// The GLSL type a uniform bound to this variable must have.
const char* glslTypeName(ValueType type);
std::optional<ValueType> valueTypeFromElement(std::string_view element);

// Parses text into a value of the given type. Colours accept 3 or 4 numbers when
// allowColorWidening; ints reject fractions; bools take true/false/1/0. A failure's error() is a
// sentence saying what was expected.
Result<Value> parseValue(ValueType type, std::string_view text);

// Inverse of parseValue: shortest text that parses back to the same floats.
std::string formatValue(const Value& value);

// Splits on whitespace and commas.
std::optional<std::vector<float>> parseFloatList(std::string_view text);
std::optional<float> parseFloat(std::string_view text);

}  // namespace rmfx
