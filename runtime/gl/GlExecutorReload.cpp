// Hot reload (gl/GlExecutor.h): each change is built completely before anything of the running
// build is touched.

#include <algorithm>

#include <epoxy/gl.h>

#include "gl/GlErrors.h"
#include "gl/GlExecutorImpl.h"

namespace rmfx {
namespace {

Diagnostic workspaceError(const Workspace& ws, const std::string& element, const std::string& message) {
    return {Diagnostic::Severity::Error, {ws.path.string(), 0}, element, message};
}

}  // namespace

Result<void> GlExecutor::recompilePasses(const std::vector<std::string>& passNames) {
    Diagnostics d;
    Impl& s = *impl_;
    drainGlErrors();
    std::vector<std::string> names;
    for (const std::string& name : passNames)
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    std::vector<std::pair<GpuPass*, std::unique_ptr<GpuPass>>> rebuilt;
    for (const std::string& name : names) {
        GpuPass* old = s.findPass(name);
        if (!old && s.ws.findPass(name)) continue;  // culled: nothing compiled to replace
        if (!old) {
            d.push_back(workspaceError(s.ws, "<pass name=\"" + name + "\">", "no enabled pass named '" + name + "' to recompile"));
            continue;
        }
        auto fresh = std::make_unique<GpuPass>();
        fresh->pass = old->pass;
        fresh->index = old->index;
        fresh->target = old->target;
        fresh->mesh = old->mesh;
        fresh->model = old->model;
        auto program = buildPassProgram(s.ws, *fresh->pass, s.plan.prelude);
        d.insert(d.end(), program.diagnostics().begin(), program.diagnostics().end());
        if (!program) continue;
        s.useProgram(*fresh, std::move(*program), d);
        rebuilt.emplace_back(old, std::move(fresh));
    }
    if (hasErrors(d)) return Result<void>::failure(std::move(d));  // the fresh programs go with `rebuilt`
    for (auto& [old, fresh] : rebuilt) {
        s.withoutEffects.erase(old->index);  // built from the old source
        s.readAnew.insert(old->index);
        *old = std::move(*fresh);
    }
    if (!rebuilt.empty()) s.variantReady = false;  // its second programs are decided anew at the next frame
    return d;
}

Result<void> GlExecutor::reloadTexture(const std::string& name) {
    Impl& s = *impl_;
    const Texture* spec = s.ws.findTexture(name);
    if (!spec) return Result<void>::failure({workspaceError(s.ws, "", "no texture named '" + name + "' to reload")});
    if (!s.textures.holds(name)) return {};  // no pass that can run samples it: nothing loaded
    if (auto reloaded = s.textures.reload(s.ws, *spec); !reloaded) return reloaded;
    s.bindTexture(name);
    return {};
}

Result<void> GlExecutor::replaceInputImage(const std::string& name, std::shared_ptr<const Image> image) {
    Impl& s = *impl_;
    const Texture* spec = s.ws.findTexture(name);
    if (!s.ws.findInput(name) || !spec)
        return Result<void>::failure({workspaceError(s.ws, "", "no input named '" + name + "' to give an image")});
    if (!s.plan.options.givenInputs.count(name))
        return Result<void>::failure({workspaceError(s.ws, "<input name=\"" + name + "\">",
                                                     "input '" + name + "' was given no image when the run began")});
    if (!image || image->empty())
        return Result<void>::failure({workspaceError(s.ws, "<input name=\"" + name + "\">", "an empty image for input '" + name + "'")});
    if (!s.textures.holds(name)) return {};  // no pass that can run samples it
    Texture next = *spec;
    next.supplied = std::move(image);
    if (auto replaced = s.textures.reload(s.ws, next); !replaced) return replaced;
    s.bindTexture(name);
    return {};
}

bool GlExecutor::writeInputPixels(const std::string& name, const InputPixels& p) {
    Impl& s = *impl_;
    const Texture* spec = s.ws.findTexture(name);
    if (!s.ws.findInput(name) || !spec || !s.plan.options.givenInputs.count(name) || !s.textures.holds(name)) return false;
    if (spec->kind != TextureKind::Texture2D || spec->mipmaps || spec->colorSpace == ColorSpace::Srgb || !p.data) return false;
    const GLuint texture = s.textures.object(name);
    GLint width = 0, height = 0, internal = 0, levels = 0;
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &width);
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_HEIGHT, &height);
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &internal);
    glGetTextureParameteriv(texture, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
    if (width != p.width || height != p.height || internal != GL_RGBA32F || levels != 1) return false;
    const GLenum type = p.half ? GL_HALF_FLOAT : GL_FLOAT;
    const std::size_t packed = static_cast<std::size_t>(width) * 4 * (p.half ? 2 : 4);
    const auto* bytes = static_cast<const unsigned char*>(p.data);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (rowsTopFirst(s.ws.textureSpace) && p.rowBytes == packed) {
        glTextureSubImage2D(texture, 0, 0, 0, width, height, GL_RGBA, type, bytes);
    } else {
        // OpenGL's row 0 is the bottom one: each row to its place, which costs no copy either.
        for (int y = 0; y < height; ++y) {
            const int row = rowsTopFirst(s.ws.textureSpace) ? y : height - 1 - y;
            glTextureSubImage2D(texture, 0, 0, row, width, 1, GL_RGBA, type, bytes + static_cast<std::size_t>(y) * p.rowBytes);
        }
    }
    return true;
}

Result<void> GlExecutor::reloadModel(const std::string& file) {
    Impl& s = *impl_;
    const GlMesh* old = s.meshes.loadedModel(file);
    const Pass* user = nullptr;
    for (const auto& p : s.passes)
        if (!p->pass->draw.mesh && p->pass->draw.file == file) user = p->pass;
    if (!old || !user) return Result<void>::failure({workspaceError(s.ws, "<draw>", "no pass draws model file '" + file + "'")});
    auto fresh = GlMeshCache::loadAgain(s.ws, file, user->draw);
    if (!fresh) return Result<void>::failure(fresh.takeDiagnostics());
    for (auto& p : s.passes)
        if (p->mesh == old) p->mesh = fresh->get();
    s.meshes.replace(file, std::move(*fresh));
    return {};
}

unsigned GlExecutor::passProgram(const std::string& pass) const {
    const GpuPass* p = impl_->findPass(pass);
    return p ? p->program.get() : 0;
}

unsigned GlExecutor::textureObject(const std::string& name) const { return impl_->textures.object(name); }

}  // namespace rmfx
