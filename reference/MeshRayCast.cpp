#include "reference/MeshRayCast.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

namespace rmfx::test {

MeshRayCast::MeshRayCast(const Mesh& mesh, const glm::dmat4& model, const glm::dmat4& view,
                         const glm::dmat4& projection, glm::ivec2 size)
    : mesh_(mesh), size_(size), bins_(size_t(std::max(size.x, 0)) * std::max(size.y, 0)) {
    const glm::dmat4 objectToClip = projection * view * model;
    windowToObject_ = glm::inverse(objectToClip);
    const size_t count = mesh.triangleCount();
    triangles_.reserve(count);
    for (size_t t = 0; t < count; ++t) {
        glm::dvec3 v[3];
        double minX = 1e300, minY = 1e300, maxX = -1e300, maxY = -1e300;
        bool behindEye = false;
        for (int k = 0; k < 3; ++k) {
            v[k] = glm::dvec3(mesh.positions[mesh.indices[3 * t + k]]);
            glm::dvec4 clip = objectToClip * glm::dvec4(v[k], 1.0);
            if (!(clip.w > 1e-12)) {
                behindEye = true;
                continue;
            }
            double x = (clip.x / clip.w * 0.5 + 0.5) * size.x, y = (clip.y / clip.w * 0.5 + 0.5) * size.y;
            minX = std::min(minX, x), maxX = std::max(maxX, x);
            minY = std::min(minY, y), maxY = std::max(maxY, y);
        }
        triangles_.push_back({v[0], v[1], v[2]});
        const auto index = static_cast<uint32_t>(t);
        if (behindEye) {
            everywhere_.push_back(index);
            continue;
        }
        // One pixel of margin: a query anywhere within half a pixel of a centre uses that pixel's bin.
        int x0 = std::max(0, static_cast<int>(std::floor(minX)) - 1);
        int x1 = std::min(size.x - 1, static_cast<int>(std::ceil(maxX)) + 1);
        int y0 = std::max(0, static_cast<int>(std::floor(minY)) - 1);
        int y1 = std::min(size.y - 1, static_cast<int>(std::ceil(maxY)) + 1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) bins_[size_t(y) * size.x + x].push_back(index);
    }
}

std::optional<SurfaceHit> MeshRayCast::at(double x, double y) const {
    if (size_.x <= 0 || size_.y <= 0) return std::nullopt;
    glm::dvec2 ndc(x / size_.x * 2.0 - 1.0, y / size_.y * 2.0 - 1.0);
    glm::dvec4 nearPoint = windowToObject_ * glm::dvec4(ndc, -1.0, 1.0);
    glm::dvec4 farPoint = windowToObject_ * glm::dvec4(ndc, 1.0, 1.0);
    const glm::dvec3 origin = glm::dvec3(nearPoint) / nearPoint.w;
    const glm::dvec3 direction = glm::dvec3(farPoint) / farPoint.w - origin;  // t in [0, 1]: near to far

    std::optional<SurfaceHit> best;
    auto tryTriangle = [&](uint32_t t) {
        // Möller–Trumbore; a hair of slack on the edges so that a ray through a shared edge finds a triangle.
        const Triangle& tri = triangles_[t];
        const glm::dvec3 e1 = tri.b - tri.a, e2 = tri.c - tri.a;
        const glm::dvec3 p = glm::cross(direction, e2);
        const double det = glm::dot(e1, p);
        if (std::abs(det) < 1e-300) return;
        const double inv = 1.0 / det;
        const glm::dvec3 s = origin - tri.a;
        const double u = glm::dot(s, p) * inv;
        if (u < -1e-9 || u > 1.0 + 1e-9) return;
        const glm::dvec3 q = glm::cross(s, e1);
        const double v = glm::dot(direction, q) * inv;
        if (v < -1e-9 || u + v > 1.0 + 1e-9) return;
        const double depth = glm::dot(e2, q) * inv;
        if (depth < 0.0 || depth > 1.0 || (best && depth >= best->depth)) return;
        const double w = 1.0 - u - v;
        const uint32_t i0 = mesh_.indices[3 * t], i1 = mesh_.indices[3 * t + 1], i2 = mesh_.indices[3 * t + 2];
        SurfaceHit hit;
        hit.position = w * tri.a + u * tri.b + v * tri.c;
        hit.normal = w * glm::dvec3(mesh_.normals[i0]) + u * glm::dvec3(mesh_.normals[i1]) +
                     v * glm::dvec3(mesh_.normals[i2]);
        hit.texcoord = w * glm::dvec2(mesh_.texcoords[i0]) + u * glm::dvec2(mesh_.texcoords[i1]) +
                       v * glm::dvec2(mesh_.texcoords[i2]);
        hit.depth = depth;
        hit.triangle = t;
        best = hit;
    };
    const int px = std::clamp(static_cast<int>(std::floor(x)), 0, size_.x - 1);
    const int py = std::clamp(static_cast<int>(std::floor(y)), 0, size_.y - 1);
    for (uint32_t t : bins_[size_t(py) * size_.x + px]) tryTriangle(t);
    for (uint32_t t : everywhere_) tryTriangle(t);
    return best;
}

bool MeshRayCast::settled(int i, int j, double depthSpread) const {
    const double cx = centre(i, j).x, cy = centre(i, j).y;
    const auto centre = at(cx, cy);
    for (double dx : {-0.35, 0.35})
        for (double dy : {-0.35, 0.35}) {
            const auto corner = at(cx + dx, cy + dy);
            if (corner.has_value() != centre.has_value()) return false;
            if (centre && std::abs(corner->depth - centre->depth) > depthSpread * centre->depth) return false;
        }
    return true;
}

}  // namespace rmfx::test
