#include "gl/GlRenderState.h"

#include <epoxy/gl.h>

#include "gl/GlFormats.h"

namespace rmfx {

void applyRenderState(const Pass& pass) {
    if (pass.blend.enabled) {
        glEnable(GL_BLEND);
        glBlendFuncSeparate(gl::blendFactor(pass.blend.srcColor), gl::blendFactor(pass.blend.dstColor),
                            gl::blendFactor(pass.blend.srcAlpha), gl::blendFactor(pass.blend.dstAlpha));
        glBlendEquationSeparate(gl::blendEquation(pass.blend.colorOp), gl::blendEquation(pass.blend.alphaOp));
        glBlendColor(pass.blend.constant.r, pass.blend.constant.g, pass.blend.constant.b, pass.blend.constant.a);
    } else {
        glDisable(GL_BLEND);
    }
    if (pass.depth.test || pass.depth.write) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(pass.depth.test ? gl::compareFunc(pass.depth.func) : GL_ALWAYS);
    } else {
        glDisable(GL_DEPTH_TEST);
    }
    glDepthMask(pass.depth.write ? GL_TRUE : GL_FALSE);
    if (pass.raster.cull == CullFace::None) {
        glDisable(GL_CULL_FACE);
    } else {
        glEnable(GL_CULL_FACE);
        glCullFace(pass.raster.cull == CullFace::Back ? GL_BACK : GL_FRONT);
    }
    glFrontFace(pass.raster.frontCounterClockwise ? GL_CCW : GL_CW);
}

}  // namespace rmfx
