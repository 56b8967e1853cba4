#include <algorithm>
#include <array>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "io/mesh/BuiltinMeshes.h"
#include "io/mesh/TeapotData.h"

namespace rmfx {

namespace {

struct Basis {
    std::array<float, 4> value;       // cubic Bernstein polynomials
    std::array<float, 4> derivative;  // their derivatives
};

Basis bernstein(float t) {
    const float s = 1.0f - t;
    return {{s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t},
            {-3 * s * s, 3 * s * s - 6 * t * s, 6 * t * s - 3 * t * t, 3 * t * t}};
}

struct SurfacePoint {
    glm::vec3 position, du, dv;
};

class BezierPatch {
public:
    explicit BezierPatch(const std::array<uint16_t, 16>& indices) {
        for (int k = 0; k < 16; ++k) {
            const teapot::ControlPoint& c = teapot::kPoints[indices[k] - 1];
            points_[k / 4][k % 4] = glm::vec3(c.x, c.y, c.z);
        }
    }

    SurfacePoint at(float u, float v) const {
        const Basis bu = bernstein(u), bv = bernstein(v);
        SurfacePoint p{glm::vec3(0), glm::vec3(0), glm::vec3(0)};
        for (int i = 0; i < 4; ++i) {
            for (int j = 0; j < 4; ++j) {
                p.position += bu.value[i] * bv.value[j] * points_[i][j];
                p.du += bu.derivative[i] * bv.value[j] * points_[i][j];
                p.dv += bu.value[i] * bv.derivative[j] * points_[i][j];
            }
        }
        return p;
    }

    // cross(du, dv), unnormalised. Where the patch collapses to a point (the lid knob and
    // bottom poles) one derivative vanishes, so look a little way into the patch instead:
    // the normal there is continuous and tends to the pole's normal.
    glm::vec3 rawNormal(float u, float v) const {
        const float steps[] = {0.0f, 1e-3f, 1e-2f};
        for (float h : steps) {
            const float uu = u < 0.5f ? u + h : u - h;
            const float vv = v < 0.5f ? v + h : v - h;
            const SurfacePoint p = at(uu, vv);
            const glm::vec3 n = glm::cross(p.du, p.dv);
            // Control points are a few units apart; rounding leaves ~1e-6 in a vanished derivative.
            const float du = glm::length(p.du), dv = glm::length(p.dv);
            if (du > 1e-4f && dv > 1e-4f && glm::length(n) > 1e-3f * du * dv) return n;
        }
        return glm::vec3(0, 0, 1);
    }

    // +1 when cross(du, dv) points out of the teapot, -1 when the patch runs the other way.
    // Every teapot patch bulges outward, so its middle lies outside the chord through its corners.
    float outwardSign() const {
        const glm::vec3 corners = (points_[0][0] + points_[0][3] + points_[3][0] + points_[3][3]) * 0.25f;
        const glm::vec3 middle = at(0.5f, 0.5f).position;
        return glm::dot(rawNormal(0.5f, 0.5f), middle - corners) >= 0.0f ? 1.0f : -1.0f;
    }

private:
    glm::vec3 points_[4][4];
};

// Z up to Y up (a rotation about X, so winding and handedness survive), then into [-1,1].
struct Placement {
    glm::vec3 centre;
    float scale;

    static Placement fromControlPoints() {
        glm::vec3 lo(1e30f), hi(-1e30f);
        for (const teapot::ControlPoint& c : teapot::kPoints) {
            lo = glm::min(lo, glm::vec3(c.x, c.y, c.z));
            hi = glm::max(hi, glm::vec3(c.x, c.y, c.z));
        }
        const glm::vec3 extent = hi - lo;
        return {(lo + hi) * 0.5f, 2.0f / std::max({extent.x, extent.y, extent.z})};
    }

    glm::vec3 position(glm::vec3 p) const { return direction((p - centre) * scale); }
    static glm::vec3 direction(glm::vec3 d) { return {d.x, d.z, -d.y}; }
};

}  // namespace

Mesh makeTeapot(int subdivisions) {
    const int n = std::max(subdivisions, 1);
    const Placement placement = Placement::fromControlPoints();
    Mesh mesh;
    const size_t verticesPerPatch = size_t(n + 1) * size_t(n + 1);
    mesh.positions.reserve(teapot::kPatches.size() * verticesPerPatch);
    mesh.normals.reserve(mesh.positions.capacity());
    mesh.texcoords.reserve(mesh.positions.capacity());
    mesh.indices.reserve(teapot::kPatches.size() * size_t(n) * size_t(n) * 6);

    for (const auto& indices : teapot::kPatches) {
        const BezierPatch patch(indices);
        const float sign = patch.outwardSign();
        const auto base = static_cast<uint32_t>(mesh.positions.size());
        for (int i = 0; i <= n; ++i) {
            for (int j = 0; j <= n; ++j) {
                const float u = float(i) / float(n), v = float(j) / float(n);
                mesh.positions.push_back(placement.position(patch.at(u, v).position));
                mesh.normals.push_back(Placement::direction(glm::normalize(sign * patch.rawNormal(u, v))));
                mesh.texcoords.emplace_back(u, v);
            }
        }
        const auto at = [&](int i, int j) { return base + static_cast<uint32_t>(i * (n + 1) + j); };
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                // (u, v) -> (u+1, v) -> (u+1, v+1) turns about cross(du, dv); reverse it when
                // that points inward.
                std::array<uint32_t, 4> quad{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
                if (sign < 0) std::swap(quad[1], quad[3]);
                mesh.indices.insert(mesh.indices.end(), {quad[0], quad[1], quad[2], quad[0], quad[2], quad[3]});
            }
        }
    }
    return mesh;
}

}  // namespace rmfx
