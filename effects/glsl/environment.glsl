#pragma once
// The chapter's HDR environment. Environment is the 8-bit cube map with brightness in alpha,
// decoded as rgb * (1 + 64 a) (multipliers 1 .. 65); Environment_Float holds the same sky in half
// floats (0.02 .. 2000, the sun unclipped). Environment_Format picks one. A float sky may hold NaN,
// Inf or negative texels (a lossy or broken EXR): the filtered sample is made finite and
// non-negative here, the first place the scene reads it, so nothing bad reaches any target.
#include "finite.glsl"
uniform samplerCube Environment;
uniform samplerCube Environment_Float;
uniform int Environment_Format;

vec3 environmentColor(vec3 direction) {
    if (Environment_Format == 1) return finiteNonNegative(texture(Environment_Float, direction).rgb);
    vec4 color = texture(Environment, direction);
    return color.rgb * (1.0 + color.a * 64.0);
}
