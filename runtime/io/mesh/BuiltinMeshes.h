#pragma once
// Meshes a workspace can name instead of a model file: RenderMonkey's stock geometry.

#include <optional>
#include <string_view>

#include "model/BuiltinMeshNames.h"
#include "model/Mesh.h"
#include "model/Workspace.h"

namespace rmfx {

Mesh makeMesh(BuiltinMesh which);
// The built-in mesh a draw call names, its vertices scaled by meshScale and moved by meshOffset
// (a stand-in for a missing model); nullopt when it names a file.
std::optional<Mesh> makeDrawnMesh(const DrawCall& draw);

// One triangle that covers clip space [-1,1]^2; texcoords are 0..1 over the visible square.
Mesh makeFullscreenTriangle();
// Side 2, centred at the origin, 24 vertices so each face has its own normal and 0..1 UVs.
Mesh makeCube();
// Radius 1 at the origin; segments around the Y axis, rings from pole to pole.
Mesh makeSphere(int segments = 48, int rings = 24);
// 2x2 in XZ at y = 0, facing +Y.
Mesh makePlane();
// 2x2 in XY at z = 0, facing +Z, texcoords 0..1 from the bottom-left corner: the stand-in for
// RenderMonkey's ScreenAlignedQuad.3ds, whose shaders write its positions straight to clip space.
Mesh makeQuad();
// The Utah teapot, Y up, centred near the origin and scaled to fit [-1,1];
// each of its 32 Bezier patches becomes subdivisions x subdivisions quads over its own
// (subdivisions+1)^2 vertices, patch after patch in the classic order (rim, body, handle,
// spout, lid, bottom). Texcoords are the patch parameters.
Mesh makeTeapot(int subdivisions = 10);
// A ring around the Y axis, centred at the origin: the tube's centre at majorRadius, the tube
// minorRadius thick (the defaults fit [-1,1]); texcoords u around the ring, v around the tube.
Mesh makeTorus(float majorRadius = 0.7f, float minorRadius = 0.3f, int segments = 48, int sides = 24);

}  // namespace rmfx
