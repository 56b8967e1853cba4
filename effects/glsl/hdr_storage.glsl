#pragma once
// How the HDR pipeline's colour images (scene, quarter, bright pass, bloom and star images) are
// written and read: every pass writes them with storeHDR and reads them with loadHDR, one texel at
// a time, in the encoding HDR_Encoding picks (hdr_encoding.glsl: 0 float, 1 RGB16, 2 RGB32,
// 3 RGB9E5, 4 RGBE8, 5 RGBA8x64); the targets' formats follow the same variable (format-by).
// An encoded texel must be decoded before it is filtered, so filtering is done after loadHDR, in
// hdr_filter.glsl. The log-luminance chain and the 1x1 statistics are plain float targets, not
// written through here (see luminance.glsl).
#include "hdr_encoding.glsl"

vec4 storeHDR(vec3 color) { return encodeHDR(color); }

// A pipeline whose targets use only some encodings may define HDR_DECODE(texel, encoding) before
// including this file, so that its shaders compile only those decoders: every filter tap inlines
// one, and RGB32's double maths alone costs llvmpipe about a second per shader.
#ifndef HDR_DECODE
#define HDR_DECODE(texel, encoding) decodeHDR(texel, encoding)
#endif

// Texel `texel` of an image written with storeHDR, decoded; the caller keeps it inside the image.
// The overload with `encoding` serves pipelines whose selector is not HDR_Encoding.
vec3 loadHDR(sampler2D image, ivec2 texel, int encoding) { return HDR_DECODE(texelFetch(image, texel, 0), encoding); }
vec3 loadHDR(sampler2D image, ivec2 texel) { return loadHDR(image, texel, HDR_Encoding); }
