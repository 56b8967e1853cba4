#pragma once
// Float64 bilinear lookups in a cube map, by OpenGL's face-selection table (see
// runtime/CubeMapLayout.h), for the references of passes that read the environment.

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "model/Image.h"

namespace rmfx::test {

struct CubeSample {
    glm::dvec4 value{0.0};
    // The 2x2 footprint leaves the face: GL's seamless filtering then mixes in the neighbouring
    // face, which this reference does not model, so callers skip such samples.
    bool nearEdge = false;
};

// GL_LINEAR within one face (no mipmaps). Missing channels are 0 (rgb) or 1 (alpha).
CubeSample sampleCubeBilinear(const CubeFaces& faces, glm::dvec3 direction);

}  // namespace rmfx::test
