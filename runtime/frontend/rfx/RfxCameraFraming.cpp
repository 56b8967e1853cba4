#include "frontend/rfx/RfxCameraFraming.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "io/mesh/BuiltinMeshes.h"
#include "io/mesh/ModelLoader.h"

namespace rmfx {

void frameDrawnModels(Workspace& ws) {
    if (!ws.camera.where.file.empty()) return;  // an RmCamera placed it
    glm::dvec3 low(std::numeric_limits<double>::infinity()), high(-std::numeric_limits<double>::infinity());
    std::vector<Mesh> meshes;
    for (const Pass& pass : ws.passes) {
        if (pass.draw.mesh) {
            if (*pass.draw.mesh == BuiltinMesh::Quad || *pass.draw.mesh == BuiltinMesh::FullscreenTriangle) continue;
            meshes.push_back(makeMesh(*pass.draw.mesh));
        } else if (!pass.draw.file.empty()) {
            if (auto loaded = loadModel(ws.folder / pass.draw.file)) meshes.push_back(std::move(*loaded));
        }
    }
    for (const Mesh& mesh : meshes)
        for (const glm::vec3& p : mesh.positions) {
            low = glm::min(low, glm::dvec3(p));
            high = glm::max(high, glm::dvec3(p));
        }
    if (meshes.empty() || !(low.x <= high.x)) return;
    const glm::dvec3 centre = (low + high) * 0.5;
    double radius = 0.0;
    for (const Mesh& mesh : meshes)
        for (const glm::vec3& p : mesh.positions) radius = std::max(radius, glm::length(glm::dvec3(p) - centre));
    if (!(radius > 0.0) || !std::isfinite(radius)) return;
    const double halfFov = ws.camera.fovYDegrees * 0.5 * 3.14159265358979323846 / 180.0;
    const double distance = radius / std::sin(halfFov) * 1.05;
    ws.camera.target = glm::vec3(centre);
    ws.camera.distance = static_cast<float>(distance);
    ws.camera.nearPlane = static_cast<float>(std::max((distance - radius) * 0.5, distance * 1e-3));
    ws.camera.farPlane = static_cast<float>((distance + radius) * 2.0);
}

}  // namespace rmfx
