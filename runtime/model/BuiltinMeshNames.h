#pragma once
// The names a workspace gives rmfx's built-in meshes (<draw mesh="teapot">): what the parser reads
// and messages print, apart from the code that makes the meshes (io/mesh/BuiltinMeshes).

#include <optional>
#include <string>
#include <string_view>

#include "model/Mesh.h"

namespace rmfx {

// "fullscreen", "cube", "sphere", "plane", "teapot", "quad", "torus" (case-insensitive).
std::optional<BuiltinMesh> builtinMeshFromName(std::string_view name);
const char* builtinMeshName(BuiltinMesh which);
// Every name above, for messages: "fullscreen, cube, …, torus".
std::string builtinMeshNameList();

}  // namespace rmfx
