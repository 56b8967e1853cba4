#include "core/Value.h"

#include <gtest/gtest.h>

namespace rmfx {

namespace {

// Parses text that must be valid.
Value parsed(ValueType type, std::string_view text) {
    Result<Value> v = parseValue(type, text);
    EXPECT_TRUE(v.ok()) << "'" << text << "': " << v.error();
    return v ? *v : Value{};
}

// The error sentence for text that must be rejected.
std::string rejection(ValueType type, std::string_view text) {
    Result<Value> v = parseValue(type, text);
    EXPECT_FALSE(v.ok()) << "'" << text << "' parsed as " << (v ? formatValue(*v) : "");
    return v.error();
}

}  // namespace

TEST(Value, ParsesEveryType) {
    EXPECT_EQ(parsed(ValueType::Float, " 0.25 "), Value::ofFloat(0.25f));
    EXPECT_EQ(parsed(ValueType::Float, "+1e3"), Value::ofFloat(1000.0f));
    EXPECT_EQ(parsed(ValueType::Int, "-7"), Value::ofInt(-7));
    EXPECT_EQ(parsed(ValueType::Int, "3.0"), Value::ofInt(3));
    EXPECT_EQ(parsed(ValueType::Bool, "true"), Value::ofBool(true));
    EXPECT_EQ(parsed(ValueType::Bool, "0"), Value::ofBool(false));

    Value v3 = parsed(ValueType::Vec3, "1, 2,3");
    EXPECT_EQ(v3.type, ValueType::Vec3);
    EXPECT_EQ(v3.data[0], 1.0f);
    EXPECT_EQ(v3.data[1], 2.0f);
    EXPECT_EQ(v3.data[2], 3.0f);

    Value m = parsed(ValueType::Mat4, "1 0 0 0  0 1 0 0  0 0 1 0  4 5 6 1");
    EXPECT_EQ(m.type, ValueType::Mat4);
    EXPECT_EQ(m.data[12], 4.0f);
    EXPECT_EQ(m.data[15], 1.0f);
}

TEST(Value, ColorNarrowsToItsCount) {
    EXPECT_EQ(parsed(ValueType::Color4, "0.9 0.75 0.5").type, ValueType::Color3);
    EXPECT_EQ(parsed(ValueType::Color4, "0.9 0.75 0.5 1").type, ValueType::Color4);
    EXPECT_EQ(parsed(ValueType::Color3, "0.9 0.75 0.5 1").type, ValueType::Color4);
}

TEST(Value, RejectionsSayWhatWasExpected) {
    EXPECT_EQ(rejection(ValueType::Float, "abc"), "expected numbers, got 'abc'");
    EXPECT_EQ(rejection(ValueType::Float, ""), "a float takes 1 number, got 0");
    EXPECT_EQ(rejection(ValueType::Float, "1 2"), "a float takes 1 number, got 2");
    EXPECT_EQ(rejection(ValueType::Vec3, "1 2"), "a vec3 takes 3 numbers, got 2");
    EXPECT_EQ(rejection(ValueType::Mat4, "1 0 0 1"), "a mat4 takes 16 numbers, got 4");
    EXPECT_EQ(rejection(ValueType::Int, "2.5"), "expected an integer, got '2.5'");
    EXPECT_EQ(rejection(ValueType::Int, "1e9"), "expected an integer, got '1e9'");
    EXPECT_EQ(rejection(ValueType::Bool, "yes"), "expected true or false, got 'yes'");
    EXPECT_EQ(rejection(ValueType::Color4, "1 0"), "a color takes 3 (rgb) or 4 (rgba) numbers, got 2");
    EXPECT_EQ(rejection(ValueType::Vec2, "1 nan"), "expected numbers, got '1 nan'");
    EXPECT_EQ(rejection(ValueType::Float, "inf"), "expected numbers, got 'inf'");
    EXPECT_EQ(rejection(ValueType::Float, "1e39"), "expected numbers, got '1e39'");  // overflows a float
}

TEST(Value, ParseFloatIsStrict) {
    EXPECT_EQ(parseFloat("0.5"), 0.5f);
    EXPECT_EQ(parseFloat(" -2 "), -2.0f);
    EXPECT_FALSE(parseFloat("0.5x"));
    EXPECT_FALSE(parseFloat("1,5"));
    EXPECT_FALSE(parseFloat(""));
    EXPECT_FALSE(parseFloat("++1"));
    auto list = parseFloatList(" 1,2 ,, 3 ");
    ASSERT_TRUE(list);
    EXPECT_EQ(*list, (std::vector<float>{1.0f, 2.0f, 3.0f}));
    EXPECT_FALSE(parseFloatList("1 two 3"));
    ASSERT_TRUE(parseFloatList(""));
    EXPECT_TRUE(parseFloatList("")->empty());
}

TEST(Value, FormatIsShortestAndRoundTrips) {
    EXPECT_EQ(formatValue(Value::ofFloat(0.1f)), "0.1");
    EXPECT_EQ(formatValue(Value::ofFloat(2.0f)), "2");
    EXPECT_EQ(formatValue(Value::ofFloat(-0.35f)), "-0.35");
    EXPECT_EQ(formatValue(Value::ofInt(-3)), "-3");
    EXPECT_EQ(formatValue(Value::ofBool(true)), "true");
    EXPECT_EQ(formatValue(Value::ofBool(false)), "false");
    EXPECT_EQ(formatValue(parsed(ValueType::Color4, "0.9 0.75 0.5")), "0.9 0.75 0.5");
    EXPECT_EQ(formatValue(parsed(ValueType::Vec4, "1,2,3,4")), "1 2 3 4");

    const std::pair<ValueType, const char*> cases[] = {
        {ValueType::Float, "0.1"},         {ValueType::Float, "1e-07"},       {ValueType::Float, "123456.79"},
        {ValueType::Float, "3.4028235e+38"}, {ValueType::Int, "16777216"},  {ValueType::Int, "-1"},
        {ValueType::Bool, "true"},         {ValueType::Vec2, "0.333 -2"},     {ValueType::Vec3, "-0.35 0.12 -0.93"},
        {ValueType::Vec4, "0 0 0 1"},      {ValueType::Color4, "1 0.5 0.25 0.125"},
        {ValueType::Mat4, "1 0 0 0 0 1 0 0 0 0 1 0 0.1 0.2 0.3 1"},
    };
    for (const auto& [type, text] : cases) {
        Value v = parsed(type, text);
        EXPECT_EQ(formatValue(v), text);
        EXPECT_EQ(parsed(type, formatValue(v)), v) << text;
    }
    // Any float survives format → parse bit for bit.
    for (float f : {1.0f / 3.0f, 0.7f, 1e-30f, -65504.0f, 0.1f + 0.2f}) {
        Value v = Value::ofFloat(f);
        EXPECT_EQ(parsed(ValueType::Float, formatValue(v)), v) << formatValue(v);
    }
}

TEST(Value, TypeNames) {
    EXPECT_STREQ(valueTypeName(ValueType::Color3), "color");
    EXPECT_STREQ(valueTypeName(ValueType::Color4), "color");
    EXPECT_STREQ(glslTypeName(ValueType::Color3), "vec3");
    EXPECT_STREQ(glslTypeName(ValueType::Color4), "vec4");
    EXPECT_EQ(valueTypeFromElement("color"), ValueType::Color4);
    EXPECT_EQ(valueTypeFromElement("mat4"), ValueType::Mat4);
    EXPECT_FALSE(valueTypeFromElement("mat3"));
    EXPECT_EQ(componentCount(ValueType::Mat4), 16);
    EXPECT_EQ(componentCount(ValueType::Color3), 3);
}

}  // namespace rmfx
