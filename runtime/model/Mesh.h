#pragma once
// Triangle geometry on the CPU, ready for upload. Attribute locations used by every program:
// 0 position, 1 normal, 2 texcoord.

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace rmfx {

struct Mesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;    // same count as positions, unit length
    std::vector<glm::vec2> texcoords;  // same count as positions
    std::vector<uint32_t> indices;     // triangles, counter-clockwise seen from outside

    size_t vertexCount() const { return positions.size(); }
    size_t triangleCount() const { return indices.size() / 3; }
};

enum class BuiltinMesh { FullscreenTriangle, Cube, Sphere, Plane, Teapot, Quad, Torus };

}  // namespace rmfx
