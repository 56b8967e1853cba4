#pragma once
// The blur kinds of the bloom stage (effects/variants/bloom.xml), each on the bright part at the
// reduced size D, black outside the image. sigma_D, the ideal Gaussian's sigma in texels at D, is
// Bloom_Sigma * H / n for an input H texels high reduced n times. The C++ twin of every parameter
// choice is tests/reference/BloomVariantsReference.cpp.
#include "variant_target.glsl"

uniform sampler2D Input;  // only its size
uniform float Bloom_Sigma;

float bloomSigmaD(ivec2 reducedSize) {
    ivec2 inputSize = textureSize(Input, 0);
    return Bloom_Sigma * float(inputSize.y) / float(reductionFactor(inputSize, reducedSize));
}

// Variance per axis that a bilinear fetch adds at fractional texel position f: f (1 - f).
float bilinearVariance(float offset) {
    float f = fract(offset);
    return f * (1.0 - f);
}

// ---- 9-tap Gauss (gauss9xN, linear9x2) and the 49-tap Gauss ----

// Weights of the 9-tap Gaussian of `sigma`, exp(-k^2 / (2 sigma^2)) for k = 0..4, normalised over
// the 9 taps.
void gauss9Weights(float sigma, out float w[5]) {
    float s = max(sigma, 1e-6);
    float sum = 0.0;
    for (int k = 0; k <= 4; ++k) {
        w[k] = exp(-float(k * k) / (2.0 * s * s));
        sum += k == 0 ? w[k] : 2.0 * w[k];
    }
    for (int k = 0; k <= 4; ++k) w[k] /= sum;
}

vec3 gauss9(sampler2D image, ivec2 texel, ivec2 axis, float sigma) {
    float w[5];
    gauss9Weights(sigma, w);
    vec3 sum = vec3(0.0);
    for (int k = -4; k < unrolledNot(5); ++k) sum += w[abs(k)] * loadTargetOrBlack(image, texel + k * axis);
    return sum;
}

// The same kernel in 5 bilinear fetches: taps k and k+1 (k = 1, 3) merged into one fetch of
// weight w_k + w_k+1 at the offset (k w_k + (k+1) w_k+1) / (w_k + w_k+1) between them.
vec3 linear9(sampler2D image, vec2 centre, vec2 axis, float sigma) {
    float w[5];
    gauss9Weights(sigma, w);
    float pairWeight[2], pairOffset[2];
    for (int j = 0; j < 2; ++j) {
        int k = 2 * j + 1;
        pairWeight[j] = w[k] + w[k + 1];
        pairOffset[j] = pairWeight[j] > 0.0 ? (float(k) * w[k] + float(k + 1) * w[k + 1]) / pairWeight[j] : float(k);
    }
    vec3 sum = vec3(0.0);
    for (int j = -2; j < unrolledNot(3); ++j) {
        float weight = j == 0 ? w[0] : pairWeight[abs(j) - 1];
        float offset = j == 0 ? 0.0 : sign(float(j)) * pairOffset[abs(j) - 1];
        sum += weight * bilinearTargetOrBlack(image, centre + offset * axis);
    }
    return sum;
}

// One pass of the 7x7 Gaussian of `sigma`, normalised over its 49 taps.
vec3 gauss49(sampler2D image, ivec2 texel, float sigma) {
    float s = max(sigma, 1e-6);
    vec3 sum = vec3(0.0);
    float total = 0.0;
    for (int y = -3; y < unrolledNot(4); ++y)
        for (int x = -3; x < unrolledNot(4); ++x) {
            float w = exp(-float(x * x + y * y) / (2.0 * s * s));
            sum += w * loadTargetOrBlack(image, texel + ivec2(x, y));
            total += w;
        }
    return sum / total;
}

// ---- Kawase ----

// Pass j: 4 bilinear taps at (±o, ±o), averaged, with o = s (i_j + 0.5), i = 0, 1, 2, 2, 3. Per axis a pass adds
// o^2 + f (1 - f) (its two tap columns at ±o, each a bilinear blend at fraction f = fract(o)), so
// the chain's variance is V(s) = sum_j s^2 (i_j + 0.5)^2 + f_j (1 - f_j). s solves V(s) = sigma^2
// by bisection between sqrt((sigma^2 - 5/4) / 27.25) and sigma / sqrt(27.25), where
// 27.25 = sum (i_j + 0.5)^2 and V lies between 27.25 s^2 and 27.25 s^2 + 5/4.
const float KAWASE_STEPS[5] = float[5](0.5, 1.5, 2.5, 2.5, 3.5);

float kawaseVariance(float s) {
    float v = 0.0;
    for (int j = 0; j < unrolledNot(5); ++j) v += s * s * KAWASE_STEPS[j] * KAWASE_STEPS[j] + bilinearVariance(s * KAWASE_STEPS[j]);
    return v;
}

float kawaseScale(float sigma) {
    float target = sigma * sigma;
    float lo = sqrt(max(target - 1.25, 0.0) / 27.25), hi = sigma / sqrt(27.25);
    for (int k = 0; k < unrolledNot(24); ++k) {
        float mid = 0.5 * (lo + hi);
        if (kawaseVariance(mid) < target) lo = mid; else hi = mid;
    }
    return 0.5 * (lo + hi);
}

// Each tap loop below runs over a table to unrolledNot(count): one bilinear fetch site per shader.
const vec2 DIAGONALS[4] = vec2[4](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));

vec3 kawase(sampler2D image, vec2 centre, int pass, float sigma) {
    float o = kawaseScale(sigma) * KAWASE_STEPS[pass];
    vec3 sum = vec3(0.0);
    for (int t = 0; t < unrolledNot(4); ++t) sum += bilinearTargetOrBlack(image, centre + o * DIAGONALS[t]);
    return 0.25 * sum;
}

// ---- dual filter (Bjorge 2015) and 13-tap downsample + tent upsample (Jimenez 2014) ----
//
// Both go D -> D/2 -> D/4 and back with every tap offset scaled by one radius r (r = 1: the
// published kernels). Per axis, in texels of the level a pass reads, a kernel of taps at offsets o_t
// with weights w_t, each a bilinear fetch, has variance sum_t w_t (o_t^2 + f_t (1 - f_t)), f_t the
// fetch's fraction. A downsample's centre lies on a texel corner (fraction 1/2 + o_t); an
// upsample's on a quarter texel (fraction o_t ± 1/4 on alternate texels, averaged). A level k
// texel is 2^k D texels, so the chain's variance at D is V = (1 + 4) V_down(r) + (16 + 4) V_up(r):
//   dual down  (4 x centre + 4 diagonals (±r, ±r)) / 8:        1/2 (1/4) + 1/2 (r^2 + b(r + 1/2))
//   dual up    (4 axis (±2r, 0), (0, ±2r) + 2 x 4 diagonals) / 12: 4/3 r^2 + 1/6 q(0) + 1/6 q(2r) + 2/3 q(r)
//   13-tap down (centre 1/8, axis ±2r 1/16, corners ±2r 1/32, inner ±r 1/8):
//                 3/2 r^2 + 1/4 b(1/2) + 1/4 b(2r + 1/2) + 1/2 b(r + 1/2)
//   tent up    (1 2 1) x (1 2 1) / 16 at ±r:                  1/2 r^2 + 1/2 q(0) + 1/2 q(r)
// with b(x) = fract(x) (1 - fract(x)) and q(o) = (b(o - 1/4) + b(o + 1/4)) / 2. r solves
// V(r) = sigma_D^2 by bisection over [0, sigma_D / sqrt(a)] (V >= a r^2, a = 5 * 1/2 + 20 * 4/3 for the dual
// filter, 5 * 3/2 + 20 * 1/2 for the tent); at r = 0 both chains still have V = 5, the smallest
// sigma_D they reach (r = 0 then).
float upsampleBilinearVariance(float o) { return 0.5 * (bilinearVariance(o - 0.25) + bilinearVariance(o + 0.25)); }

float dualFilterVariance(float r) {
    float down = 0.125 + 0.5 * (r * r + bilinearVariance(r + 0.5));
    float up = 4.0 / 3.0 * r * r + (upsampleBilinearVariance(0.0) + upsampleBilinearVariance(2.0 * r)) / 6.0 +
               2.0 / 3.0 * upsampleBilinearVariance(r);
    return 5.0 * down + 20.0 * up;
}

float tent13Variance(float r) {
    float down = 1.5 * r * r + 0.25 * bilinearVariance(0.5) + 0.25 * bilinearVariance(2.0 * r + 0.5) +
                 0.5 * bilinearVariance(r + 0.5);
    float up = 0.5 * r * r + 0.5 * upsampleBilinearVariance(0.0) + 0.5 * upsampleBilinearVariance(r);
    return 5.0 * down + 20.0 * up;
}

// kind 0: dual filter, 1: tent13.
float pyramidRadius(int kind, float sigma) {
    float target = sigma * sigma;
    float a = kind == 0 ? 2.5 + 80.0 / 3.0 : 17.5;
    float lo = 0.0, hi = sigma / sqrt(a);
    for (int k = 0; k < unrolledNot(24); ++k) {
        float mid = 0.5 * (lo + hi);
        float v = kind == 0 ? dualFilterVariance(mid) : tent13Variance(mid);
        if (v < target) lo = mid; else hi = mid;
    }
    return 0.5 * (lo + hi);
}

// Taps (offset in units of r, weight) of the four pyramid kernels.
const vec3 DUAL_DOWN[5] = vec3[5](vec3(0.0, 0.0, 0.5), vec3(-1.0, -1.0, 0.125), vec3(1.0, -1.0, 0.125),
                                  vec3(-1.0, 1.0, 0.125), vec3(1.0, 1.0, 0.125));
const vec3 DUAL_UP[8] = vec3[8](vec3(-2.0, 0.0, 1.0 / 12.0), vec3(2.0, 0.0, 1.0 / 12.0), vec3(0.0, -2.0, 1.0 / 12.0),
                                vec3(0.0, 2.0, 1.0 / 12.0), vec3(-1.0, -1.0, 2.0 / 12.0), vec3(1.0, -1.0, 2.0 / 12.0),
                                vec3(-1.0, 1.0, 2.0 / 12.0), vec3(1.0, 1.0, 2.0 / 12.0));
// Jimenez's 13 taps: five 4x4 boxes (at r = 1), the central one weighted 1/2 and the four corner
// ones 1/8 each, every tap a bilinear fetch on a texel corner.
const vec3 TENT13_DOWN[13] = vec3[13](
    vec3(0.0, 0.0, 0.125), vec3(-1.0, 1.0, 0.125), vec3(1.0, 1.0, 0.125), vec3(-1.0, -1.0, 0.125), vec3(1.0, -1.0, 0.125),
    vec3(0.0, 2.0, 0.0625), vec3(-2.0, 0.0, 0.0625), vec3(2.0, 0.0, 0.0625), vec3(0.0, -2.0, 0.0625),
    vec3(-2.0, 2.0, 0.03125), vec3(2.0, 2.0, 0.03125), vec3(-2.0, -2.0, 0.03125), vec3(2.0, -2.0, 0.03125));
// The 3x3 tent (1 2 1) x (1 2 1) / 16.
const vec3 TENT_UP[9] = vec3[9](vec3(0.0, 0.0, 0.25), vec3(-1.0, 0.0, 0.125), vec3(1.0, 0.0, 0.125), vec3(0.0, -1.0, 0.125),
                                vec3(0.0, 1.0, 0.125), vec3(-1.0, -1.0, 0.0625), vec3(1.0, -1.0, 0.0625),
                                vec3(-1.0, 1.0, 0.0625), vec3(1.0, 1.0, 0.0625));

// A downsample's centre, for texel t of the half-size level, is the source corner 2 t + 1; an
// upsample's, for texel t of the double-size level, is (t + 0.5) / 2 in the source.
#define PYRAMID_PASS(taps, count, centre)                                                           \
    vec3 sum = vec3(0.0);                                                                           \
    for (int t = 0; t < unrolledNot(count); ++t)                                                    \
        sum += taps[t].z * bilinearTargetOrBlack(image, centre + r * taps[t].xy);                   \
    return sum;

vec3 dualDown(sampler2D image, vec2 texelCentre, float r) { PYRAMID_PASS(DUAL_DOWN, 5, 2.0 * texelCentre) }
vec3 dualUp(sampler2D image, vec2 texelCentre, float r) { PYRAMID_PASS(DUAL_UP, 8, 0.5 * texelCentre) }
vec3 tent13Down(sampler2D image, vec2 texelCentre, float r) { PYRAMID_PASS(TENT13_DOWN, 13, 2.0 * texelCentre) }
vec3 tentUp(sampler2D image, vec2 texelCentre, float r) { PYRAMID_PASS(TENT_UP, 9, 0.5 * texelCentre) }
