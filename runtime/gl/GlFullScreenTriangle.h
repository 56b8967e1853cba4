#pragma once
// The vertex shader of rmfx's own full-screen draws between passes (content skip's probe, the
// health check): one triangle covering the viewport from gl_VertexID alone, drawn with
// glDrawArrays(GL_TRIANGLES, 0, 3) and an empty vertex array.

namespace rmfx {

inline const char* fullScreenTriangleVertexSource() {
    return R"(#version 450 core
void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
)";
}

}  // namespace rmfx
