#include "gl/GlMeshCache.h"

#include "io/mesh/BuiltinMeshes.h"
#include "io/mesh/ModelLoader.h"

namespace rmfx {
namespace {

Diagnostics drawError(const DrawCall& draw, const std::string& message) {
    return {{Diagnostic::Severity::Error, draw.where, "<draw>", message}};
}

}  // namespace

Result<const GlMesh*> GlMeshCache::meshFor(const Workspace& ws, const DrawCall& draw) {
    std::string key = draw.mesh ? std::string("builtin:") + builtinMeshName(*draw.mesh) : "file:" + draw.file;
    if (draw.mesh && (draw.meshScale != 1.0f || draw.meshOffset != glm::vec3(0.0f)))
        key += "@" + std::to_string(draw.meshScale) + "+" + std::to_string(draw.meshOffset.x) + "," +
               std::to_string(draw.meshOffset.y) + "," + std::to_string(draw.meshOffset.z);
    if (draw.mirrorU) key += "~u";
    if (auto it = meshes_.find(key); it != meshes_.end()) return static_cast<const GlMesh*>(it->second.get());
    Mesh mesh;
    if (draw.mesh) {
        mesh = *makeDrawnMesh(draw);
        // Built-in meshes put t = 0 at the bottom of an image; Direct3D's v = 0 is its top row,
        // where model files made for Direct3D (RenderMonkey's stock .3ds files) have it.
        if (rowsTopFirst(ws.textureSpace))
            for (glm::vec2& t : mesh.texcoords) t.y = 1.0f - t.y;
    } else {
        auto loaded = loadModel(ws.folder / draw.file);
        if (!loaded) return Result<const GlMesh*>::failure(drawError(draw, loaded.error()));
        mesh = std::move(*loaded);
    }
    auto& slot = meshes_[key];
    slot = std::make_unique<GlMesh>(mesh);
    return static_cast<const GlMesh*>(slot.get());
}

Result<std::unique_ptr<GlMesh>> GlMeshCache::loadAgain(const Workspace& ws, const std::string& file, const DrawCall& user) {
    auto loaded = loadModel(ws.folder / file);
    if (!loaded) return Result<std::unique_ptr<GlMesh>>::failure(drawError(user, loaded.error()));
    return std::make_unique<GlMesh>(*loaded);
}

void GlMeshCache::replace(const std::string& file, std::unique_ptr<GlMesh> mesh) { meshes_["file:" + file] = std::move(mesh); }

const GlMesh* GlMeshCache::loadedModel(const std::string& file) const {
    auto it = meshes_.find("file:" + file);
    return it == meshes_.end() ? nullptr : it->second.get();
}

}  // namespace rmfx
