#pragma once
// How the HDR pipeline's intermediate images (scene, quarter, luminance chain, bright pass, bloom
// and star sources) are written and read: every pass writes them with storeHDR and reads them
// with loadHDR, one texel at a time (an encoded texel must be decoded before it is filtered, so
// filtering is done after loadHDR, in hdr_filter.glsl). Both are the identity on float targets
// today; the HDR encodings (RGB16, RGB9E5, RGBE8, ...) plug in here and nowhere else.

vec4 storeHDR(vec3 color) { return vec4(color, 1.0); }

// Texel `texel` of an image written with storeHDR; the caller keeps it inside the image.
vec3 loadHDR(sampler2D image, ivec2 texel) { return texelFetch(image, texel, 0).rgb; }
