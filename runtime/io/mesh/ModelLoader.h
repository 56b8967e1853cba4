#pragma once
// Loads a model file (OBJ, 3DS, FBX, glTF, … whatever Assimp reads) into one Mesh.

#include <filesystem>

#include "core/Result.h"
#include "model/Mesh.h"

namespace rmfx {

// All meshes of the file, transformed into world space by their nodes and merged into one;
// smooth normals are generated where the file has none, missing texcoords become (0, 0).
// Points and lines are dropped. A file without triangles is an error.
Result<Mesh> loadModel(const std::filesystem::path& path);

}  // namespace rmfx
