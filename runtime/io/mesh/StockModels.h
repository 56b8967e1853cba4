#pragma once
// RenderMonkey's stock models (its Examples/Media/Models), which many public .rfx files name
// but do not carry: the size each has, so that a built-in mesh standing in for a missing one is
// drawn where the model was. A shader's own scaling (`Pos.xyz * radius`, `normalize(Pos)`) and the
// camera a file stored were made for these sizes. Measured from the public copies (sha1 of the
// file; coordinates as stored, y up):
//   Sphere.3ds             ddcdc7d7 (danginsburg/opengles-book-samples; popekim's sphere.x is
//                          the same mesh)                           radius 52 about (0.001, 0.001, 0.001)
//   Teapot.3ds             e640d462 (opengles-book-samples; popekim's teapot.x)
//   Torus.3ds              efdb90a7 (opengles-book-samples; popekim's torus.x): a torus knot
//   ScreenAlignedQuad.3ds  9ede13e8 (opengles-book-samples, pugakn/Drider-Engine): [-0.999, 1.001]²
//   Terrain.3ds            9c95b0ec (opengles-book-samples): a height field 900 wide

#include <optional>
#include <string_view>

#include <glm/vec3.hpp>

#include "model/Mesh.h"

namespace rmfx {

struct StockModel {
    std::string_view stem;  // the file name's stem, lower case: "sphere"
    BuiltinMesh standIn;    // the built-in mesh drawn in its place
    glm::vec3 boundsMin, boundsMax;
    bool mirrorU = false;   // the model's u runs the other way round from the built-in mesh's
};

// The stock model a file name (its stem, any case: "Sphere", "TEAPOT") names; nullopt for others.
std::optional<StockModel> findStockModel(std::string_view stem);

// What puts a built-in mesh where the stock model was: its vertices times `scale`, plus `offset`,
// give it the stock model's bounding-box centre and largest side.
struct MeshPlacement {
    float scale = 1.0f;
    glm::vec3 offset{0.0f};
};
MeshPlacement stockModelPlacement(const StockModel& model);

}  // namespace rmfx
