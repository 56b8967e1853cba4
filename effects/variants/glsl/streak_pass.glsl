#pragma once
// One pass of a streak direction at the reduced size D (effects/variants/streak.xml). Per full-size
// diagonal step the weight decays by w = exp(-1 / (Streak_Length H)); at D a texel step is n full
// steps, w_D = w^n. Pass p takes 4 texels at 4^p i steps along the direction (i = 0..3), weighted
// w_D^(4^p i); the first pass also multiplies by 1 - w_D. After P passes a texel holds
// (1 - w_D) sum_{k < 4^P} w_D^k B(x + k u), black outside the image.
#include "variant_target.glsl"

uniform sampler2D Input;  // only its size
uniform float Streak_Length;

vec3 streakPass(sampler2D source, ivec2 texel, ivec2 direction, int pass) {
    ivec2 inputSize = textureSize(Input, 0);
    int n = reductionFactor(inputSize, textureSize(source, 0));
    float stepDecay = float(n) / (Streak_Length * float(inputSize.y));  // -log(w_D)
    int stride = 1 << (2 * pass);
    vec3 sum = vec3(0.0);
    for (int i = 0; i < unrolledNot(4); ++i)
        sum += exp(-stepDecay * float(stride * i)) * loadTargetOrBlack(source, texel + direction * (stride * i));
    return pass == 0 ? (1.0 - exp(-stepDecay)) * sum : sum;
}
