// The streak composite of shader_3 on half-float targets (streak_combine.glsl).
#include "streak_combine.glsl"

vec3 streakColor(vec4 texel) { return texel.rgb; }
