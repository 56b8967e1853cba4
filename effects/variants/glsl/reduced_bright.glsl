#pragma once
// The first pass of the bloom and streak stages: the input sanitised (NaN, ±Inf and negatives as
// 0), its bright part B = max(S - threshold, 0) box-averaged exactly into the reduced target.
#include "variant_target.glsl"
#include "stage_input.glsl"

uniform vec2 rm_TargetSize;

vec4 reducedBright(float threshold) {
    int n = reductionFactor(textureSize(Input, 0), ivec2(rm_TargetSize));
    return storeTarget(boxAverageBrightHDR(Input, ivec2(gl_FragCoord.xy), n, 0, threshold));
}
