#include "editor/DisplayTexture.h"

#include <epoxy/gl.h>
#include <glm/common.hpp>

namespace rmfx::editor {

DisplayTexture::~DisplayTexture() { release(); }

void DisplayTexture::release() {
    if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
    if (texture_) glDeleteTextures(1, &texture_);
    framebuffer_ = texture_ = 0;
    size_ = glm::ivec2(0);
}

void DisplayTexture::resize(glm::ivec2 size) {
    if (size == size_ && texture_) return;
    release();
    size_ = glm::max(size, glm::ivec2(1));
    glCreateTextures(GL_TEXTURE_2D, 1, &texture_);
    glTextureStorage2D(texture_, 1, GL_RGBA8, size_.x, size_.y);
    glTextureParameteri(texture_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(texture_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(texture_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void DisplayTexture::upload(const std::vector<std::uint8_t>& rgba) {
    if (!texture_ || rgba.size() != static_cast<size_t>(size_.x) * size_.y * 4) return;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glTextureSubImage2D(texture_, 0, 0, 0, size_.x, size_.y, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
}

void DisplayTexture::bindFramebuffer() {
    if (!framebuffer_) {
        glCreateFramebuffers(1, &framebuffer_);
        glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0, texture_, 0);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, size_.x, size_.y);
}

}  // namespace rmfx::editor
