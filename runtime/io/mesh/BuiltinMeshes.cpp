#include "io/mesh/BuiltinMeshes.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>

#include <glm/geometric.hpp>

namespace rmfx {

namespace {

// Appends a quad with corners centre ± tangent ± bitangent. cross(tangent, bitangent) must
// point along normal so that the corners run counter-clockwise seen from outside.
void addQuad(Mesh& mesh, glm::vec3 centre, glm::vec3 tangent, glm::vec3 bitangent, glm::vec3 normal) {
    const auto base = static_cast<uint32_t>(mesh.positions.size());
    const std::array<glm::vec2, 4> corners{{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};
    for (glm::vec2 c : corners) {
        mesh.positions.push_back(centre + c.x * tangent + c.y * bitangent);
        mesh.normals.push_back(normal);
        mesh.texcoords.push_back((c + 1.0f) * 0.5f);
    }
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
}

}  // namespace

Mesh makeFullscreenTriangle() {
    Mesh mesh;
    mesh.positions = {{-1, -1, 0}, {3, -1, 0}, {-1, 3, 0}};
    mesh.normals.assign(3, glm::vec3(0, 0, 1));
    mesh.texcoords = {{0, 0}, {2, 0}, {0, 2}};
    mesh.indices = {0, 1, 2};
    return mesh;
}

Mesh makeCube() {
    struct Face {
        glm::vec3 normal, tangent, bitangent;
    };
    const std::array<Face, 6> faces{{
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}},
        {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},
        {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},
        {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
    }};
    Mesh mesh;
    for (const Face& f : faces) addQuad(mesh, f.normal, f.tangent, f.bitangent, f.normal);
    return mesh;
}

Mesh makeSphere(int segments, int rings) {
    segments = std::max(segments, 3);
    rings = std::max(rings, 2);
    const float pi = 3.14159265358979323846f;
    Mesh mesh;
    // Rows from the north pole (y = 1) down; the seam column is duplicated so u runs 0..1.
    // Pole rows keep one vertex per column so that each pole triangle gets its own u.
    for (int r = 0; r <= rings; ++r) {
        const float theta = pi * float(r) / float(rings);
        for (int s = 0; s <= segments; ++s) {
            const float phi = 2.0f * pi * float(s) / float(segments);
            glm::vec3 p(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi));
            if (r == 0 || r == rings) p = glm::vec3(0, r == 0 ? 1 : -1, 0);
            mesh.positions.push_back(p);
            mesh.normals.push_back(p);
            float u = float(s) / float(segments);
            if (r == 0 || r == rings) u = (float(s) + 0.5f) / float(segments);
            mesh.texcoords.emplace_back(u, 1.0f - float(r) / float(rings));
        }
    }
    const auto at = [&](int r, int s) { return static_cast<uint32_t>(r * (segments + 1) + s); };
    for (int r = 0; r < rings; ++r) {
        for (int s = 0; s < segments; ++s) {
            // Going down a ring and then along a segment turns counter-clockwise seen from outside.
            // At a pole the quad collapses to one triangle through that pole's column-s vertex.
            if (r == rings - 1) {
                mesh.indices.insert(mesh.indices.end(), {at(r, s), at(r + 1, s), at(r, s + 1)});
                continue;
            }
            mesh.indices.insert(mesh.indices.end(), {at(r, s), at(r + 1, s), at(r + 1, s + 1)});
            if (r != 0) mesh.indices.insert(mesh.indices.end(), {at(r, s), at(r + 1, s + 1), at(r, s + 1)});
        }
    }
    return mesh;
}

Mesh makePlane() {
    Mesh mesh;
    addQuad(mesh, {0, 0, 0}, {1, 0, 0}, {0, 0, -1}, {0, 1, 0});
    return mesh;
}

Mesh makeQuad() {
    Mesh mesh;
    addQuad(mesh, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
    return mesh;
}

Mesh makeTorus(float majorRadius, float minorRadius, int segments, int sides) {
    segments = std::max(segments, 3);
    sides = std::max(sides, 3);
    const float pi = 3.14159265358979323846f;
    Mesh mesh;
    // u around the y axis, v around the tube; the seams are duplicated so both run 0..1.
    for (int i = 0; i <= segments; ++i) {
        const float u = 2.0f * pi * float(i) / float(segments);
        for (int j = 0; j <= sides; ++j) {
            const float v = 2.0f * pi * float(j) / float(sides);
            const glm::vec3 normal(std::cos(v) * std::sin(u), std::sin(v), std::cos(v) * std::cos(u));
            mesh.positions.push_back(majorRadius * glm::vec3(std::sin(u), 0.0f, std::cos(u)) + minorRadius * normal);
            mesh.normals.push_back(normal);
            mesh.texcoords.emplace_back(float(i) / float(segments), float(j) / float(sides));
        }
    }
    const auto at = [&](int i, int j) { return static_cast<uint32_t>(i * (sides + 1) + j); };
    // d/du × d/dv points out of the tube, so (i, j), (i + 1, j), (i + 1, j + 1) winds counter-clockwise seen from outside.
    for (int i = 0; i < segments; ++i)
        for (int j = 0; j < sides; ++j)
            mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    return mesh;
}

std::optional<Mesh> makeDrawnMesh(const DrawCall& draw) {
    if (!draw.mesh) return std::nullopt;
    Mesh mesh = makeMesh(*draw.mesh);
    for (glm::vec3& p : mesh.positions) p = p * draw.meshScale + draw.meshOffset;
    if (draw.mirrorU)
        for (glm::vec2& t : mesh.texcoords) t.x = 1.0f - t.x;
    return mesh;
}

Mesh makeMesh(BuiltinMesh which) {
    switch (which) {
        case BuiltinMesh::FullscreenTriangle: return makeFullscreenTriangle();
        case BuiltinMesh::Cube: return makeCube();
        case BuiltinMesh::Sphere: return makeSphere();
        case BuiltinMesh::Plane: return makePlane();
        case BuiltinMesh::Teapot: return makeTeapot();
        case BuiltinMesh::Quad: return makeQuad();
        case BuiltinMesh::Torus: return makeTorus();
    }
    return {};
}

}  // namespace rmfx
