#include "editor/TargetBrowser.h"

#include <algorithm>

#include <glm/common.hpp>

#include <epoxy/gl.h>
#include <imgui.h>

namespace rmfx::editor {
namespace {

glm::ivec2 thumbnailExtent(glm::ivec2 size) {
    const float longer = static_cast<float>(std::max(size.x, size.y));
    const float scale = static_cast<float>(thumbnailSize) / std::max(longer, 1.0f);  // small targets grow
    return glm::max(glm::ivec2(glm::vec2(size) * scale + 0.5f), glm::ivec2(1));
}

}  // namespace

void TargetBrowser::setOutput(const std::string& target, DisplayTransform transform) {
    output_ = target;
    outputTransform_ = transform;
}

DisplayTransform TargetBrowser::transformOf(const std::string& target) const {
    return target == output_ ? outputTransform_ : DisplayTransform::Srgb;
}

void TargetBrowser::updateThumbnails(GlExecutor& executor, const Workspace& ws, TextureBlit& blit) {
    written_.clear();
    for (const std::string& pass : executor.passesRun())
        if (const Pass* p = ws.findPass(pass)) written_.insert(ws.passTargetName(*p));
    const FrameHealth* health = executor.frameHealth();
    health_ = health ? targetHealthBadges(*health) : std::map<std::string, TargetHealthBadge>{};
    std::vector<std::string> names = executor.targetNames();
    std::vector<Thumbnail> updated;
    for (const std::string& name : names) {
        auto old = std::find_if(thumbnails_.begin(), thumbnails_.end(), [&](const Thumbnail& t) { return t.target == name; });
        Thumbnail t{name, old != thumbnails_.end() ? std::move(old->texture) : std::make_unique<DisplayTexture>()};
        t.texture->resize(thumbnailExtent(executor.targetSize(name)));
        if (unsigned texture = executor.targetTexture(name)) {
            t.texture->bindFramebuffer();
            blit.drawFiltered(texture, 0.0f, transformOf(name));
        }
        updated.push_back(std::move(t));
    }
    thumbnails_ = std::move(updated);
    updateVolumes(executor, ws, blit);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void TargetBrowser::updateVolumes(const GlExecutor& executor, const Workspace& ws, TextureBlit& blit) {
    std::vector<VolumeThumbnail> updated;
    for (const Texture& t : ws.textures) {
        if (t.kind != TextureKind::Volume) continue;
        const unsigned object = executor.textureObject(t.name);
        if (!object) continue;
        auto old = std::find_if(volumes_.begin(), volumes_.end(), [&](const VolumeThumbnail& v) { return v.texture == t.name; });
        VolumeThumbnail v{t.name, old != volumes_.end() ? std::move(old->image) : std::make_unique<DisplayTexture>(),
                          glm::ivec3(0), old != volumes_.end() ? old->slice : 0.5f};
        glGetTextureLevelParameteriv(object, 0, GL_TEXTURE_WIDTH, &v.size.x);
        glGetTextureLevelParameteriv(object, 0, GL_TEXTURE_HEIGHT, &v.size.y);
        glGetTextureLevelParameteriv(object, 0, GL_TEXTURE_DEPTH, &v.size.z);
        v.image->resize(thumbnailExtent(glm::ivec2(v.size)));
        v.image->bindFramebuffer();
        blit.drawSlice(object, v.slice, DisplayTransform::Srgb);
        updated.push_back(std::move(v));
    }
    volumes_ = std::move(updated);
}

void TargetBrowser::drawVolumes() {
    if (volumes_.empty()) return;
    ImGui::Separator();
    ImGui::TextDisabled("Volume textures (one slice)");
    for (VolumeThumbnail& v : volumes_) {
        ImGui::PushID(v.texture.c_str());
        ImGui::BeginGroup();
        const glm::ivec2 size = v.image->size();
        // GL rows bottom-up, as for targets: flipped in v.
        ImGui::Image(v.image->imguiTexture(), ImVec2(static_cast<float>(size.x), static_cast<float>(size.y)), ImVec2(0, 1),
                     ImVec2(1, 0));
        const int slices = std::max(v.size.z, 1);
        const int shown = std::clamp(static_cast<int>(v.slice * static_cast<float>(slices)), 0, slices - 1);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("%s: %dx%dx%d volume texture; slice %d of %d", v.texture.c_str(), v.size.x, v.size.y, v.size.z,
                              shown + 1, slices);
        ImGui::TextUnformatted(v.texture.c_str());
        int chosen = shown;
        ImGui::SetNextItemWidth(static_cast<float>(thumbnailSize));
        if (ImGui::SliderInt("##slice", &chosen, 0, slices - 1, "slice %d"))
            v.slice = (static_cast<float>(chosen) + 0.5f) / static_cast<float>(slices);  // its texel centre
        ImGui::EndGroup();
        ImGui::PopID();
        ImGui::SameLine();
    }
    ImGui::NewLine();
}

void TargetBrowser::draw(const GlExecutor& executor) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const float cell = static_cast<float>(thumbnailSize) + 2.0f * style.FramePadding.x;
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    for (size_t i = 0; i < thumbnails_.size(); ++i) {
        const Thumbnail& t = thumbnails_[i];
        ImGui::PushID(t.target.c_str());
        ImGui::BeginGroup();
        glm::ivec2 size = t.texture->size();
        // Target textures hold GL rows bottom-up: the image is flipped in v.
        ImVec2 shown(static_cast<float>(size.x), static_cast<float>(size.y));
        float padX = (static_cast<float>(thumbnailSize) - shown.x) * 0.5f;
        ImGui::SetCursorPosX(ImGui::GetCursorPosX() + padX);
        const bool written = written_.count(t.target) > 0;
        // Targets the frame did not write are dimmed: they hold what an earlier frame left.
        const ImVec4 tint = written ? ImVec4(1, 1, 1, 1) : ImVec4(0.35f, 0.35f, 0.35f, 1.0f);
        if (ImGui::ImageButton(t.texture->imguiTexture(), shown, ImVec2(0, 1), ImVec2(1, 0), -1, ImVec4(0, 0, 0, 0), tint))
            open(t.target);
        ImGui::SetCursorPosX(ImGui::GetCursorPosX() - padX);
        const auto badge = health_.find(t.target);
        const TargetHealthBadge* healthOf = badge == health_.end() ? nullptr : &badge->second;
        if (ImGui::IsItemHovered()) {
            glm::ivec2 full = executor.targetSize(t.target);
            ImGui::SetTooltip("%s: %dx%d %s%s; click to view%s%s", t.target.c_str(), full.x, full.y,
                              targetFormatName(executor.targetFormat(t.target)),
                              written ? "" : "; not written by the last frame (its passes are switched off)",
                              healthOf ? "\n" : "", healthOf ? healthOf->details.c_str() : "");
        }
        ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + cell);
        if (written) ImGui::TextUnformatted(t.target.c_str());
        else ImGui::TextDisabled("%s (off)", t.target.c_str());
        if (healthOf && !healthOf->text.empty()) {
            const ImVec4 colour = healthOf->error ? ImVec4(1.0f, 0.3f, 0.3f, 1.0f) : ImVec4(1.0f, 0.75f, 0.2f, 1.0f);
            ImGui::TextColored(colour, "%s", healthOf->text.c_str());
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", healthOf->details.c_str());
        } else if (healthOf) {
            ImGui::TextDisabled("%s", healthOf->inspected ? "ok" : "not inspected");
        }
        ImGui::PopTextWrapPos();
        ImGui::EndGroup();
        ImGui::PopID();
        float nextRight = ImGui::GetItemRectMax().x + style.ItemSpacing.x + cell;
        if (i + 1 < thumbnails_.size() && nextRight < right) ImGui::SameLine();
    }
    drawVolumes();
}

void TargetBrowser::open(const std::string& target) {
    focus_ = target;
    for (const auto& v : viewers_)
        if (v->target() == target) return;
    viewers_.push_back(std::make_unique<TargetViewer>(target, transformOf(target)));
}

void TargetBrowser::drawViewers(const GlExecutor& executor, glm::vec2 firstPosition, glm::vec2 firstSize) {
    std::vector<std::string> names = executor.targetNames();
    for (size_t i = 0; i < viewers_.size();) {
        TargetViewer& v = *viewers_[i];
        bool exists = std::find(names.begin(), names.end(), v.target()) != names.end();
        if (exists && v.target() == focus_) ImGui::SetNextWindowFocus();
        glm::vec2 position = firstPosition + glm::vec2(24.0f) * static_cast<float>(i);
        if (!exists || !v.draw(executor, position, firstSize, written_.count(v.target()) > 0)) viewers_.erase(viewers_.begin() + static_cast<long>(i));
        else ++i;
    }
    focus_.clear();
}

}  // namespace rmfx::editor
