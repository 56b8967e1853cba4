#pragma once
// Turning one image (a cross or a longitude/latitude panorama) or six images into cube map faces,
// in OpenGL's face order and orientation.
//
// Face-local coordinates: u runs across a stored face image (0 at its left edge, 1 at its right),
// v down it (0 at the top edge: row 0, the first row handed to glTexImage2D). OpenGL picks the face
// and (sc, tc, ma) for a direction r by its cube map table (GL 4.6 §8.13, table 8.19):
//     +X: sc = -rz, tc = -ry, ma = rx        -X: sc = +rz, tc = -ry, ma = rx
//     +Y: sc = +rx, tc = +rz, ma = ry        -Y: sc = +rx, tc = -rz, ma = ry
//     +Z: sc = +rx, tc = -ry, ma = rz        -Z: sc = -rx, tc = -ry, ma = rz
// with s = (sc / |ma| + 1) / 2 and t = (tc / |ma| + 1) / 2, where t = 0 is the first row uploaded.
// So u = s and v = t, and with a = 2u - 1, b = 2v - 1 a face texel looks along
//     +X: ( 1, -b, -a)   -X: (-1, -b,  a)   +Y: ( a,  1,  b)
//     -Y: ( a, -1, -b)   +Z: ( a, -b,  1)   -Z: (-a, -b, -1)
//
// Crosses (N = face size):
//     horizontal, 4N x 3N:        vertical, 3N x 4N:
//            +Y                         +Y
//        -X  +Z  +X  -Z             -X  +Z  +X
//            -Y                         -Y
//                                       -Z  (stored rotated by 180 degrees)
// The faces of the horizontal cross are taken as they are: by the table above, neighbouring faces
// in the cross meet along edges that look the same way (the right column of +Z and the left column
// of +X both look along (1, -b, 1)). In the vertical cross -Z hangs below -Y, so the block holds the
// face rotated by 180 degrees and is turned back.
//
// Longitude/latitude (equirectangular) images, W x H with W = 2H: image coordinates (u, v) in
// [0, 1] (v = 0 at the top) have longitude phi = 2 pi (u - 0.5) and latitude theta = pi (0.5 - v),
// and look along (cos theta sin phi, sin theta, -cos theta cos phi): the centre of the image looks
// along -Z, the top row toward +Y, and u grows toward +X (right-handed, Y up).

#include <array>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/Result.h"
#include "model/Image.h"

namespace rmfx {

enum CubeFace { PositiveX = 0, NegativeX, PositiveY, NegativeY, PositiveZ, NegativeZ };

// "+X", "-X", ... for messages.
const char* cubeFaceName(int face);

// The unit direction OpenGL samples at face-local (u, v) of a face, per the table above.
glm::vec3 cubeFaceTexelDirection(int face, float u, float v);

// Longitude/latitude mapping per the convention above: image (u, v) to unit direction and back
// (u in [0, 1), v in [0, 1]).
glm::vec3 equirectDirection(float u, float v);
glm::vec2 equirectCoordinates(const glm::vec3& direction);

// A horizontal (4:3) or vertical (3:4) cross; the size must divide into whole faces.
Result<CubeFaces> cubeFromCross(const Image& cross);

// A 2:1 longitude/latitude image, sampled bilinearly (wrapping in longitude) at each face texel
// centre. faceSize 0 means height / 2.
Result<CubeFaces> cubeFromEquirect(const Image& panorama, int faceSize = 0);

// Six faces in GL order; checks they are non-empty, square, of one size and one channel count.
Result<CubeFaces> cubeFromFaces(std::array<Image, 6> faces);

// Picks the layout by aspect ratio: 2:1 longitude/latitude, 4:3 or 3:4 cross.
Result<CubeFaces> cubeFromImage(const Image& image);

}  // namespace rmfx
