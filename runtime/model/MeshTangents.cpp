#include "model/MeshTangents.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

namespace rmfx {
namespace {

glm::vec3 anyOrthogonal(glm::vec3 n) {
    glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return glm::normalize(glm::cross(axis, n));
}

}  // namespace

MeshTangents computeTangents(const Mesh& mesh) {
    size_t count = mesh.vertexCount();
    std::vector<glm::vec3> du(count, glm::vec3(0)), dv(count, glm::vec3(0));
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
        if (a >= count || b >= count || c >= count || mesh.texcoords.size() < count) continue;
        glm::vec3 e1 = mesh.positions[b] - mesh.positions[a], e2 = mesh.positions[c] - mesh.positions[a];
        glm::vec2 t1 = mesh.texcoords[b] - mesh.texcoords[a], t2 = mesh.texcoords[c] - mesh.texcoords[a];
        float det = t1.x * t2.y - t2.x * t1.y;
        if (std::abs(det) < 1e-12f) continue;
        float r = 1.0f / det;
        glm::vec3 u = (e1 * t2.y - e2 * t1.y) * r, v = (e2 * t1.x - e1 * t2.x) * r;
        for (uint32_t k : {a, b, c}) {
            du[k] += u;
            dv[k] += v;
        }
    }
    MeshTangents out;
    out.tangents.resize(count);
    out.binormals.resize(count);
    for (size_t i = 0; i < count; ++i) {
        glm::vec3 n = i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0, 0, 1);
        glm::vec3 t = du[i] - n * glm::dot(n, du[i]);
        t = glm::length(t) > 1e-12f ? glm::normalize(t) : anyOrthogonal(n);
        float handedness = glm::dot(glm::cross(n, t), dv[i]) < 0.0f ? -1.0f : 1.0f;
        out.tangents[i] = t;
        out.binormals[i] = glm::cross(n, t) * handedness;
    }
    return out;
}

}  // namespace rmfx
