#pragma once
// Model files written by the tests, in the formats RenderMonkey's media came in, so that what an
// importer does to a real file's numbers shows up on a shape the test knows.

#include <array>
#include <filesystem>
#include <optional>

#include "model/Mesh.h"

namespace rmfx::test {

// A 3D Studio .3ds file: one object, its triangles (at most 65535 vertices and faces), texture
// coordinates and, when given, the object's local axes (the 0x4160 chunk: x, y and z axis and the
// origin, 12 floats); the vertices are written as given, which is world space in a .3ds file.
void write3ds(const std::filesystem::path& file, const Mesh& mesh,
              const std::optional<std::array<float, 12>>& localAxes = std::nullopt);

// A DirectX .x text file: one Mesh with its positions, faces and MeshTextureCoords, all written as
// given (no normals: importers generate them).
void writeDirectX(const std::filesystem::path& file, const Mesh& mesh);

// A Wavefront .obj file: positions, texture coordinates, normals (when the mesh has them) and
// faces as given (%.9g, exact for floats).
void writeObj(const std::filesystem::path& file, const Mesh& mesh);

// Three boxes from the origin along +x (long), +y (middle) and +z (short), each with its own
// range of texture coordinates: every mirror, axis swap, v flip or winding reversal of it draws
// differently. Counter-clockwise seen from outside.
Mesh asymmetricBoxes();

}  // namespace rmfx::test
