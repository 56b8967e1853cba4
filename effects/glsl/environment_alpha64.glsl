#pragma once
// The scene of shader_6 on 8-bit targets: the 8-bit environment's colour is kept as it is and its
// brightness (1 + 64 a), times the exposure, goes to alpha (alpha64.glsl) instead of being applied.
#include "alpha64.glsl"
uniform samplerCube Environment;
uniform float Exposure_Level;

vec4 environmentAlpha64(vec3 direction) {
    vec4 color = texture(Environment, direction);
    return encodeAlpha64(color.rgb, (1.0 + color.a * 64.0) * Exposure_Level);
}
