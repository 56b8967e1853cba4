#include "gl/GlRenderState.h"

#include <epoxy/gl.h>

#include "gl/GlFormats.h"

namespace rmfx {

namespace {

GLenum polygonMode(PolygonMode mode) {
    return mode == PolygonMode::Line ? GL_LINE : mode == PolygonMode::Point ? GL_POINT : GL_FILL;
}

bool sameBlend(const BlendState& a, const BlendState& b) {
    return a.srcColor == b.srcColor && a.dstColor == b.dstColor && a.srcAlpha == b.srcAlpha && a.dstAlpha == b.dstAlpha &&
           a.colorOp == b.colorOp && a.alphaOp == b.alphaOp && a.constant == b.constant;
}

// Calls `set` when `value` differs from what `known` says the context holds.
template <class T, class Set>
void setIfChanged(std::optional<T>& known, const T& value, Set set) {
    if (known == value) return;
    set();
    known = value;
}

}  // namespace

void GlRenderState::enable(unsigned cap, bool on, std::optional<bool>& known) {
    setIfChanged(known, on, [&] { on ? glEnable(cap) : glDisable(cap); });
}

void GlRenderState::apply(const Pass& pass, bool compatibility, bool rowsTopFirst) {
    const GLenum front = polygonMode(pass.raster.frontMode), back = polygonMode(pass.raster.backMode);
    if (compatibility) {
        setIfChanged(polygonFront_, front, [&] { glPolygonMode(GL_FRONT, front); });
        setIfChanged(polygonBack_, back, [&] { glPolygonMode(GL_BACK, back); });
        setIfChanged(lineWidth_, pass.raster.lineWidth, [&] { glLineWidth(pass.raster.lineWidth); });
    } else if (polygonFront_ != front || polygonBack_ != front) {
        glPolygonMode(GL_FRONT_AND_BACK, front);
        polygonFront_ = polygonBack_ = front;
    }
    enable(GL_BLEND, pass.blend.enabled, blend_);
    if (pass.blend.enabled && !(blendState_ && sameBlend(*blendState_, pass.blend))) {
        glBlendFuncSeparate(gl::blendFactor(pass.blend.srcColor), gl::blendFactor(pass.blend.dstColor),
                            gl::blendFactor(pass.blend.srcAlpha), gl::blendFactor(pass.blend.dstAlpha));
        glBlendEquationSeparate(gl::blendEquation(pass.blend.colorOp), gl::blendEquation(pass.blend.alphaOp));
        glBlendColor(pass.blend.constant.r, pass.blend.constant.g, pass.blend.constant.b, pass.blend.constant.a);
        blendState_ = pass.blend;
    }
    const bool depth = pass.depth.test || pass.depth.write;
    enable(GL_DEPTH_TEST, depth, depthTest_);
    if (depth) {
        const GLenum func = pass.depth.test ? gl::compareFunc(pass.depth.func) : GL_ALWAYS;
        setIfChanged(depthFunc_, func, [&] { glDepthFunc(func); });
    }
    depthMask(pass.depth.write);
    enable(GL_CULL_FACE, pass.raster.cull != CullFace::None, cull_);
    if (pass.raster.cull != CullFace::None) {
        const GLenum face = pass.raster.cull == CullFace::Back ? GL_BACK : GL_FRONT;
        setIfChanged(cullFace_, face, [&] { glCullFace(face); });
    }
    // The winding is as the picture shows it; drawn top row first, GL's window y runs down it.
    const GLenum winding = pass.raster.frontCounterClockwise != rowsTopFirst ? GL_CCW : GL_CW;
    setIfChanged(frontFace_, winding, [&] { glFrontFace(winding); });
}

void GlRenderState::restoreFilledPolygons(const Pass& pass, bool compatibility) {
    if (pass.raster.frontMode != PolygonMode::Fill || pass.raster.backMode != PolygonMode::Fill) {
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        polygonFront_ = polygonBack_ = GL_FILL;
    }
    if (compatibility && pass.raster.lineWidth != 1.0f) {
        glLineWidth(1.0f);
        lineWidth_ = 1.0f;
    }
}

void GlRenderState::depthMask(bool write) {
    setIfChanged(depthMask_, write, [&] { glDepthMask(write ? GL_TRUE : GL_FALSE); });
}

}  // namespace rmfx
