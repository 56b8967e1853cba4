#pragma once
// Luminance and the log-average reduction of the HDRLighting sample (Reinhard et al. 2002):
// Lavg = exp(mean(log(delta + Y))) over the texels of the quarter-size scene.

const vec3 LUMINANCE_WEIGHTS = vec3(0.2125, 0.7154, 0.0721);  // the DirectX sample's
const float LOG_DELTA = 0.0001;                                // keeps log finite on black texels

float luminance(vec3 c) { return max(dot(c, LUMINANCE_WEIGHTS), 0.0); }

// The reduction carries log(delta + Y) - log(delta) = log(1 + Y / delta) instead of log(delta + Y):
// the same mean up to the constant log(delta), but never negative. The largest luminance travels
// beside it the same way (log is monotonic, so the max of the logs is the log of the max). The
// chain (r: mean, g: log of the peak) stays in 32-bit floats (rg32f, or rgba32f with a third
// statistic in b) whatever HDR_Encoding is: an absolute error e
// of a log is a relative error e of Lavg or the peak, and the shared-exponent encodings would tie
// the mean's error to the larger log of the peak (RGBE8: up to 2^-8 of ~16, 6%, per level).
// It is read and written as plain floats: logLevel / storeLogLevel.
float logLuminance(float y) { return log(1.0 + y / LOG_DELTA); }
float fromLogLuminance(float s) { return LOG_DELTA * exp(s); }  // delta * exp(mean): exp(mean(log(delta + Y)))
float peakFromLogLuminance(float m) { return LOG_DELTA * (exp(m) - 1.0); }

// A texel of the chain (mean, log of the peak), and what a chain pass writes. A chain in rgba32f
// may carry a third statistic in b (hdr_lighting: the brightest channel, hdr_lum_initial.frag),
// the largest over the footprint like the peak.
vec3 logLevel(sampler2D level, ivec2 texel) { return texelFetch(level, texel, 0).rgb; }
vec4 storeLogLevel(float mean, float logPeak) { return vec4(mean, logPeak, 0.0, 1.0); }
vec4 storeLogLevel(float mean, float logPeak, float largest) { return vec4(mean, logPeak, largest, 1.0); }

// The reduction levels (64², 16², 4², 1²) partition the quarter image exactly: texel k of a level
// n texels wide covers quarter texels [k * size / n, (k + 1) * size / n) (integer division), and
// the four children 4k .. 4k+3 of a texel of the next level cover exactly its span. A span can be
// empty when the quarter image is narrower than the level.
ivec2 footprintStart(ivec2 k, ivec2 levelSize, ivec2 quarterSize) { return k * quarterSize / levelSize; }
ivec2 footprintEnd(ivec2 k, ivec2 levelSize, ivec2 quarterSize) { return (k + 1) * quarterSize / levelSize; }

// Texel k of a reduction level from the level 4x finer: the mean of the children's log-luminance
// means weighted by how many quarter texels each covers, the largest of their peaks, and the
// largest of their third statistics (b; chains that carry one keep it at least 0, as the peak).
vec3 reduceLogLuminance(sampler2D finer, ivec2 k, ivec2 quarterSize) {
    ivec2 finerSize = textureSize(finer, 0);
    float sum = 0.0, weight = 0.0, peak = 0.0, largest = 0.0;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            ivec2 child = 4 * k + ivec2(x, y);
            ivec2 span = footprintEnd(child, finerSize, quarterSize) - footprintStart(child, finerSize, quarterSize);
            float w = float(span.x * span.y);
            if (w == 0.0) continue;
            vec3 v = logLevel(finer, child);
            sum += w * v.x;
            weight += w;
            peak = max(peak, v.y);
            largest = max(largest, v.z);
        }
    return vec3(weight > 0.0 ? sum / weight : 0.0, peak, largest);
}
