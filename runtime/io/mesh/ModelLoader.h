#pragma once
// Loads a model file (OBJ, 3DS, FBX, glTF, … whatever Assimp reads) into one Mesh.

#include <filesystem>

#include "core/Result.h"
#include "model/Mesh.h"

namespace rmfx {

// All meshes of the file, transformed into world space by their nodes and merged into one;
// smooth normals are generated where the file has none, missing texcoords become (0, 0).
// Points and lines are dropped. A file without triangles is an error.
//
// Coordinates, texture coordinates and winding are the file's own, as RenderMonkey drew them:
// what Assimp's importers convert is undone. Its 3DS importer rotates the scene from Z up to Y up
// ((x, y, z) → (x, z, −y), on the root node); its DirectX .x importer mirrors z, flips v and
// reverses the winding (Direct3D's left-handed conventions to OpenGL's).
Result<Mesh> loadModel(const std::filesystem::path& path);

}  // namespace rmfx
