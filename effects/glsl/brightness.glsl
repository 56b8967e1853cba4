#pragma once
// "Brightness" of an HDR colour for automatic exposure: Rec.709 luminance of the colour after
// NaN and negative channels become 0 and +Inf becomes 65504 (the largest half float, what the
// rgba16f scene can hold), so one bad pixel cannot turn the average into NaN or Inf.
#include "finite.glsl"

float sanitisedChannel(float c) {
    if (!isFiniteFloat(c)) return floatBitsToUint(c) == 0x7F800000u ? 65504.0 : 0.0;  // +Inf, or NaN / -Inf
    return c > 0.0 ? min(c, 65504.0) : 0.0;
}

float brightness(vec3 color) {
    vec3 c = vec3(sanitisedChannel(color.r), sanitisedChannel(color.g), sanitisedChannel(color.b));
    return dot(c, vec3(0.2126, 0.7152, 0.0722));
}
