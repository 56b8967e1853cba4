#pragma once
// Filters over images read with loadHDR (decode first, then filter). Coordinates are in texels of
// the image read: texel (i, j) covers [i, i+1) x [j, j+1), its centre at (i + 0.5, j + 0.5).
#include "hdr_storage.glsl"
#include "finite.glsl"

// A texel, or black outside the image: the DirectX sample keeps a one-texel black border around
// its glare textures so that blurs and star lines fade out at the edges instead of smearing them.
// The overloads with `encoding` decode with it instead of HDR_Encoding.
vec3 loadHDROrBlack(sampler2D image, ivec2 texel, int encoding) {
    ivec2 size = textureSize(image, 0);
    if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, size))) return vec3(0.0);
    return loadHDR(image, texel, encoding);
}
vec3 loadHDROrBlack(sampler2D image, ivec2 texel) { return loadHDROrBlack(image, texel, HDR_Encoding); }

// Bilinear interpolation at `position` (in texels) with black outside the image.
vec3 bilinearHDROrBlack(sampler2D image, vec2 position, int encoding) {
    vec2 p = position - 0.5;
    ivec2 i = ivec2(floor(p));
    vec2 f = p - vec2(i);
    vec3 bottom = mix(loadHDROrBlack(image, i, encoding), loadHDROrBlack(image, i + ivec2(1, 0), encoding), f.x);
    vec3 top = mix(loadHDROrBlack(image, i + ivec2(0, 1), encoding), loadHDROrBlack(image, i + ivec2(1, 1), encoding), f.x);
    return mix(bottom, top, f.y);
}
vec3 bilinearHDROrBlack(sampler2D image, vec2 position) { return bilinearHDROrBlack(image, position, HDR_Encoding); }

// Exact mean of the texels of the block [block * n, block * n + n) that lie inside the image,
// each made finite and non-negative and then reduced to its part above `threshold`,
// max(c - threshold, 0) (a bright pass; threshold 0 keeps c): blocks at the right and top edges of
// an image whose size is not a multiple of n average the texels they have, so every texel counts
// once, in one block.
vec3 boxAverageBrightHDR(sampler2D image, ivec2 block, int n, int encoding, float threshold) {
    ivec2 size = textureSize(image, 0);
    ivec2 start = block * n;
    ivec2 end = min(start + n, size);
    vec3 sum = vec3(0.0);
    for (int y = start.y; y < end.y; ++y)
        for (int x = start.x; x < end.x; ++x)
            sum += max(finiteNonNegative(loadHDR(image, ivec2(x, y), encoding)) - threshold, vec3(0.0));
    ivec2 count = max(end - start, ivec2(1));
    return sum / float(count.x * count.y);
}
vec3 boxAverageHDR(sampler2D image, ivec2 block, int n) { return boxAverageBrightHDR(image, block, n, HDR_Encoding, 0.0); }
