#include "gl/HealthBuffer.h"

#include <epoxy/gl.h>

namespace rmfx {

int healthBufferBinding() {
    GLint bindings = 0;
    glGetIntegerv(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS, &bindings);
    return bindings > 0 ? bindings - 1 : 0;
}

}  // namespace rmfx
