#include "io/mesh/BuiltinMeshes.h"

#include <array>
#include <cmath>
#include <map>
#include <tuple>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace rmfx {

namespace {

const float kPi = 3.14159265358979323846f;

void expectWellFormed(const Mesh& mesh) {
    ASSERT_GT(mesh.vertexCount(), 0u);
    ASSERT_EQ(mesh.normals.size(), mesh.vertexCount());
    ASSERT_EQ(mesh.texcoords.size(), mesh.vertexCount());
    ASSERT_EQ(mesh.indices.size() % 3, 0u);
    ASSERT_GT(mesh.triangleCount(), 0u);
    for (uint32_t i : mesh.indices) ASSERT_LT(i, mesh.vertexCount());
    for (size_t v = 0; v < mesh.vertexCount(); ++v) {
        const glm::vec3 p = mesh.positions[v], n = mesh.normals[v];
        const glm::vec2 t = mesh.texcoords[v];
        ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) << "position " << v;
        ASSERT_TRUE(std::isfinite(t.x) && std::isfinite(t.y)) << "texcoord " << v;
        ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f) << "normal " << v;
    }
}

std::array<glm::vec3, 3> corners(const Mesh& mesh, size_t triangle) {
    return {mesh.positions[mesh.indices[3 * triangle]], mesh.positions[mesh.indices[3 * triangle + 1]],
            mesh.positions[mesh.indices[3 * triangle + 2]]};
}

// Twice the area, along the normal given by the winding.
glm::vec3 faceNormal(const Mesh& mesh, size_t triangle) {
    const auto [a, b, c] = corners(mesh, triangle);
    return glm::cross(b - a, c - a);
}

// Divergence theorem: the sum of the tetrahedra spanned by the origin and each triangle.
double signedVolume(const Mesh& mesh) {
    double volume = 0;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        const auto [a, b, c] = corners(mesh, t);
        volume += double(glm::dot(a, glm::cross(b, c))) / 6.0;
    }
    return volume;
}

double area(const Mesh& mesh) {
    double sum = 0;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) sum += 0.5 * double(glm::length(faceNormal(mesh, t)));
    return sum;
}

// Welds vertices at the same position, then checks that every edge joins exactly two
// triangles that run along it in opposite directions: closed and consistently wound.
void expectClosedAndConsistent(const Mesh& mesh) {
    std::map<std::tuple<long, long, long>, int> ids;
    const auto weld = [&](glm::vec3 p) {
        const auto key = std::make_tuple(std::lround(p.x * 1e4f), std::lround(p.y * 1e4f), std::lround(p.z * 1e4f));
        return ids.emplace(key, int(ids.size())).first->second;
    };
    std::map<std::pair<int, int>, int> directed;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        const auto p = corners(mesh, t);
        const int v[3] = {weld(p[0]), weld(p[1]), weld(p[2])};
        ASSERT_TRUE(v[0] != v[1] && v[1] != v[2] && v[0] != v[2]) << "degenerate triangle " << t;
        for (int k = 0; k < 3; ++k) ++directed[{v[k], v[(k + 1) % 3]}];
    }
    for (const auto& [edge, count] : directed) {
        EXPECT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second;
        const auto back = directed.find({edge.second, edge.first});
        EXPECT_TRUE(back != directed.end() && back->second == 1) << "edge " << edge.first << "-" << edge.second;
    }
}

// Each triangle's winding normal agrees with the normals at its corners; triangles with no
// area (at the teapot's poles) have no direction to check.
void expectWindingMatchesNormals(const Mesh& mesh, float minDoubleArea = 1e-10f) {
    size_t checked = 0;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        const glm::vec3 n = faceNormal(mesh, t);
        if (glm::length(n) <= minDoubleArea) continue;
        ++checked;
        for (int k = 0; k < 3; ++k)
            ASSERT_GT(glm::dot(n, mesh.normals[mesh.indices[3 * t + k]]), 0.0f) << "triangle " << t << " corner " << k;
    }
    EXPECT_GT(checked, mesh.triangleCount() * 9 / 10);
}

glm::vec3 boundsMin(const Mesh& mesh) {
    glm::vec3 lo(1e30f);
    for (glm::vec3 p : mesh.positions) lo = glm::min(lo, p);
    return lo;
}

glm::vec3 boundsMax(const Mesh& mesh) {
    glm::vec3 hi(-1e30f);
    for (glm::vec3 p : mesh.positions) hi = glm::max(hi, p);
    return hi;
}

}  // namespace

TEST(BuiltinMeshes, EveryBuiltinIsWellFormed) {
    for (BuiltinMesh m : {BuiltinMesh::FullscreenTriangle, BuiltinMesh::Cube, BuiltinMesh::Sphere, BuiltinMesh::Plane,
                          BuiltinMesh::Teapot, BuiltinMesh::Quad, BuiltinMesh::Torus}) {
        SCOPED_TRACE(builtinMeshName(m));
        expectWellFormed(makeMesh(m));
    }
}

TEST(BuiltinMeshes, NamesRoundTripIgnoringCase) {
    for (BuiltinMesh m : {BuiltinMesh::FullscreenTriangle, BuiltinMesh::Cube, BuiltinMesh::Sphere, BuiltinMesh::Plane,
                          BuiltinMesh::Teapot, BuiltinMesh::Quad, BuiltinMesh::Torus})
        EXPECT_EQ(builtinMeshFromName(builtinMeshName(m)), m);
    EXPECT_EQ(builtinMeshFromName("fullscreen"), BuiltinMesh::FullscreenTriangle);
    EXPECT_EQ(builtinMeshFromName("Teapot"), BuiltinMesh::Teapot);
    EXPECT_EQ(builtinMeshFromName("SPHERE"), BuiltinMesh::Sphere);
    EXPECT_EQ(builtinMeshFromName("Torus"), BuiltinMesh::Torus);
    EXPECT_FALSE(builtinMeshFromName("donut"));
    EXPECT_FALSE(builtinMeshFromName(""));
    EXPECT_FALSE(builtinMeshFromName("cubes"));
}

TEST(BuiltinMeshes, FullscreenTriangleCoversClipSquare) {
    const Mesh mesh = makeFullscreenTriangle();
    expectWellFormed(mesh);
    ASSERT_EQ(mesh.vertexCount(), 3u);
    ASSERT_EQ(mesh.triangleCount(), 1u);
    const glm::vec2 a(mesh.positions[0]), b(mesh.positions[1]), c(mesh.positions[2]);
    const float det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    EXPECT_GT(det, 0.0f) << "counter-clockwise in clip space";
    for (float x = -1.0f; x <= 1.0f; x += 0.25f) {
        for (float y = -1.0f; y <= 1.0f; y += 0.25f) {
            // Barycentric weights of (x, y); all in [0, 1] means inside.
            const float wb = ((x - a.x) * (c.y - a.y) - (c.x - a.x) * (y - a.y)) / det;
            const float wc = ((b.x - a.x) * (y - a.y) - (x - a.x) * (b.y - a.y)) / det;
            const float wa = 1.0f - wb - wc;
            EXPECT_GE(std::min({wa, wb, wc}), -1e-6f) << x << "," << y;
            // Texcoords interpolate to 0..1 across the visible square.
            const glm::vec2 uv = wa * mesh.texcoords[0] + wb * mesh.texcoords[1] + wc * mesh.texcoords[2];
            EXPECT_NEAR(uv.x, (x + 1) / 2, 1e-5f);
            EXPECT_NEAR(uv.y, (y + 1) / 2, 1e-5f);
        }
    }
    for (glm::vec3 p : mesh.positions) EXPECT_EQ(p.z, 0.0f);
    for (glm::vec3 n : mesh.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

TEST(BuiltinMeshes, CubeIsClosedWithVolumeEight) {
    const Mesh mesh = makeCube();
    expectWellFormed(mesh);
    EXPECT_EQ(mesh.vertexCount(), 24u);
    EXPECT_EQ(mesh.triangleCount(), 12u);
    EXPECT_EQ(boundsMin(mesh), glm::vec3(-1));
    EXPECT_EQ(boundsMax(mesh), glm::vec3(1));
    expectClosedAndConsistent(mesh);
    EXPECT_NEAR(signedVolume(mesh), 8.0, 1e-5);
    EXPECT_NEAR(area(mesh), 24.0, 1e-5);
    expectWindingMatchesNormals(mesh);
    for (size_t v = 0; v < mesh.vertexCount(); ++v) {
        // Flat faces: the normal is the axis the vertex sits at ±1 on.
        const glm::vec3 n = mesh.normals[v];
        EXPECT_FLOAT_EQ(glm::dot(n, mesh.positions[v]), 1.0f);
        EXPECT_FLOAT_EQ(std::abs(n.x) + std::abs(n.y) + std::abs(n.z), 1.0f);
        const glm::vec2 t = mesh.texcoords[v];
        EXPECT_TRUE((t.x == 0 || t.x == 1) && (t.y == 0 || t.y == 1));
    }
}

TEST(BuiltinMeshes, SphereIsClosedUnitSphere) {
    const Mesh mesh = makeSphere(128, 64);
    expectWellFormed(mesh);
    expectClosedAndConsistent(mesh);
    const double exact = 4.0 / 3.0 * kPi;
    EXPECT_GT(signedVolume(mesh), 0.99 * exact);
    EXPECT_LT(signedVolume(mesh), exact);  // inscribed
    EXPECT_NEAR(area(mesh), 4.0 * kPi, 0.01 * 4.0 * kPi);
    expectWindingMatchesNormals(mesh);
    for (size_t v = 0; v < mesh.vertexCount(); ++v) {
        EXPECT_NEAR(glm::length(mesh.positions[v]), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::distance(mesh.positions[v], mesh.normals[v]), 0.0f, 1e-5f);
        EXPECT_GE(mesh.texcoords[v].y, 0.0f);
        EXPECT_LE(mesh.texcoords[v].y, 1.0f);
    }
}

// Pappus: volume 2π²Rr², area 4π²Rr (a polygonal torus, inscribed, falls a little short of both).
TEST(BuiltinMeshes, TorusIsClosedWithPappusVolumeAndArea) {
    const double R = 0.7, r = 0.3;
    const Mesh mesh = makeTorus(float(R), float(r), 256, 128);
    expectWellFormed(mesh);
    expectClosedAndConsistent(mesh);
    expectWindingMatchesNormals(mesh);
    const double volume = 2.0 * kPi * kPi * R * r * r, surface = 4.0 * kPi * kPi * R * r;
    EXPECT_GT(signedVolume(mesh), 0.999 * volume);
    EXPECT_LT(signedVolume(mesh), volume);
    EXPECT_NEAR(area(mesh), surface, 0.001 * surface);
    for (size_t v = 0; v < mesh.vertexCount(); ++v) {
        // Each vertex lies r from the tube's centre circle, along its normal.
        const glm::dvec3 p(mesh.positions[v]), n(mesh.normals[v]);
        const glm::dvec3 centre = p - r * n;
        EXPECT_NEAR(std::hypot(centre.x, centre.z), R, 1e-5);
        EXPECT_NEAR(centre.y, 0.0, 1e-5);
    }
    EXPECT_NEAR(boundsMax(makeTorus()).x, 1.0f, 1e-5f);  // the defaults fit [-1, 1]
    EXPECT_NEAR(boundsMax(makeTorus()).y, 0.3f, 1e-5f);
}

TEST(BuiltinMeshes, SphereCountsAndSeam) {
    const int segments = 8, rings = 4;
    const Mesh mesh = makeSphere(segments, rings);
    expectWellFormed(mesh);
    expectClosedAndConsistent(mesh);
    EXPECT_EQ(mesh.vertexCount(), size_t((segments + 1) * (rings + 1)));
    // Two triangles per quad, one per quad in the two pole rows.
    EXPECT_EQ(mesh.triangleCount(), size_t(2 * segments * (rings - 2) + 2 * segments));
    // The seam column repeats the first at u = 1.
    for (int r = 1; r < rings; ++r) {
        const size_t first = size_t(r * (segments + 1)), last = first + size_t(segments);
        EXPECT_NEAR(glm::distance(mesh.positions[first], mesh.positions[last]), 0.0f, 1e-6f);
        EXPECT_EQ(mesh.texcoords[first].x, 0.0f);
        EXPECT_EQ(mesh.texcoords[last].x, 1.0f);
    }
    EXPECT_EQ(mesh.positions.front(), glm::vec3(0, 1, 0));
    EXPECT_EQ(mesh.positions.back(), glm::vec3(0, -1, 0));
    EXPECT_GT(signedVolume(makeSphere()), 0.97 * 4.0 / 3.0 * kPi);
}

TEST(BuiltinMeshes, PlaneFacesUp) {
    const Mesh mesh = makePlane();
    expectWellFormed(mesh);
    EXPECT_EQ(mesh.vertexCount(), 4u);
    EXPECT_EQ(mesh.triangleCount(), 2u);
    EXPECT_EQ(boundsMin(mesh), glm::vec3(-1, 0, -1));
    EXPECT_EQ(boundsMax(mesh), glm::vec3(1, 0, 1));
    EXPECT_NEAR(area(mesh), 4.0, 1e-6);
    for (size_t t = 0; t < mesh.triangleCount(); ++t)
        EXPECT_GT(glm::dot(faceNormal(mesh, t), glm::vec3(0, 1, 0)), 0.0f);
    for (size_t v = 0; v < mesh.vertexCount(); ++v) {
        EXPECT_EQ(mesh.normals[v], glm::vec3(0, 1, 0));
        // UVs span 0..1 and follow x.
        EXPECT_FLOAT_EQ(mesh.texcoords[v].x, (mesh.positions[v].x + 1) / 2);
    }
}

TEST(Teapot, HasTwoTrianglesPerQuadOfEveryPatch) {
    for (int sub : {1, 4, 10}) {
        const Mesh mesh = makeTeapot(sub);
        expectWellFormed(mesh);
        EXPECT_EQ(mesh.triangleCount(), size_t(32 * sub * sub * 2));
        EXPECT_EQ(mesh.vertexCount(), size_t(32 * (sub + 1) * (sub + 1)));
    }
    EXPECT_EQ(makeMesh(BuiltinMesh::Teapot).triangleCount(), size_t(32 * 10 * 10 * 2));
}

TEST(Teapot, FitsInUnitBoxWithYUp) {
    const Mesh mesh = makeTeapot(10);
    const glm::vec3 lo = boundsMin(mesh), hi = boundsMax(mesh);
    for (int k = 0; k < 3; ++k) {
        EXPECT_GE(lo[k], -1.2f);
        EXPECT_LE(hi[k], 1.2f);
    }
    // Widest from handle to spout (along X), then across (Z), and shortest upright (Y).
    const glm::vec3 size = hi - lo;
    EXPECT_GT(size.x, 1.8f);
    EXPECT_GT(size.x, size.z);
    EXPECT_GT(size.z, size.y);
    EXPECT_NEAR(lo.y + hi.y, 0.0f, 0.05f);
    // The lid knob is on top: the highest vertex sits near the vertical axis.
    size_t top = 0;
    for (size_t v = 0; v < mesh.vertexCount(); ++v)
        if (mesh.positions[v].y > mesh.positions[top].y) top = v;
    EXPECT_LT(std::abs(mesh.positions[top].z), 0.05f);
    EXPECT_NEAR(mesh.normals[top].y, 1.0f, 1e-3f);
}

TEST(Teapot, NormalsPointOutward) {
    const int sub = 12;
    const Mesh mesh = makeTeapot(sub);
    glm::vec3 centroid(0);
    for (glm::vec3 p : mesh.positions) centroid += p;
    centroid /= float(mesh.vertexCount());

    // Patches come in the classic order: rim 0-3, body 4-11, handle 12-15, spout 16-19,
    // lid 20-27, bottom 28-31, each with (sub+1)^2 vertices.
    const size_t perPatch = size_t((sub + 1) * (sub + 1));
    size_t away = 0, bodyAway = 0, bodyCount = 0;
    for (size_t v = 0; v < mesh.vertexCount(); ++v) {
        const bool out = glm::dot(mesh.normals[v], mesh.positions[v] - centroid) > 0;
        away += out;
        const size_t patch = v / perPatch;
        if ((patch >= 4 && patch < 12) || patch >= 24) {
            ++bodyCount;
            bodyAway += out;
        }
    }
    EXPECT_GT(double(bodyAway) / double(bodyCount), 0.9);
    EXPECT_GT(double(away) / double(mesh.vertexCount()), 0.75);
    expectWindingMatchesNormals(mesh, 1e-7f);
}

TEST(Teapot, AreaConvergesUnderRefinement) {
    const double a8 = area(makeTeapot(8)), a16 = area(makeTeapot(16)), a32 = area(makeTeapot(32));
    EXPECT_GT(a8, 0.0);
    EXPECT_NEAR(a16, a32, 0.01 * a32);
    EXPECT_LT(std::abs(a32 - a16), std::abs(a16 - a8));
    // Inscribed triangles underestimate a curved surface.
    EXPECT_LT(a8, a16);
}

}  // namespace rmfx
