#pragma once
// The meshes passes draw, each built-in mesh and model file uploaded once and shared by the
// passes that draw it. Needs a current GL context.

#include <map>
#include <memory>
#include <string>

#include "core/Result.h"
#include "gl/GlMesh.h"
#include "model/Workspace.h"

namespace rmfx {

class GlMeshCache {
public:
    // The mesh of a pass's <draw>, loaded on first use; an error at the <draw> when its file fails.
    Result<const GlMesh*> meshFor(const Workspace& ws, const DrawCall& draw);
    // Reads a model file (as a <draw file="…"> names it) again, into a mesh of its own: replace()
    // puts it in once the passes drawing the old one draw it. Errors are placed at `user`'s <draw>.
    static Result<std::unique_ptr<GlMesh>> loadAgain(const Workspace& ws, const std::string& file, const DrawCall& user);
    void replace(const std::string& file, std::unique_ptr<GlMesh> mesh);
    const GlMesh* loadedModel(const std::string& file) const;  // null when no pass draws it

private:
    std::map<std::string, std::unique_ptr<GlMesh>> meshes_;  // "builtin:NAME" or "file:PATH"
};

}  // namespace rmfx
