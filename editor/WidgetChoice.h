#pragma once
// Which ImGui widget edits a workspace variable, decided from its type and hints alone (no ImGui
// here, so the choice is unit-tested): the Variables panel only carries it out.

#include <string>

#include "model/Workspace.h"

namespace rmfx::editor {

enum class WidgetKind {
    Checkbox,  // bool
    Combo,     // int with options: value i selects options[i]
    Slider,    // float or int components within [min, max]
    Drag,      // float or int components, unbounded or clamped to whichever of min/max is given
    Color,     // colour picker: rgb or rgba
    Matrix,    // mat4: four rows of four drags
};

struct WidgetChoice {
    WidgetKind kind = WidgetKind::Drag;
    int components = 1;     // edited numbers per row: 1..4 (a matrix: 4 rows of 4)
    bool integer = false;   // SliderInt/DragInt rather than the float widgets
    // Slider range; for a drag the clamp range (ImGui clamps only when min < max).
    float min = 0.0f, max = 0.0f;
    float dragSpeed = 0.01f;  // value change per pixel of drag
    std::string format;       // printf format of the number: "%d", "%.3f", …
    bool alpha = false;       // colour: edits alpha too
    bool hdr = false;         // colour: values may exceed 1 (ImGuiColorEditFlags_HDR | _Float)
};

WidgetChoice chooseWidget(const Variable& variable);

}  // namespace rmfx::editor
