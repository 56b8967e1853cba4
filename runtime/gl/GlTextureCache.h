#pragma once
// The workspace textures a frame samples, as GL textures by name. Needs a current GL context.

#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/Result.h"
#include "gl/GlHandles.h"
#include "model/Workspace.h"

namespace rmfx {

class GlTextureCache;

// Textures a new build may copy from the previous one (hot reload of the workspace file): those
// named whose files the caller knows did not change.
struct TextureReuse {
    const Workspace* ws = nullptr;        // the previous build's
    const GlTextureCache* cache = nullptr;
    std::vector<std::string> names;
};

class GlTextureCache {
public:
    // Loads the textures named in `sampled`. One `reuse` offers with the same declaration
    // (files, layout, colour space, mipmaps) is copied on the GPU instead of read and decoded again.
    // Errors name each texture that failed; the others are loaded.
    Result<void> load(const Workspace& ws, const std::set<std::string>& sampled, const TextureReuse& reuse = {});
    // Reads a loaded texture's files again and replaces it; on error the old one stays.
    Result<void> reload(const Workspace& ws, const Texture& texture);

    bool holds(const std::string& name) const { return textures_.count(name) != 0; }
    unsigned object(const std::string& name) const;  // 0 when not loaded

private:
    bool copyFrom(const Workspace& ws, const Texture& t, const TextureReuse& reuse);

    std::map<std::string, TextureHandle> textures_;
};

}  // namespace rmfx
