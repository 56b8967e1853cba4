#pragma once
// An RGBA8 texture the editor draws into (through its framebuffer) or uploads to, and shows with
// ImGui::Image. Needs a current GL context for its whole life.

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace rmfx::editor {

class DisplayTexture {
public:
    DisplayTexture() = default;
    ~DisplayTexture();
    DisplayTexture(const DisplayTexture&) = delete;
    DisplayTexture& operator=(const DisplayTexture&) = delete;

    // (Re)allocates when the size changes; magnified texels stay sharp (nearest) so a viewer can
    // show single texels.
    void resize(glm::ivec2 size);
    // RGBA8 bytes of the whole texture, row 0 at the top (the first row ImGui::Image shows with
    // its default uv).
    void upload(const std::vector<std::uint8_t>& rgba);
    // Binds the framebuffer drawing into the texture and sets the viewport to cover it.
    void bindFramebuffer();

    glm::ivec2 size() const { return size_; }
    void* imguiTexture() const { return reinterpret_cast<void*>(static_cast<std::uintptr_t>(texture_)); }

private:
    void release();
    unsigned texture_ = 0;
    unsigned framebuffer_ = 0;
    glm::ivec2 size_{0};
};

}  // namespace rmfx::editor
