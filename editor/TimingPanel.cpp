#include "editor/TimingPanel.h"

#include <algorithm>
#include <string>

#include <imgui.h>

namespace rmfx::editor {

void TimingPanel::record(GlExecutor& executor) {
    const std::vector<PassTiming>& passes = executor.passTimings();
    history_.add(passes, executor.frameGpuMilliseconds());
    skippedPasses_.clear();
    const std::map<std::string, std::string>& skipped = executor.contentSkippedEffects(false);
    for (const auto& [name, why] : skipped)
        if (const Effect* e = executor.workspace().findEffect(name)) skippedPasses_.insert(e->passes.begin(), e->passes.end());
    // Passes outside the effects that only they read are left out with them.
    if (!skipped.empty())
        for (const auto& [pass, effects] : executor.passesDrawnOnlyForEffects())
            if (std::all_of(effects.begin(), effects.end(), [&](const std::string& e) { return skipped.count(e) > 0; }))
                skippedPasses_.insert(pass);
    for (const PassTiming& p : passes)
        if (!skippedPasses_.count(p.pass)) ranMilliseconds_[p.pass] = p.milliseconds;
}

void TimingPanel::draw() {
    if (history_.size() == 0) {
        ImGui::TextDisabled("waiting for the first timed frame");
        return;
    }
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchProp;
    if (ImGui::BeginTable("passes", 3, flags)) {
        ImGui::TableSetupColumn("pass", ImGuiTableColumnFlags_WidthStretch, 2.0f);
        ImGui::TableSetupColumn("GPU ms", ImGuiTableColumnFlags_WidthStretch, 1.0f);
        ImGui::TableSetupColumn("average", ImGuiTableColumnFlags_WidthStretch, 1.0f);
        ImGui::TableHeadersRow();
        for (const TimingHistory::Row& r : history_.rows()) {
            const bool skipped = skippedPasses_.count(r.pass) > 0;
            if (skipped) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(skipped ? (r.pass + " (skipped)").c_str() : r.pass.c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", r.lastMilliseconds);
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", r.averageMilliseconds);
            if (skipped) ImGui::PopStyleColor();
        }
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted("frame");
        ImGui::TableNextColumn();
        ImGui::Text("%.3f", history_.lastFrameMilliseconds());
        ImGui::TableNextColumn();
        ImGui::Text("%.3f", history_.averageFrameMilliseconds());
        ImGui::EndTable();
    }
    if (!skippedPasses_.empty()) {
        double saved = 0.0;
        for (const std::string& pass : skippedPasses_)
            if (auto it = ranMilliseconds_.find(pass); it != ranMilliseconds_.end()) saved += it->second;
        ImGui::TextDisabled("skipped by content: about %.3f GPU ms a frame saved (what those passes took when they last ran)",
                            saved);
    }
    std::vector<float> totals = history_.frameTotals();
    float top = *std::max_element(totals.begin(), totals.end());
    std::string overlay = "frame GPU ms over " + std::to_string(totals.size()) + " frames, max " +
                          std::to_string(top).substr(0, std::to_string(top).find('.') + 3);
    ImGui::PlotLines("##frames", totals.data(), static_cast<int>(totals.size()), 0, overlay.c_str(), 0.0f, top * 1.1f,
                     ImVec2(ImGui::GetContentRegionAvail().x, 60.0f));
}

}  // namespace rmfx::editor
