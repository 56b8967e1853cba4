#pragma once
// The chapter's 8-bit intensity encoding for render targets (shader_6): colour in rgb (0..1),
// the HDR multiplier / 64 in alpha, so an rgba8 target holds multipliers 0 .. 64 in steps of 64/255.
vec4 encodeAlpha64(vec3 rgb, float multiplier) { return vec4(rgb, multiplier / 64.0); }
vec3 decodeAlpha64(vec4 color) { return color.rgb * (color.a * 64.0); }
