#pragma once
// Whether the current GL context renders on the CPU (Mesa's llvmpipe and softpipe, SwiftShader):
// there a shader's untaken branches cost as much as taken ones, which decides how --check looks
// (gl/GlHealthCheck.h). Needs a current context.

#include <string>

#include <epoxy/gl.h>

namespace rmfx {

inline bool currentContextIsSoftwareRasteriser() {
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const std::string name = renderer ? renderer : "";
    return name.find("llvmpipe") != std::string::npos || name.find("softpipe") != std::string::npos ||
           name.find("SwiftShader") != std::string::npos;
}

}  // namespace rmfx
