#include "gl/GlRenderState.h"

#include <epoxy/gl.h>

#include "gl/GlFormats.h"

namespace rmfx {

namespace {

GLenum polygonMode(PolygonMode mode) {
    return mode == PolygonMode::Line ? GL_LINE : mode == PolygonMode::Point ? GL_POINT : GL_FILL;
}

}  // namespace

void applyRenderState(const Pass& pass, bool compatibility, bool rowsTopFirst) {
    if (compatibility) {
        glPolygonMode(GL_FRONT, polygonMode(pass.raster.frontMode));
        glPolygonMode(GL_BACK, polygonMode(pass.raster.backMode));
        glLineWidth(pass.raster.lineWidth);
    } else {
        glPolygonMode(GL_FRONT_AND_BACK, polygonMode(pass.raster.frontMode));
    }
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
    // The winding is as the picture shows it; drawn top row first, GL's window y runs down it.
    glFrontFace(pass.raster.frontCounterClockwise != rowsTopFirst ? GL_CCW : GL_CW);
}

void restoreFilledPolygons(const Pass& pass, bool compatibility) {
    if (pass.raster.frontMode != PolygonMode::Fill || pass.raster.backMode != PolygonMode::Fill)
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    if (compatibility && pass.raster.lineWidth != 1.0f) glLineWidth(1.0f);
}

}  // namespace rmfx
