#pragma once
// The HDRLighting sample's night vision: under low light the rods dominate, so the colour is
// desaturated and shifted towards blue, fully at adapted luminance -1.5 and not at all from 2.6 up
// (a linear blend over that range, as the sample has it).
#include "luminance.glsl"

const vec3 BLUE_SHIFT_VECTOR = vec3(1.05, 0.97, 1.27);

float blueShiftCoefficient(float adaptedLuminance) { return clamp(1.0 - (adaptedLuminance + 1.5) / 4.1, 0.0, 1.0); }

vec3 blueShift(vec3 c, float adaptedLuminance) {
    vec3 rodColor = dot(c, LUMINANCE_WEIGHTS) * BLUE_SHIFT_VECTOR;
    return mix(c, rodColor, blueShiftCoefficient(adaptedLuminance));
}
