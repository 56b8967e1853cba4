#include "gl/GlTextureCache.h"

#include <algorithm>

#include <epoxy/gl.h>

#include "gl/GlErrors.h"
#include "gl/GlTexture.h"

namespace rmfx {
namespace {

// A texture of the same target, size, levels, format and swizzle, its contents copied on the GPU;
// empty when `source` is not a 2D or cube texture or the copy raised a GL error.
TextureHandle copyTexture(GLuint source) {
    drainGlErrors();
    GLint target = 0, levels = 0, width = 0, height = 0, depth = 1, internal = 0;
    GLint swizzle[4] = {GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA};
    glGetTextureParameteriv(source, GL_TEXTURE_TARGET, &target);
    glGetTextureParameteriv(source, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
    glGetTextureParameteriv(source, GL_TEXTURE_SWIZZLE_RGBA, swizzle);
    glGetTextureLevelParameteriv(source, 0, GL_TEXTURE_WIDTH, &width);
    glGetTextureLevelParameteriv(source, 0, GL_TEXTURE_HEIGHT, &height);
    glGetTextureLevelParameteriv(source, 0, GL_TEXTURE_INTERNAL_FORMAT, &internal);
    if (target == GL_TEXTURE_3D) glGetTextureLevelParameteriv(source, 0, GL_TEXTURE_DEPTH, &depth);
    if ((target != GL_TEXTURE_2D && target != GL_TEXTURE_CUBE_MAP && target != GL_TEXTURE_3D) || levels < 1 || width < 1 ||
        height < 1 || depth < 1)
        return {};
    TextureHandle copy = createTexture(static_cast<GLenum>(target));
    if (target == GL_TEXTURE_3D)
        glTextureStorage3D(copy.get(), levels, static_cast<GLenum>(internal), width, height, depth);
    else
        glTextureStorage2D(copy.get(), levels, static_cast<GLenum>(internal), width, height);
    glTextureParameteriv(copy.get(), GL_TEXTURE_SWIZZLE_RGBA, swizzle);
    for (GLint level = 0; level < levels; ++level)
        glCopyImageSubData(source, static_cast<GLenum>(target), level, 0, 0, 0, copy.get(), static_cast<GLenum>(target),
                           level, 0, 0, 0, std::max(1, width >> level), std::max(1, height >> level),
                           target == GL_TEXTURE_CUBE_MAP ? 6 : std::max(1, depth >> level));
    if (!drainGlErrors().empty()) return {};
    return copy;
}

}  // namespace

Result<void> GlTextureCache::load(const Workspace& ws, const std::set<std::string>& sampled, const TextureReuse& reuse) {
    Diagnostics d;
    for (const Texture& t : ws.textures) {
        if (!sampled.count(t.name)) continue;
        if (copyFrom(ws, t, reuse)) continue;
        auto loaded = loadGlTexture(ws, t);
        if (!loaded) {
            d.push_back({Diagnostic::Severity::Error, t.where, "", loaded.error()});
            continue;
        }
        textures_[t.name] = TextureHandle(loaded->name);
    }
    return d;
}

bool GlTextureCache::copyFrom(const Workspace& ws, const Texture& t, const TextureReuse& reuse) {
    if (!reuse.ws || !reuse.cache || std::find(reuse.names.begin(), reuse.names.end(), t.name) == reuse.names.end())
        return false;
    const Texture* old = reuse.ws->findTexture(t.name);
    auto it = reuse.cache->textures_.find(t.name);
    if (!old || it == reuse.cache->textures_.end() || old->kind != t.kind || old->layout != t.layout ||
        old->colorSpace != t.colorSpace || old->mipmaps != t.mipmaps || old->faceSize != t.faceSize ||
        old->files.size() != t.files.size() || old->supplied != t.supplied)
        return false;
    for (size_t i = 0; i < t.files.size(); ++i)
        if ((reuse.ws->folder / old->files[i]).lexically_normal() != (ws.folder / t.files[i]).lexically_normal())
            return false;
    TextureHandle copy = copyTexture(it->second.get());
    if (!copy) return false;
    textures_[t.name] = std::move(copy);
    return true;
}

Result<void> GlTextureCache::reload(const Workspace& ws, const Texture& texture) {
    auto fail = [&](const std::string& message) {
        return Result<void>::failure({{Diagnostic::Severity::Error, texture.where, "", message}});
    };
    drainGlErrors();
    auto loaded = loadGlTexture(ws, texture);
    if (!loaded) return fail(loaded.error());
    TextureHandle fresh(loaded->name);
    if (std::string e = firstGlError(); !e.empty()) return fail(e + " while uploading texture '" + texture.name + "'");
    textures_[texture.name] = std::move(fresh);
    return {};
}

unsigned GlTextureCache::object(const std::string& name) const {
    auto it = textures_.find(name);
    return it == textures_.end() ? 0 : it->second.get();
}

}  // namespace rmfx
