#include "model/BuiltinMeshNames.h"

#include <algorithm>
#include <array>
#include <cctype>

namespace rmfx {

namespace {

constexpr std::array<BuiltinMesh, 7> kAllBuiltins{BuiltinMesh::FullscreenTriangle, BuiltinMesh::Cube, BuiltinMesh::Sphere,
                                                  BuiltinMesh::Plane, BuiltinMesh::Teapot, BuiltinMesh::Quad,
                                                  BuiltinMesh::Torus};

bool equalsIgnoringCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

}  // namespace

std::optional<BuiltinMesh> builtinMeshFromName(std::string_view name) {
    for (BuiltinMesh m : kAllBuiltins)
        if (equalsIgnoringCase(name, builtinMeshName(m))) return m;
    return std::nullopt;
}

std::string builtinMeshNameList() {
    std::string list;
    for (BuiltinMesh m : kAllBuiltins) list += (list.empty() ? "" : ", ") + std::string(builtinMeshName(m));
    return list;
}

const char* builtinMeshName(BuiltinMesh which) {
    switch (which) {
        case BuiltinMesh::FullscreenTriangle: return "fullscreen";
        case BuiltinMesh::Cube: return "cube";
        case BuiltinMesh::Sphere: return "sphere";
        case BuiltinMesh::Plane: return "plane";
        case BuiltinMesh::Teapot: return "teapot";
        case BuiltinMesh::Quad: return "quad";
        case BuiltinMesh::Torus: return "torus";
    }
    return "?";
}

}  // namespace rmfx
