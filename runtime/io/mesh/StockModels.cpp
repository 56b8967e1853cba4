#include "io/mesh/StockModels.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <string>

#include <glm/common.hpp>

#include "io/mesh/BuiltinMeshes.h"

namespace rmfx {

namespace {

// StockModels.h says where each was measured.
constexpr std::array kStockModels = {
    // Sphere.3ds: u = 0 at +z, 0.25 at -x, 0.5 at -z, 0.75 at +x; v = 0 at +y.
    StockModel{"sphere", BuiltinMesh::Sphere, {-52.0006f, -52.0006f, -52.0006f}, {52.0026f, 52.0026f, 52.0026f}, true},
    StockModel{"teapot", BuiltinMesh::Teapot, {-74.8518f, -38.2332f, -49.8711f}, {85.9982f, 40.5168f, 50.1289f}},
    StockModel{"torus", BuiltinMesh::Torus, {-53.6954f, -39.8554f, -57.9029f}, {54.0770f, 39.8558f, 43.6192f}},
    StockModel{"screenalignedquad", BuiltinMesh::Quad, {-0.999f, -0.999f, 0.001f}, {1.001f, 1.001f, 0.001f}},
    StockModel{"terrain", BuiltinMesh::Plane, {-450.0f, -82.19f, -392.24f}, {450.0f, 83.33f, 507.76f}},
};

}  // namespace

std::optional<StockModel> findStockModel(std::string_view stem) {
    std::string lower(stem);
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const StockModel& model : kStockModels)
        if (model.stem == lower) return model;
    return std::nullopt;
}

MeshPlacement stockModelPlacement(const StockModel& model) {
    const Mesh mesh = makeMesh(model.standIn);
    glm::vec3 low(0.0f), high(0.0f);
    if (!mesh.positions.empty()) low = high = mesh.positions.front();
    for (const glm::vec3& p : mesh.positions) {
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
    const glm::vec3 size = high - low, stockSize = model.boundsMax - model.boundsMin;
    const float largest = std::max({size.x, size.y, size.z});
    MeshPlacement placement;
    placement.scale = largest > 0.0f ? std::max({stockSize.x, stockSize.y, stockSize.z}) / largest : 1.0f;
    placement.offset = 0.5f * (model.boundsMin + model.boundsMax) - placement.scale * 0.5f * (low + high);
    return placement;
}

}  // namespace rmfx
