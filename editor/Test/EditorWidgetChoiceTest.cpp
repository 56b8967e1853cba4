#include "editor/WidgetChoice.h"

#include <cfloat>

#include <gtest/gtest.h>

namespace rmfx::editor {
namespace {

Variable variable(ValueType type, WidgetHint hint = WidgetHint::Auto) {
    Variable v;
    v.name = "v";
    v.value.type = type;
    v.widget = hint;
    return v;
}

}  // namespace

TEST(EditorWidgetChoice, BoolIsACheckbox) {
    EXPECT_EQ(chooseWidget(variable(ValueType::Bool)).kind, WidgetKind::Checkbox);
    EXPECT_EQ(chooseWidget(variable(ValueType::Bool, WidgetHint::Checkbox)).kind, WidgetKind::Checkbox);
}

TEST(EditorWidgetChoice, IntWithOptionsIsACombo) {
    Variable v = variable(ValueType::Int, WidgetHint::Combo);
    v.options = {"Cross", "Snow"};
    EXPECT_EQ(chooseWidget(v).kind, WidgetKind::Combo);
    v.widget = WidgetHint::Auto;  // options alone imply a combo
    EXPECT_EQ(chooseWidget(v).kind, WidgetKind::Combo);
    v.widget = WidgetHint::Drag;  // an explicit drag wins
    EXPECT_EQ(chooseWidget(v).kind, WidgetKind::Drag);
}

TEST(EditorWidgetChoice, FloatWithARangeIsASliderOverIt) {
    Variable v = variable(ValueType::Float);
    v.min = 0.0f;
    v.max = 4.0f;
    v.step = 0.01f;
    WidgetChoice c = chooseWidget(v);
    EXPECT_EQ(c.kind, WidgetKind::Slider);
    EXPECT_FALSE(c.integer);
    EXPECT_EQ(c.components, 1);
    EXPECT_EQ(c.min, 0.0f);
    EXPECT_EQ(c.max, 4.0f);
    EXPECT_EQ(c.format, "%.2f");  // step 0.01: two decimals
}

TEST(EditorWidgetChoice, FloatFormatShowsOneStep) {
    auto formatFor = [](float step) {
        Variable v = variable(ValueType::Float);
        v.step = step;
        return chooseWidget(v).format;
    };
    EXPECT_EQ(formatFor(0.001f), "%.3f");
    EXPECT_EQ(formatFor(0.0001f), "%.4f");
    EXPECT_EQ(formatFor(0.5f), "%.1f");
    EXPECT_EQ(formatFor(1.0f), "%.0f");
    EXPECT_EQ(formatFor(2.5f), "%.1f");
    EXPECT_EQ(formatFor(1.0f / 3.0f), "%.4f");  // no finite decimal: within a thousandth of a step
}

TEST(EditorWidgetChoice, IntSliderUsesIntegers) {
    Variable v = variable(ValueType::Int, WidgetHint::Slider);
    v.min = 1.0f;
    v.max = 8.0f;
    WidgetChoice c = chooseWidget(v);
    EXPECT_EQ(c.kind, WidgetKind::Slider);
    EXPECT_TRUE(c.integer);
    EXPECT_EQ(c.format, "%d");
    EXPECT_EQ(c.min, 1.0f);
    EXPECT_EQ(c.max, 8.0f);
}

TEST(EditorWidgetChoice, NoRangeIsAnUnclampedDrag) {
    Variable v = variable(ValueType::Float);
    WidgetChoice c = chooseWidget(v);
    EXPECT_EQ(c.kind, WidgetKind::Drag);
    EXPECT_EQ(c.min, 0.0f);  // min == max: ImGui does not clamp
    EXPECT_EQ(c.max, 0.0f);
    EXPECT_FLOAT_EQ(c.dragSpeed, 0.01f);
    EXPECT_EQ(c.format, "%.3f");
}

TEST(EditorWidgetChoice, DragHintWithARangeClampsToIt) {
    Variable v = variable(ValueType::Float, WidgetHint::Drag);
    v.min = -2.0f;
    v.max = 2.0f;
    WidgetChoice c = chooseWidget(v);
    EXPECT_EQ(c.kind, WidgetKind::Drag);
    EXPECT_EQ(c.min, -2.0f);
    EXPECT_EQ(c.max, 2.0f);
    EXPECT_FLOAT_EQ(c.dragSpeed, 4.0f / 200.0f);  // the range in 200 pixels
}

TEST(EditorWidgetChoice, OneSidedRangeClampsThatSideOnly) {
    Variable v = variable(ValueType::Float);
    v.min = 0.5f;
    v.step = 0.25f;
    WidgetChoice c = chooseWidget(v);
    EXPECT_EQ(c.kind, WidgetKind::Drag);
    EXPECT_EQ(c.min, 0.5f);
    EXPECT_EQ(c.max, FLT_MAX);
    EXPECT_EQ(c.dragSpeed, 0.25f);
    EXPECT_EQ(c.format, "%.2f");
}

TEST(EditorWidgetChoice, VectorsEditEveryComponent) {
    EXPECT_EQ(chooseWidget(variable(ValueType::Vec2)).components, 2);
    WidgetChoice v3 = chooseWidget(variable(ValueType::Vec3));
    EXPECT_EQ(v3.kind, WidgetKind::Drag);
    EXPECT_EQ(v3.components, 3);
    Variable ranged = variable(ValueType::Vec4);
    ranged.min = -1.0f;
    ranged.max = 1.0f;
    WidgetChoice v4 = chooseWidget(ranged);
    EXPECT_EQ(v4.kind, WidgetKind::Slider);
    EXPECT_EQ(v4.components, 4);
}

TEST(EditorWidgetChoice, ColoursGetAPickerWithHdrWhenAsked) {
    WidgetChoice rgb = chooseWidget(variable(ValueType::Color3));
    EXPECT_EQ(rgb.kind, WidgetKind::Color);
    EXPECT_FALSE(rgb.alpha);
    EXPECT_FALSE(rgb.hdr);
    Variable hdr = variable(ValueType::Color4);
    hdr.hdr = true;
    WidgetChoice rgba = chooseWidget(hdr);
    EXPECT_EQ(rgba.kind, WidgetKind::Color);
    EXPECT_TRUE(rgba.alpha);
    EXPECT_TRUE(rgba.hdr);
    // A vec3 is a colour only when it says so.
    EXPECT_EQ(chooseWidget(variable(ValueType::Vec3, WidgetHint::Color)).kind, WidgetKind::Color);
    WidgetChoice vec4Color = chooseWidget(variable(ValueType::Vec4, WidgetHint::Color));
    EXPECT_TRUE(vec4Color.alpha);
}

TEST(EditorWidgetChoice, Mat4IsFourRowsOfFour) {
    WidgetChoice c = chooseWidget(variable(ValueType::Mat4));
    EXPECT_EQ(c.kind, WidgetKind::Matrix);
    EXPECT_EQ(c.components, 4);
}

}  // namespace rmfx::editor
