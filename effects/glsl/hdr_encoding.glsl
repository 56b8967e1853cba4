#pragma once
// HDR colour in integer target formats (docs/encodings.md). encodeX(rgb) returns the texel to write
// into a target of the encoding's format; decodeX(texel) takes the texel as texelFetch returns it.
// HDR_Encoding picks one: 0 float, 1 RGB16, 2 RGB32, 3 RGB9E5, 4 RGBE8, 5 RGBA8x64, for
// encodeHDR / decodeHDR; a target's format follows it with <target format="..." format-by="HDR_Encoding">.
//
// Packed texels (all but float and RGB16) must be fetched, not filtered: decode, then filter.
// The C++ twins (runtime/HdrEncoding.cpp) repeat these operations in the same order; `precise`
// keeps the compiler from fusing or reordering them, so the integer codes agree bit for bit.

uniform int HDR_Encoding;

const float HDR_RGB16_MAX = 100.0;
const float HDR_RGB32_MAX = 10000.0;
const float HDR_RGB9E5_MAX = 65408.0;      // 511/512 * 2^16
const float HDR_RGBA8X64_MAX = 65.0;

// NaN and negatives to 0, then at most limit (clamp alone leaves NaN undefined).
vec3 hdrSanitize(vec3 c, float limit) {
    return clamp(mix(c, vec3(0.0), isnan(c)), 0.0, limit);
}

float hdrPeak(vec3 c) { return max(c.r, max(c.g, c.b)); }

// Integer codes <-> texel channels: k / 255 in rgba8, k / 65535 in rgba16.
uvec4 hdrCodes(vec4 texel, float unit) {
    precise vec4 scaled = floor(clamp(texel, 0.0, 1.0) * unit + 0.5);
    return uvec4(scaled);
}
vec4 hdrTexel(uvec4 codes, float unit) { return vec4(codes) / unit; }

uvec4 hdrBytes(uint word) { return (uvec4(word) >> uvec4(0u, 8u, 16u, 24u)) & 255u; }
uint hdrWord(uvec4 bytes) { return bytes.x | (bytes.y << 8) | (bytes.z << 16) | (bytes.w << 24); }

// RGB16: linear over [0, 100] in 16-bit unorm channels (the D3D10 sample's x65536 wraps 100 to 0).
vec4 encodeRGB16(vec3 rgb) {
    precise vec3 q = floor(hdrSanitize(rgb, HDR_RGB16_MAX) * 655.35 + 0.5);
    return hdrTexel(uvec4(uvec3(q), 65535u), 65535.0);
}
vec3 decodeRGB16(vec4 texel) {
    precise vec3 c = vec3(hdrCodes(texel, 65535.0).rgb) * (100.0 / 65535.0);
    return c;
}

// RGB32: linear over [0, 10000] in 32-bit codes, computed in double (a float has 24 bits). The
// three codes travel as four 24-bit integers, which an rgba32f target holds exactly.
vec4 encodeRGB32(vec3 rgb) {
    precise dvec3 q = floor(dvec3(hdrSanitize(rgb, HDR_RGB32_MAX)) * 429496.7295LF + 0.5LF);
    uvec3 u = uvec3(q);
    return vec4(uvec4(u.r & 0xFFFFFFu, (u.r >> 24) | ((u.g & 0xFFFFu) << 8), (u.g >> 16) | ((u.b & 0xFFu) << 16),
                      u.b >> 8));
}
vec3 decodeRGB32(vec4 texel) {
    uvec4 k = uvec4(texel);
    uvec3 u = uvec3(k.x | (k.y << 24), (k.y >> 8) | (k.z << 16), (k.z >> 16) | (k.w << 8));
    precise dvec3 c = dvec3(u) * (10000.0LF / 4294967295.0LF);
    return vec3(c);
}

// RGB9E5 (EXT_texture_shared_exponent), the 32-bit word in the four bytes of an rgba8 texel:
// GL_RGB9_E5 itself is not colour-renderable.
uint hdrPackRGB9E5(vec3 rgb) {
    vec3 c = hdrSanitize(rgb, HDR_RGB9E5_MAX);
    float peak = hdrPeak(c);
    int log2Peak = -16;  // floor(log2(peak)) exactly, from frexp; at least -16
    if (peak >= 1.52587890625e-5) {
        frexp(peak, log2Peak);
        log2Peak -= 1;
    }
    int e = log2Peak + 16;  // biased shared exponent: floor(log2) + 1 + 15; a mantissa step is 2^(e - 24)
    precise float peakMantissa = floor(ldexp(peak, 24 - e) + 0.5);
    if (peakMantissa == 512.0) e += 1;
    precise vec3 m = floor(ldexp(c, ivec3(24 - e)) + 0.5);
    uvec3 u = uvec3(m);
    return u.r | (u.g << 9) | (u.b << 18) | (uint(e) << 27);
}
vec3 hdrUnpackRGB9E5(uint bits) {
    uvec3 m = (uvec3(bits) >> uvec3(0u, 9u, 18u)) & 511u;
    return ldexp(vec3(m), ivec3(int(bits >> 27) - 24));
}
vec4 encodeRGB9E5(vec3 rgb) { return hdrTexel(hdrBytes(hdrPackRGB9E5(rgb)), 255.0); }
vec3 decodeRGB9E5(vec4 texel) { return hdrUnpackRGB9E5(hdrWord(hdrCodes(texel, 255.0))); }

// RGBE8 (Ward's Radiance format): zero below 1e-32, never NaN; exponent byte 0 is black.
vec4 encodeRGBE8(vec3 rgb) {
    vec3 c = hdrSanitize(rgb, ldexp(255.0, 119));
    float peak = hdrPeak(c);
    if (!(peak > 1e-32)) return vec4(0.0);
    int e;
    frexp(peak, e);
    // Ward's frexp mantissa * 256 / peak is exactly 2^(8 - e); scaling by it loses nothing.
    uvec3 m = uvec3(floor(ldexp(c, ivec3(8 - e))));
    return hdrTexel(uvec4(m, uint(e + 128)), 255.0);
}
vec3 decodeRGBE8(vec4 texel) {
    uvec4 k = hdrCodes(texel, 255.0);
    if (k.a == 0u) return vec3(0.0);
    return ldexp(vec3(k.rgb) + 0.5, ivec3(int(k.a) - 136));
}

// The chapter's rgb * (1 + 64 a) in rgba8: the smallest alpha step whose multiplier covers the
// peak; above 65 the colour is scaled down keeping its hue.
vec4 encodeRGBA8x64(vec3 rgb) {
    precise vec3 c = hdrSanitize(rgb, 1e30);
    float peak = hdrPeak(c);
    if (peak > HDR_RGBA8X64_MAX) c = c * (HDR_RGBA8X64_MAX * (1.0 / peak));
    peak = min(peak, HDR_RGBA8X64_MAX);
    precise float alpha = peak > 1.0 ? min(ceil((peak - 1.0) * (255.0 / 64.0)), 255.0) : 0.0;
    precise float multiplier = 1.0 + 64.0 * (alpha * (1.0 / 255.0));
    precise float inverse = 1.0 / multiplier;
    precise vec3 q = floor(clamp(c * inverse, 0.0, 1.0) * 255.0 + 0.5);
    return hdrTexel(uvec4(uvec3(q), uint(alpha)), 255.0);
}
vec3 decodeRGBA8x64(vec4 texel) {
    uvec4 k = hdrCodes(texel, 255.0);
    precise vec3 c = vec3(k.rgb) * (1.0 / 255.0) * (1.0 + 64.0 * (float(k.a) * (1.0 / 255.0)));
    return c;
}

vec4 encodeHDR(vec3 rgb, int encoding) {
    switch (encoding) {
        case 1: return encodeRGB16(rgb);
        case 2: return encodeRGB32(rgb);
        case 3: return encodeRGB9E5(rgb);
        case 4: return encodeRGBE8(rgb);
        case 5: return encodeRGBA8x64(rgb);
        default: return vec4(rgb, 1.0);
    }
}
vec3 decodeHDR(vec4 texel, int encoding) {
    switch (encoding) {
        case 1: return decodeRGB16(texel);
        case 2: return decodeRGB32(texel);
        case 3: return decodeRGB9E5(texel);
        case 4: return decodeRGBE8(texel);
        case 5: return decodeRGBA8x64(texel);
        default: return texel.rgb;
    }
}
vec4 encodeHDR(vec3 rgb) { return encodeHDR(rgb, HDR_Encoding); }
vec3 decodeHDR(vec4 texel) { return decodeHDR(texel, HDR_Encoding); }
