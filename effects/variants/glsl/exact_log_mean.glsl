#pragma once
// The levels of the exact log-average (rgba32f). A texel holds the mean of log(delta + Y) over the
// full-resolution pixels it covers as a float pair, r + g (about 48 bits: a float32 mean of two
// million logs would drift by more than the 1e-6 this variant promises), how many pixels that is
// in b (an exact integer up to 2^24), and the largest Y among them in a. Sums are formed in double.
#include "stage_input.glsl"

uniform float Luminance_Delta;

// Source texels [start, end) under texel k of a target of targetSize: blocks of ceil(source /
// target) texels clipped at the source's edge, so that every source texel lies in exactly one
// block whatever the two sizes are (with the runtime's ceil(viewport x scale) sizes a block is
// the level's ratio, 16; trailing blocks can be empty, and then weigh nothing).
ivec2 blockStart(ivec2 k, ivec2 sourceSize, ivec2 targetSize) { return k * ((sourceSize + targetSize - 1) / targetSize); }
ivec2 blockEnd(ivec2 k, ivec2 sourceSize, ivec2 targetSize) {
    return min(blockStart(k + 1, sourceSize, targetSize), sourceSize);
}

struct LogMeanSum {
    double weightedSum;  // sum over the parts of count x mean
    double count;
    float peak;
};

LogMeanSum emptyLogMeanSum() { return LogMeanSum(0.0LF, 0.0LF, 0.0); }

void addPixel(inout LogMeanSum s, vec3 sanitised) {
    float y = rec709Luminance(sanitised);
    s.weightedSum += double(log(Luminance_Delta + y));
    s.count += 1.0LF;
    s.peak = max(s.peak, y);
}

void addLevelTexel(inout LogMeanSum s, vec4 texel) {
    if (texel.b == 0.0) return;
    s.weightedSum += double(texel.b) * (double(texel.r) + double(texel.g));
    s.count += double(texel.b);
    s.peak = max(s.peak, texel.a);
}

double meanOf(LogMeanSum s) { return s.count > 0.0LF ? s.weightedSum / s.count : 0.0LF; }

vec4 storeLogMean(LogMeanSum s) {
    double mean = meanOf(s);
    float high = float(mean);
    return vec4(high, float(mean - double(high)), float(s.count), s.peak);
}

// exp(mean) to float precision: exp of the float part, times 1 + the small remainder.
float expOfMean(LogMeanSum s) {
    double mean = meanOf(s);
    float high = float(mean);
    return float(double(exp(high)) * (1.0LF + (mean - double(high))));
}
