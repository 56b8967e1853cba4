#include "editor/WidgetChoice.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace rmfx::editor {
namespace {

// Enough decimals to show one step: step 0.01 → "%.2f", 0.25 → "%.2f", 1 → "%.0f", none → "%.3f".
std::string floatFormat(const std::optional<float>& step) {
    int decimals = 3;
    if (step && *step > 0.0f) {
        decimals = 0;
        for (double scaled = *step; decimals < 6 && std::fabs(scaled - std::round(scaled)) > 1e-3 * scaled; scaled *= 10.0) ++decimals;
    }
    return "%." + std::to_string(decimals) + "f";
}

bool isColorType(ValueType type) { return type == ValueType::Color3 || type == ValueType::Color4; }

}  // namespace

WidgetChoice chooseWidget(const Variable& v) {
    WidgetChoice c;
    const ValueType type = v.value.type;
    c.components = std::min(componentCount(type), 4);
    c.integer = type == ValueType::Int;
    c.format = c.integer ? "%d" : floatFormat(v.step);

    if (type == ValueType::Bool) {
        c.kind = WidgetKind::Checkbox;
        return c;
    }
    if (type == ValueType::Int && !v.options.empty() && (v.widget == WidgetHint::Combo || v.widget == WidgetHint::Auto)) {
        c.kind = WidgetKind::Combo;
        return c;
    }
    if (type == ValueType::Mat2 || type == ValueType::Mat3 || type == ValueType::Mat4) {
        c.kind = WidgetKind::Matrix;
        c.dragSpeed = v.step.value_or(0.01f);
        return c;
    }
    const bool colorCapable = isColorType(type) || type == ValueType::Vec3 || type == ValueType::Vec4;
    if (colorCapable && (v.widget == WidgetHint::Color || (isColorType(type) && v.widget == WidgetHint::Auto))) {
        c.kind = WidgetKind::Color;
        c.alpha = c.components == 4;
        c.hdr = v.hdr;
        return c;
    }
    const bool ranged = v.min && v.max && *v.min < *v.max;
    if (v.widget == WidgetHint::Slider || (v.widget == WidgetHint::Auto && ranged)) {
        if (ranged) {
            c.kind = WidgetKind::Slider;
            c.min = *v.min;
            c.max = *v.max;
            return c;
        }
    }
    c.kind = WidgetKind::Drag;
    if (v.step) c.dragSpeed = *v.step;
    else if (ranged) c.dragSpeed = (*v.max - *v.min) / 200.0f;
    else c.dragSpeed = c.integer ? 0.2f : 0.01f;
    if (v.min || v.max) {
        c.min = v.min.value_or(-FLT_MAX);
        c.max = v.max.value_or(FLT_MAX);
    }
    return c;
}

}  // namespace rmfx::editor
