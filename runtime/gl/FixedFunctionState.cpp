#include "gl/FixedFunctionState.h"

#include <epoxy/gl.h>
#include <glm/gtc/type_ptr.hpp>

namespace rmfx {

void loadFixedFunctionState(const glm::mat4& projection, const glm::mat4& modelView, const FixedFunctionLight& light,
                            const FixedFunctionMaterial& material) {
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(glm::value_ptr(projection));
    glMatrixMode(GL_MODELVIEW);
    // GL transforms a light position by the modelview matrix current when it is set: with the
    // identity, the position is taken in eye space.
    glLoadIdentity();
    glLightfv(GL_LIGHT0, GL_POSITION, glm::value_ptr(light.position));
    glLightfv(GL_LIGHT0, GL_AMBIENT, glm::value_ptr(light.ambient));
    glLightfv(GL_LIGHT0, GL_DIFFUSE, glm::value_ptr(light.diffuse));
    glLightfv(GL_LIGHT0, GL_SPECULAR, glm::value_ptr(light.specular));
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, glm::value_ptr(material.ambient));
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, glm::value_ptr(material.diffuse));
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, glm::value_ptr(material.specular));
    glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, glm::value_ptr(material.emission));
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, material.shininess);
    glLoadMatrixf(glm::value_ptr(modelView));
}

}  // namespace rmfx
