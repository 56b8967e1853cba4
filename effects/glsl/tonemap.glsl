#pragma once
// Tone mapping of the HDRLighting sample, and Reinhard et al. 2002's global photographic operator.
#include "luminance.glsl"

// The scale that maps the adapted luminance to the key (middle gray); the 0.001 floor keeps a
// black scene from dividing by zero.
float exposureScale(float key, float adaptedLuminance) { return key / (adaptedLuminance + 0.001); }
vec3 exposeToKey(vec3 c, float key, float adaptedLuminance) { return c * exposureScale(key, adaptedLuminance); }

// The sample's operator, per channel: c / (1 + c) of the exposed colour.
vec3 toneMapPerChannel(vec3 c, float key, float adaptedLuminance) {
    vec3 exposed = exposeToKey(c, key, adaptedLuminance);
    return exposed / (1.0 + exposed);
}

// Reinhard et al. 2002, equation 4, on luminance: L = key Y / Lavg, Ld = L (1 + L / Lwhite²) / (1 + L),
// the colour scaled by Ld / Y. Lwhite (in units of L) is the smallest scaled luminance that maps to 1.
vec3 toneMapPhotographic(vec3 c, float key, float adaptedLuminance, float whitePoint) {
    float y = luminance(c);
    if (y <= 0.0) return vec3(0.0);
    float l = y * exposureScale(key, adaptedLuminance);
    float white2 = max(whitePoint * whitePoint, 1e-12);
    float ld = l * (1.0 + l / white2) / (1.0 + l);
    return c * (ld / y);
}
