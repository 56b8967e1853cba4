// The streak composite of exercise 2 on 8-bit targets: each texel decoded from its alpha
// intensity (alpha64.glsl) before streak_combine.glsl weighs and sums it.
#include "alpha64.glsl"
#include "streak_combine.glsl"

vec3 streakColor(vec4 texel) { return decodeAlpha64(texel); }
