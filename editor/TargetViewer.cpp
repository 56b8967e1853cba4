#include "editor/TargetViewer.h"

#include <algorithm>
#include <cmath>

#include <imgui.h>

namespace rmfx::editor {

bool TargetViewer::draw(const GlExecutor& executor, glm::vec2 firstPosition, glm::vec2 firstSize, bool written) {
    const std::string title = target_ + " (render target)";
    ImGui::SetNextWindowPos(ImVec2(firstPosition.x, firstPosition.y), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(firstSize.x, firstSize.y), ImGuiCond_FirstUseEver);
    if (!ImGui::Begin(title.c_str(), &open_)) {  // collapsed: nothing to read
        ImGui::End();
        return open_;
    }
    Result<Image> image = executor.readTarget(target_);
    if (!image) {
        ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.3f, 1.0f), "%s", image.error().c_str());
        ImGui::End();
        return open_;
    }
    const glm::ivec2 size(image->width, image->height);
    texture_.resize(size);
    texture_.upload(displayPixels(*image, decode_, exposureStops_, srgb_ ? DisplayTransform::Srgb : DisplayTransform::None));

    if (!written) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.85f, 0.4f, 1.0f));
        ImGui::TextWrapped("not written by the last frame (its passes are switched off): what an earlier frame left");
        ImGui::PopStyleColor();
    }
    ImGui::Text("%dx%d %s", size.x, size.y, targetFormatName(executor.targetFormat(target_)));
    ImGui::SameLine();
    ImGui::Checkbox("sRGB", &srgb_);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("encode for display with the sRGB curve (off: the values clipped to 0..1)");
    ImGui::SetNextItemWidth(100);
    if (ImGui::BeginCombo("decode as", decodeAsLabel(decode_))) {
        for (int i = 0; i < decodeAsCount; ++i) {
            DecodeAs d = static_cast<DecodeAs>(i);
            if (ImGui::Selectable(decodeAsLabel(d), d == decode_)) decode_ = d;
        }
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(100);
    ImGui::SliderFloat("exposure", &exposureStops_, -16.0f, 16.0f, "%+.1f stops");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("display = decoded value x 2^exposure, then sRGB");

    // Fit the window, but at least 128 pixels on the longer side (a 1x1 target shows as a block).
    ImVec2 avail = ImGui::GetContentRegionAvail();
    avail.y -= ImGui::GetTextLineHeightWithSpacing() * 3.0f;
    const float longer = static_cast<float>(std::max(size.x, size.y));
    float scale = std::min(avail.x / static_cast<float>(size.x), avail.y / static_cast<float>(size.y));
    if (!(scale * longer >= 128.0f)) scale = 128.0f / longer;
    ImVec2 shown(static_cast<float>(size.x) * scale, static_cast<float>(size.y) * scale);
    ImVec2 corner = ImGui::GetCursorScreenPos();
    ImGui::Image(texture_.imguiTexture(), shown);
    if (ImGui::IsItemHovered()) {
        ImVec2 mouse = ImGui::GetIO().MousePos;
        int x = std::clamp(static_cast<int>(std::floor((mouse.x - corner.x) / scale)), 0, size.x - 1);
        int y = std::clamp(static_cast<int>(std::floor((mouse.y - corner.y) / scale)), 0, size.y - 1);
        glm::vec4 stored = texelAt(*image, x, y);
        glm::vec4 decoded = decodeTexel(decode_, stored);
        // GL's texel row counts from the bottom; the picture shows row 0 at the top.
        ImGui::Text("texel %d, %d (GL row %d)", x, y, size.y - 1 - y);
        ImGui::Text("stored  %.6g %.6g %.6g %.6g", stored.r, stored.g, stored.b, stored.a);
        ImGui::Text("decoded %.6g %.6g %.6g %.6g", decoded.r, decoded.g, decoded.b, decoded.a);
    } else {
        ImGui::TextDisabled("hover the picture for the values under the cursor");
    }
    ImGui::End();
    return open_;
}

}  // namespace rmfx::editor
