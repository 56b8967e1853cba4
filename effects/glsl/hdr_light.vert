// Places the unit sphere at light Light_Index's position and radius, from the same table that
// lights the surfaces (hdr_scene.glsl), so the two cannot disagree.
#include "hdr_scene.glsl"
layout(location = 0) in vec3 rm_Position;
uniform mat4 rm_ViewProjection;
uniform int Light_Index;

void main() {
    vec3 world = LIGHT_POSITION[Light_Index] + LIGHT_RADIUS[Light_Index] * rm_Position;
    gl_Position = rm_ViewProjection * vec4(world, 1.0);
}
