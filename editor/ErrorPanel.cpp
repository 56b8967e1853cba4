#include "editor/ErrorPanel.h"

#include <string>
#include <vector>

#include <imgui.h>

namespace rmfx::editor {

namespace {

void drawWarnings(const Diagnostics& warnings) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.85f, 0.4f, 1.0f));
    ImGui::PushTextWrapPos(0.0f);
    for (const Diagnostic& d : warnings) ImGui::TextUnformatted(d.format().c_str());
    ImGui::PopTextWrapPos();
    ImGui::PopStyleColor();
}

}  // namespace

void drawErrorPanel(const Diagnostics& reloadErrors, const Diagnostics& frameErrors, const Diagnostics& reloadWarnings) {
    drawWarnings(reloadWarnings);
    if (reloadErrors.empty() && frameErrors.empty()) return;
    std::vector<std::string> lines;
    if (!reloadErrors.empty()) lines.push_back("The reload failed; the last good build keeps running:");
    for (const Diagnostic& d : reloadErrors) lines.push_back(d.format());
    for (const Diagnostic& d : frameErrors) lines.push_back(d.format());

    // A child window as tall as its wrapped text (ImGui 1.86 has no auto-height children).
    const ImGuiStyle& style = ImGui::GetStyle();
    const float wrap = ImGui::GetContentRegionAvail().x - 2.0f * style.WindowPadding.x;
    float height = 2.0f * style.WindowPadding.y;
    for (const std::string& l : lines) height += ImGui::CalcTextSize(l.c_str(), nullptr, false, wrap).y + style.ItemSpacing.y;

    ImGui::PushStyleColor(ImGuiCol_ChildBg, ImVec4(0.40f, 0.06f, 0.06f, 1.0f));
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.78f, 0.74f, 1.0f));
    ImGui::BeginChild("errors", ImVec2(0.0f, height), true, ImGuiWindowFlags_NoScrollbar);
    ImGui::PushTextWrapPos(0.0f);
    for (const std::string& l : lines) ImGui::TextUnformatted(l.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndChild();
    ImGui::PopStyleColor(2);
}

}  // namespace rmfx::editor
