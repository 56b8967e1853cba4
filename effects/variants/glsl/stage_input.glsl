#pragma once
// The stage workspaces' input image and the contract's sanitising and luminance: S is the Input
// texel with NaN, ±Inf and negative channels as 0; Y is its Rec.709 luminance.
#include "../../glsl/finite.glsl"

uniform sampler2D Input;

vec3 sanitisedInput(ivec2 pixel) { return finiteNonNegative(texelFetch(Input, pixel, 0).rgb); }

float rec709Luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }
