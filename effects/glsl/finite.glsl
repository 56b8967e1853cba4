#pragma once
// Finite-value tests on the bits: GLSL's isnan/isinf may be compiled away (a compiler may assume
// no NaN or Inf), and min/max need not drop a NaN. hdr_filter.glsl includes this file.
bool isFiniteFloat(float x) { return (floatBitsToUint(x) & 0x7F800000u) != 0x7F800000u; }
bvec3 isFiniteVec3(vec3 c) { return notEqual(floatBitsToUint(c) & 0x7F800000u, uvec3(0x7F800000u)); }

// NaN, ±Inf and negative channels as 0, tested on the bits: one bad texel would otherwise spread
// through every average, blur and the log-average luminance.
vec3 finiteNonNegative(vec3 c) {
    bvec3 finite = isFiniteVec3(c);
    return vec3(finite.x && c.x > 0.0 ? c.x : 0.0, finite.y && c.y > 0.0 ? c.y : 0.0, finite.z && c.z > 0.0 ? c.z : 0.0);
}

// The largest finite half float: what a float colour written to an rgba16f target is clamped to,
// so that a bright value times a large exposure does not turn into Inf there.
const float HALF_FLOAT_MAX = 65504.0;
vec3 clampToHalfFloat(vec3 c) { return min(c, vec3(HALF_FLOAT_MAX)); }
