#include "gl/GlRenderTargets.h"

#include <epoxy/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include "gl/GlErrors.h"
#include "gl/GlFormats.h"

namespace rmfx {
namespace {

// Storage, framebuffers cleared to the initial value; errors at the target that first uses it.
bool allocateResource(GpuResource& r, const std::string& element, const SourceLocation& where, Diagnostics& d) {
    const TargetResource& spec = r.spec;
    auto error = [&](const std::string& message) { d.push_back({Diagnostic::Severity::Error, where, element, message}); };
    int buffers = spec.history ? 2 : 1;
    int levels = spec.mipmaps ? gl::mipLevels(spec.size.x, spec.size.y) : 1;
    if (spec.depth) {
        r.depth = createRenderbuffer();
        glNamedRenderbufferStorage(r.depth.get(), GL_DEPTH_COMPONENT32F, spec.size.x, spec.size.y);
    }
    bool ok = true;
    for (int i = 0; i < buffers; ++i) {
        r.textures[i] = createTexture(GL_TEXTURE_2D);
        const GLuint texture = r.textures[i].get();
        glTextureStorage2D(texture, levels, gl::internalFormat(spec.format), spec.size.x, spec.size.y);
        r.framebuffers[i] = createFramebuffer();
        const GLuint framebuffer = r.framebuffers[i].get();
        glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, texture, 0);
        if (r.depth) glNamedFramebufferRenderbuffer(framebuffer, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, r.depth.get());
        GLenum status = glCheckNamedFramebufferStatus(framebuffer, GL_FRAMEBUFFER);
        if (status != GL_FRAMEBUFFER_COMPLETE) {
            error(std::string("framebuffer for format ") + targetFormatName(spec.format) + " " + std::to_string(spec.size.x) +
                  "x" + std::to_string(spec.size.y) + " is incomplete: " + describeFramebufferStatus(status));
            ok = false;
            continue;
        }
        glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, glm::value_ptr(spec.initial));
        // A depth test before the first depth clear compares against the farthest depth, not
        // whatever the new storage holds.
        if (r.depth) {
            const float farthest = 1.0f;
            glDepthMask(GL_TRUE);
            glClearNamedFramebufferfv(framebuffer, GL_DEPTH, 0, &farthest);
        }
    }
    if (std::string e = firstGlError(); !e.empty()) {
        error(e + " while allocating " + std::to_string(spec.size.x) + "x" + std::to_string(spec.size.y) + " " +
              targetFormatName(spec.format));
        ok = false;
    }
    return ok;
}

}  // namespace

Result<void> GlRenderTargets::allocate(const TargetPlan& plan) {
    if (targets_.empty())
        for (const PlannedTarget& p : plan.targets) {
            auto t = std::make_unique<GpuTarget>();
            t->name = p.name;
            t->spec = p.spec;
            t->where = p.where;
            targets_.push_back(std::move(t));
        }
    Diagnostics d;
    std::vector<std::unique_ptr<GpuResource>> fresh;
    for (const TargetResource& spec : plan.resources) {
        auto r = std::make_unique<GpuResource>();
        r->spec = spec;
        const PlannedTarget& first = plan.targets[static_cast<size_t>(spec.targets.front())];
        allocateResource(*r, "<target name=\"" + first.name + "\">", first.where, d);
        fresh.push_back(std::move(r));
    }
    if (hasErrors(d)) return Result<void>::failure(std::move(d));  // the new memory goes; the old stays
    for (auto& t : targets_) t->resource = nullptr;
    for (const auto& r : fresh)
        for (int t : r->spec.targets) targets_[static_cast<size_t>(t)]->resource = r.get();
    resources_ = std::move(fresh);
    return d;
}

GpuTarget* GlRenderTargets::find(const std::string& name) const {
    for (auto& t : targets_)
        if (t->name == name) return t.get();
    return nullptr;
}

void GlRenderTargets::startFrame() {
    for (auto& t : targets_) t->writtenThisFrame = false;
}

void GlRenderTargets::finishFrame() {
    for (auto& t : targets_)
        if (t->resource && t->resource->spec.history && t->writtenThisFrame) t->resource->front = 1 - t->resource->front;
}

}  // namespace rmfx
