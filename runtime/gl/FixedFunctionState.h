#pragma once
// The fixed-function state legacy GLSL reads in a compatibility-profile context: the projection
// and modelview matrices (gl_ModelViewProjectionMatrix, gl_NormalMatrix, ftransform()…), light 0
// (gl_LightSource[0]) and the front material (gl_FrontMaterial). RenderMonkey fed these from its
// camera and its own defaults; docs/rendermonkey.md documents the values below.

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

namespace rmfx {

struct FixedFunctionLight {
    glm::vec4 position{0.0f, 0.0f, 1.0f, 0.0f};  // eye space: a directional light shining from the camera
    glm::vec4 ambient{0.0f, 0.0f, 0.0f, 1.0f};
    glm::vec4 diffuse{1.0f, 1.0f, 1.0f, 1.0f};
    glm::vec4 specular{1.0f, 1.0f, 1.0f, 1.0f};
};

struct FixedFunctionMaterial {
    glm::vec4 ambient{0.2f, 0.2f, 0.2f, 1.0f};
    glm::vec4 diffuse{0.8f, 0.8f, 0.8f, 1.0f};
    glm::vec4 specular{1.0f, 1.0f, 1.0f, 1.0f};
    glm::vec4 emission{0.0f, 0.0f, 0.0f, 1.0f};
    float shininess = 32.0f;
};

// Loads GL_PROJECTION and GL_MODELVIEW (= view · model), and light 0 and the front and back
// material. Needs a current compatibility-profile context; leaves the matrix mode at GL_MODELVIEW.
void loadFixedFunctionState(const glm::mat4& projection, const glm::mat4& modelView,
                            const FixedFunctionLight& light = {}, const FixedFunctionMaterial& material = {});

}  // namespace rmfx
