#include "gl/GlLimits.h"

#include <algorithm>

#include <epoxy/gl.h>

namespace rmfx {

int queryMaxTargetSize() {
    GLint texture = 0, renderbuffer = 0, viewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    int limit = texture;
    for (GLint v : {renderbuffer, viewport[0], viewport[1]})
        if (v > 0) limit = std::min(limit, static_cast<int>(v));
    return limit > 0 ? limit : 1024;  // GL 4.5 guarantees at least 16384; 1024 if the query failed
}


}  // namespace rmfx
