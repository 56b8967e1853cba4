#include "editor/VariablesPanel.h"

#include <algorithm>
#include <ctime>
#include <map>

#include <imgui.h>

#include "editor/WidgetChoice.h"
#include "frontend/workspace/VariableValueWriter.h"

namespace rmfx::editor {
namespace {

const ImVec4 errorColor(1.0f, 0.35f, 0.3f, 1.0f);
const ImVec4 okColor(0.5f, 0.85f, 0.5f, 1.0f);

// Edits `value` with the chosen widget; true when the user changed it this frame.
bool editValue(const Variable& variable, const WidgetChoice& w, Value& value) {
    const char* label = variable.name.c_str();
    float* data = value.data.data();
    switch (w.kind) {
        case WidgetKind::Checkbox: {
            bool b = value.asBool();
            if (!ImGui::Checkbox(label, &b)) return false;
            value = Value::ofBool(b);
            return true;
        }
        case WidgetKind::Combo: {
            int current = value.asInt();
            bool known = current >= 0 && current < static_cast<int>(variable.options.size());
            std::string preview = known ? variable.options[current] : "value " + std::to_string(current);
            bool changed = false;
            if (ImGui::BeginCombo(label, preview.c_str())) {
                for (int i = 0; i < static_cast<int>(variable.options.size()); ++i) {
                    if (ImGui::Selectable(variable.options[i].c_str(), i == current) && i != current) {
                        value = Value::ofInt(i);
                        changed = true;
                    }
                    if (i == current) ImGui::SetItemDefaultFocus();
                }
                ImGui::EndCombo();
            }
            return changed;
        }
        case WidgetKind::Slider:
        case WidgetKind::Drag: {
            const bool slider = w.kind == WidgetKind::Slider;
            if (w.integer) {
                int i = value.asInt();
                int lo = static_cast<int>(w.min), hi = static_cast<int>(w.max);
                bool changed = slider ? ImGui::SliderInt(label, &i, lo, hi, w.format.c_str())
                                      : ImGui::DragInt(label, &i, w.dragSpeed, lo, hi, w.format.c_str());
                if (changed) value = Value::ofInt(i);
                return changed;
            }
            return slider ? ImGui::SliderScalarN(label, ImGuiDataType_Float, data, w.components, &w.min, &w.max, w.format.c_str())
                          : ImGui::DragScalarN(label, ImGuiDataType_Float, data, w.components, w.dragSpeed, &w.min, &w.max,
                                               w.format.c_str());
        }
        case WidgetKind::Color: {
            ImGuiColorEditFlags flags = ImGuiColorEditFlags_Float;
            if (w.hdr) flags |= ImGuiColorEditFlags_HDR;
            return w.alpha ? ImGui::ColorEdit4(label, data, flags | ImGuiColorEditFlags_AlphaBar)
                           : ImGui::ColorEdit3(label, data, flags);
        }
        case WidgetKind::Matrix: {
            // Shown as the matrix reads (row r holds column c's r-th entry); stored column by column.
            bool changed = false;
            ImGui::TextUnformatted(label);
            for (int r = 0; r < 4; ++r) {
                float row[4] = {data[r], data[4 + r], data[8 + r], data[12 + r]};
                std::string rowLabel = "##row" + std::to_string(r);
                if (ImGui::DragFloat4(rowLabel.c_str(), row, w.dragSpeed, 0.0f, 0.0f, w.format.c_str())) {
                    for (int c = 0; c < 4; ++c) data[c * 4 + r] = row[c];
                    changed = true;
                }
            }
            return changed;
        }
    }
    return false;
}

void tooltip(const Variable& v) {
    if (!ImGui::IsItemHovered()) return;
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
    if (!v.description.empty()) ImGui::TextUnformatted(v.description.c_str());
    ImGui::TextDisabled("%s %s, default %s", valueTypeName(v.value.type), v.name.c_str(), formatValue(v.value).c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

std::string clockTime() {
    std::time_t now = std::time(nullptr);
    char text[16] = "";
    std::strftime(text, sizeof text, "%H:%M:%S", std::localtime(&now));
    return text;
}

}  // namespace

void VariablesPanel::draw(LiveWorkspace& session) {
    const Workspace& ws = session.workspace();
    GlExecutor& executor = session.executor();
    if (ws.variables.empty()) {
        ImGui::TextDisabled("the workspace declares no variables");
        return;
    }
    // Widgets fill the width the longest name leaves (names are the widgets' labels, on the right).
    float labels = 0.0f;
    for (const Variable& v : ws.variables) labels = std::max(labels, ImGui::CalcTextSize(v.name.c_str()).x);
    labels = std::min(labels + ImGui::GetStyle().ItemInnerSpacing.x * 2.0f, ImGui::GetContentRegionAvail().x * 0.5f);
    ImGui::PushItemWidth(-labels);
    for (const Variable& v : ws.variables) {
        const Value* current = executor.variable(v.name);
        if (!current) continue;
        Value value = *current;
        ImGui::PushID(v.name.c_str());
        const bool isDefault = value == v.value;
        ImGui::BeginDisabled(isDefault);
        if (ImGui::SmallButton("R")) session.resetVariable(v.name);
        ImGui::EndDisabled();
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            ImGui::SetTooltip("reset to the default, %s", formatValue(v.value).c_str());
        ImGui::SameLine();
        if (editValue(v, chooseWidget(v), value)) {
            if (Result<void> set = session.setVariable(v.name, value); !set) {
                status_ = set.error();
                statusIsError_ = true;
            }
        }
        tooltip(v);
        ImGui::PopID();
    }
    ImGui::PopItemWidth();
    ImGui::Spacing();
    if (ImGui::Button("Reset all"))
        for (const Variable& v : ws.variables) session.resetVariable(v.name);
    ImGui::SameLine();
    if (ImGui::Button("Save")) save(session);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("write the current values into %s, changing nothing else", ws.path.filename().string().c_str());
    if (!status_.empty()) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextColored(statusIsError_ ? errorColor : okColor, "%s", status_.c_str());
        ImGui::PopTextWrapPos();
    }
}

void VariablesPanel::save(LiveWorkspace& session) {
    std::map<std::string, Value> values;
    for (const Variable& v : session.workspace().variables)
        if (const Value* current = session.executor().variable(v.name)) values.emplace(v.name, *current);
    const std::string file = session.workspace().path.filename().string();
    Result<void> saved = saveVariableValues(session.workspace().path, values);
    statusIsError_ = !saved;
    status_ = saved ? "saved the values to " + file + " at " + clockTime() : "not saved: " + saved.error();
}

}  // namespace rmfx::editor
