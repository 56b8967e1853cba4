#include "io/mesh/ModelLoader.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "tests/support/ModelFiles.h"
#include "tests/support/TestSupport.h"

namespace rmfx {

namespace {

bool hasPosition(const Mesh& mesh, glm::vec3 p) {
    return std::any_of(mesh.positions.begin(), mesh.positions.end(),
                       [&](glm::vec3 q) { return glm::distance(p, q) < 1e-5f; });
}

void expectWellFormed(const Mesh& mesh) {
    ASSERT_EQ(mesh.normals.size(), mesh.vertexCount());
    ASSERT_EQ(mesh.texcoords.size(), mesh.vertexCount());
    ASSERT_EQ(mesh.indices.size() % 3, 0u);
    for (uint32_t i : mesh.indices) ASSERT_LT(i, mesh.vertexCount());
    for (glm::vec3 n : mesh.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
}

glm::vec3 faceNormal(const Mesh& mesh, size_t t) {
    const glm::vec3 a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]],
                    c = mesh.positions[mesh.indices[3 * t + 2]];
    return glm::normalize(glm::cross(b - a, c - a));
}

// Every triangle written is in the loaded mesh with the same positions and texture coordinates
// in the same winding (any rotation of its corners), and as many triangles as written.
void expectTheFilesOwnTriangles(const Mesh& loaded, const Mesh& written) {
    ASSERT_EQ(loaded.triangleCount(), written.triangleCount());
    auto same = [&](uint32_t l, uint32_t w) {
        return glm::distance(loaded.positions[l], written.positions[w]) < 1e-5f &&
               glm::distance(loaded.texcoords[l], written.texcoords[w]) < 1e-5f;
    };
    for (size_t t = 0; t < written.triangleCount(); ++t) {
        const uint32_t* w = &written.indices[3 * t];
        bool found = false;
        for (size_t u = 0; u < loaded.triangleCount() && !found; ++u) {
            const uint32_t* l = &loaded.indices[3 * u];
            for (int r = 0; r < 3 && !found; ++r)
                found = same(l[r], w[0]) && same(l[(r + 1) % 3], w[1]) && same(l[(r + 2) % 3], w[2]);
        }
        EXPECT_TRUE(found) << "triangle " << t << " (" << w[0] << ", " << w[1] << ", " << w[2]
                           << ") is not in the loaded mesh as written";
    }
    // Generated normals (smoothed over the corners: the boxes' faces meet there) lean to the side
    // the file's triangles wind counter-clockwise for.
    for (size_t t = 0; t < loaded.triangleCount(); ++t)
        for (int k = 0; k < 3; ++k)
            EXPECT_GT(glm::dot(faceNormal(loaded, t), loaded.normals[loaded.indices[3 * t + k]]), 0.0f) << "triangle " << t;
}

}  // namespace

// RenderMonkey drew a model's own numbers; Assimp's 3DS importer rotates Z up to Y up, its .x
// importer mirrors z, flips v and reverses the winding, and loadModel undoes both.
TEST(ModelLoader, ThreeDsCoordinatesAreTheFilesOwn) {
    test::ScratchDir dir;
    const Mesh boxes = test::asymmetricBoxes();
    test::write3ds(dir / "boxes.3ds", boxes);
    const Result<Mesh> plain = loadModel(dir / "boxes.3ds");
    ASSERT_TRUE(plain) << plain.error();
    expectWellFormed(*plain);
    expectTheFilesOwnTriangles(*plain, boxes);
    // With local axes (a rotation about z and an origin), the vertices are still world space.
    test::write3ds(dir / "axes.3DS", boxes, std::array<float, 12>{0, 1, 0, -1, 0, 0, 0, 0, 1, 2, 3, 4});
    const Result<Mesh> withAxes = loadModel(dir / "axes.3DS");
    ASSERT_TRUE(withAxes) << withAxes.error();
    expectTheFilesOwnTriangles(*withAxes, boxes);
}

TEST(ModelLoader, DirectXCoordinatesTexcoordsAndWindingAreTheFilesOwn) {
    test::ScratchDir dir;
    const Mesh boxes = test::asymmetricBoxes();
    test::writeDirectX(dir / "boxes.x", boxes);
    const Result<Mesh> mesh = loadModel(dir / "boxes.x");
    ASSERT_TRUE(mesh) << mesh.error();
    expectWellFormed(*mesh);
    expectTheFilesOwnTriangles(*mesh, boxes);
}

TEST(ModelLoader, ObjCoordinatesAreTheFilesOwn) {
    test::ScratchDir dir;
    Mesh boxes = test::asymmetricBoxes();
    boxes.normals.clear();  // generated, as for the other formats
    test::writeObj(dir / "boxes.obj", boxes);
    const Result<Mesh> mesh = loadModel(dir / "boxes.obj");
    ASSERT_TRUE(mesh) << mesh.error();
    expectTheFilesOwnTriangles(*mesh, boxes);
}

TEST(ModelLoader, TriangleWithoutNormalsOrTexcoords) {
    test::ScratchDir dir;
    const auto file = dir.write("tri.obj",
                                "v 0 0 0\n"
                                "v 1 0 0\n"
                                "v 0 1 0\n"
                                "f 1 2 3\n");
    const Result<Mesh> mesh = loadModel(file);
    ASSERT_TRUE(mesh) << mesh.error();
    expectWellFormed(*mesh);
    EXPECT_EQ(mesh->vertexCount(), 3u);
    EXPECT_EQ(mesh->triangleCount(), 1u);
    EXPECT_TRUE(hasPosition(*mesh, {0, 0, 0}));
    EXPECT_TRUE(hasPosition(*mesh, {1, 0, 0}));
    EXPECT_TRUE(hasPosition(*mesh, {0, 1, 0}));
    // Generated normals face the side the triangle winds counter-clockwise for.
    for (glm::vec3 n : mesh->normals) EXPECT_NEAR(glm::distance(n, glm::vec3(0, 0, 1)), 0.0f, 1e-5f);
    for (glm::vec2 t : mesh->texcoords) EXPECT_EQ(t, glm::vec2(0));
    EXPECT_NEAR(glm::distance(faceNormal(*mesh, 0), glm::vec3(0, 0, 1)), 0.0f, 1e-5f);
}

TEST(ModelLoader, QuadWithTexcoordsAndNormalsIsTriangulated) {
    test::ScratchDir dir;
    const auto file = dir.write("quad.obj",
                                "v -1 0 1\nv 1 0 1\nv 1 0 -1\nv -1 0 -1\n"
                                "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                "vn 0 1 0\n"
                                "f 1/1/1 2/2/1 3/3/1 4/4/1\n");
    const Result<Mesh> mesh = loadModel(file);
    ASSERT_TRUE(mesh) << mesh.error();
    expectWellFormed(*mesh);
    EXPECT_EQ(mesh->triangleCount(), 2u);
    EXPECT_EQ(mesh->vertexCount(), 4u);  // the shared diagonal is joined
    for (size_t v = 0; v < mesh->vertexCount(); ++v) {
        const glm::vec3 p = mesh->positions[v];
        EXPECT_EQ(mesh->normals[v], glm::vec3(0, 1, 0));
        // The texcoords stay with their corners: u follows x, v follows -z.
        EXPECT_FLOAT_EQ(mesh->texcoords[v].x, (p.x + 1) / 2);
        EXPECT_FLOAT_EQ(mesh->texcoords[v].y, (1 - p.z) / 2);
    }
    for (size_t t = 0; t < mesh->triangleCount(); ++t)
        EXPECT_GT(glm::dot(faceNormal(*mesh, t), glm::vec3(0, 1, 0)), 0.99f);
}

TEST(ModelLoader, CubeOfQuadsGetsSmoothNormals) {
    test::ScratchDir dir;
    const auto file = dir.write("cube.obj",
                                "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\n"
                                "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
                                "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n");
    const Result<Mesh> mesh = loadModel(file);
    ASSERT_TRUE(mesh) << mesh.error();
    expectWellFormed(*mesh);
    EXPECT_EQ(mesh->triangleCount(), 12u);
    EXPECT_EQ(mesh->vertexCount(), 8u);
    double volume = 0;
    for (size_t t = 0; t < mesh->triangleCount(); ++t) {
        const glm::vec3 a = mesh->positions[mesh->indices[3 * t]], b = mesh->positions[mesh->indices[3 * t + 1]],
                        c = mesh->positions[mesh->indices[3 * t + 2]];
        volume += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    EXPECT_NEAR(volume, 8.0, 1e-5);
    // Smoothed over three faces, each corner's normal points along its diagonal.
    for (size_t v = 0; v < mesh->vertexCount(); ++v)
        EXPECT_NEAR(glm::dot(mesh->normals[v], glm::normalize(mesh->positions[v])), 1.0f, 1e-4f);
}

TEST(ModelLoader, MergesObjects) {
    test::ScratchDir dir;
    const auto file = dir.write("two.obj",
                                "o first\n"
                                "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                "f 1 2 3\n"
                                "o second\n"
                                "v 5 0 0\nv 6 0 0\nv 5 0 -1\nv 6 0 -1\n"
                                "f 4 5 7 6\n");
    const Result<Mesh> mesh = loadModel(file);
    ASSERT_TRUE(mesh) << mesh.error();
    expectWellFormed(*mesh);
    EXPECT_EQ(mesh->triangleCount(), 3u);
    EXPECT_EQ(mesh->vertexCount(), 7u);
    for (glm::vec3 p : {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(5, 0, 0),
                        glm::vec3(6, 0, 0), glm::vec3(5, 0, -1), glm::vec3(6, 0, -1)})
        EXPECT_TRUE(hasPosition(*mesh, p)) << p.x << "," << p.y << "," << p.z;
}

TEST(ModelLoader, NestedNodesLandInWorldSpace) {
    test::ScratchDir dir;
    const auto file = dir.write("nested.dae", R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit meter="1" name="meter"/><up_axis>Y_UP</up_axis></asset>
  <library_geometries>
    <geometry id="tri" name="tri">
      <mesh>
        <source id="tri-pos">
          <float_array id="tri-pos-array" count="9">0 0 0 1 0 0 0 1 0</float_array>
          <technique_common>
            <accessor source="#tri-pos-array" count="3" stride="3">
              <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
            </accessor>
          </technique_common>
        </source>
        <vertices id="tri-vtx"><input semantic="POSITION" source="#tri-pos"/></vertices>
        <triangles count="1"><input semantic="VERTEX" source="#tri-vtx" offset="0"/><p>0 1 2</p></triangles>
      </mesh>
    </geometry>
  </library_geometries>
  <library_visual_scenes>
    <visual_scene id="scene" name="scene">
      <node id="outer" name="outer">
        <translate>10 0 0</translate>
        <node id="inner" name="inner">
          <translate>0 5 0</translate>
          <instance_geometry url="#tri"/>
        </node>
      </node>
    </visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)");
    const Result<Mesh> mesh = loadModel(file);
    ASSERT_TRUE(mesh) << mesh.error();
    expectWellFormed(*mesh);
    EXPECT_EQ(mesh->triangleCount(), 1u);
    EXPECT_TRUE(hasPosition(*mesh, {10, 5, 0}));
    EXPECT_TRUE(hasPosition(*mesh, {11, 5, 0}));
    EXPECT_TRUE(hasPosition(*mesh, {10, 6, 0}));
}

TEST(ModelLoader, MissingFileIsAnErrorNamingIt) {
    test::ScratchDir dir;
    const auto file = dir / "nowhere.obj";
    const Result<Mesh> mesh = loadModel(file);
    ASSERT_FALSE(mesh);
    EXPECT_NE(mesh.error().find(file.string()), std::string::npos) << mesh.error();
}

TEST(ModelLoader, GarbageIsAnErrorNamingTheFile) {
    test::ScratchDir dir;
    for (const char* name : {"garbage.obj", "garbage.3ds", "garbage.bin"}) {
        const auto file = dir.write(name, std::string("\x01\x02\xff\xfe not a model \0\0\x7f", 20) + "}{][");
        const Result<Mesh> mesh = loadModel(file);
        ASSERT_FALSE(mesh) << name;
        EXPECT_NE(mesh.error().find(file.string()), std::string::npos) << mesh.error();
    }
}

TEST(ModelLoader, FileWithoutTrianglesIsAnError) {
    test::ScratchDir dir;
    for (const auto& [name, text] : {std::pair{"empty.obj", ""}, std::pair{"lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n"},
                                     std::pair{"points.obj", "v 0 0 0\nv 1 0 0\np 1 2\n"}}) {
        const auto file = dir.write(name, text);
        const Result<Mesh> mesh = loadModel(file);
        ASSERT_FALSE(mesh) << name;
        EXPECT_NE(mesh.error().find(file.string()), std::string::npos) << mesh.error();
    }
}

TEST(ModelLoader, DropsLinesBesideTriangles) {
    test::ScratchDir dir;
    const auto file = dir.write("mixed.obj",
                                "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 7 7 7\nv 8 8 8\n"
                                "f 1 2 3\n"
                                "l 4 5\n");
    const Result<Mesh> mesh = loadModel(file);
    ASSERT_TRUE(mesh) << mesh.error();
    expectWellFormed(*mesh);
    EXPECT_EQ(mesh->triangleCount(), 1u);
    EXPECT_EQ(mesh->vertexCount(), 3u);
    EXPECT_FALSE(hasPosition(*mesh, {7, 7, 7}));
}

}  // namespace rmfx
