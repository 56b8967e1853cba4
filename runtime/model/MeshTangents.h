#pragma once
// Per-vertex tangents and binormals from a mesh's texture coordinates, for vertex streams that ask
// for them (RenderMonkey's TANGENT / BINORMAL usages).

#include <vector>

#include <glm/vec3.hpp>

#include "model/Mesh.h"

namespace rmfx {

struct MeshTangents {
    std::vector<glm::vec3> tangents;   // unit, along +u, orthogonal to the normal
    std::vector<glm::vec3> binormals;  // unit, along +v: cross(normal, tangent) signed by the UV winding
};

// Sums each triangle's dP/du and dP/dv into its vertices, then orthonormalises against the
// normal. A vertex whose triangles have degenerate UVs gets any unit vector orthogonal to its normal.
MeshTangents computeTangents(const Mesh& mesh);

}  // namespace rmfx
