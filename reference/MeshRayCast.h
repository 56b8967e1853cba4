#pragma once
// What a rasteriser with a depth test and no culling shows at each pixel centre of a triangle mesh,
// found in double by casting the pixel's ray through inverse(projection · view · model) into object
// space and keeping the nearest triangle hit: the independent reference for effects that draw
// models (RenderMonkey imports), without any of the GL pipeline's code.

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "model/Mesh.h"

namespace rmfx::test {

struct SurfaceHit {
    glm::dvec3 position;  // object space
    glm::dvec3 normal;    // the vertex normals interpolated (not normalised), object space
    glm::dvec2 texcoord;
    double depth = 0.0;   // along the ray, 0 at the near plane and 1 at the far plane
    uint32_t triangle = 0;
};

class MeshRayCast {
public:
    MeshRayCast(const Mesh& mesh, const glm::dmat4& model, const glm::dmat4& view, const glm::dmat4& projection,
                glm::ivec2 size);

    // The nearest surface under the window point (x, y), y from the bottom (a pixel centre is
    // (i + 0.5, j + 0.5)); none when the ray misses or hits only beyond the clip planes.
    std::optional<SurfaceHit> at(double x, double y) const;

    // Where the rasteriser compared with shades pixel (i, j), j from the bottom: (i, j) plus
    // `pixelCentre`, (0.5, 0.5) by default (OpenGL, Direct3D 10). Direct3D 9 shades at whole-number
    // window coordinates counted down from the top: (0, 1) from the pixel's bottom-left corner.
    void setPixelCentre(glm::dvec2 pixelCentre) { pixelCentre_ = pixelCentre; }
    glm::dvec2 centre(int i, int j) const { return glm::dvec2(i, j) + pixelCentre_; }

    // Pixel (i, j) can be compared with a rasteriser's: the rays through its centre() and four points
    // 0.35 px from it diagonally all miss, or all hit at depths within `depthSpread` times the
    // centre's depth of it.
    // Elsewhere an edge, a silhouette or an occluding contour crosses the pixel, and which surface a
    // rasteriser picks there (fill rules, float rounding) is not the maths under test.
    bool settled(int i, int j, double depthSpread = 0.02) const;

    glm::ivec2 size() const { return size_; }

private:
    struct Triangle {
        glm::dvec3 a, b, c;
    };
    const Mesh& mesh_;
    glm::ivec2 size_;
    glm::dvec2 pixelCentre_{0.5, 0.5};
    glm::dmat4 windowToObject_;  // from (ndc x, ndc y, ndc z, 1)
    std::vector<Triangle> triangles_;
    std::vector<std::vector<uint32_t>> bins_;  // triangles whose window bounding box covers each pixel
    std::vector<uint32_t> everywhere_;         // triangles reaching behind the eye: tried for every pixel
};

}  // namespace rmfx::test
