// Exact log-average, the 1x1 result: every texel of the last level merged, r = exp(mean of
// log(delta + Y)) over all Input pixels, g = the largest Y.
#include "exact_log_mean.glsl"
uniform sampler2D Finer;
out vec4 fragColor;

void main() {
    ivec2 finerSize = textureSize(Finer, 0);
    LogMeanSum s = emptyLogMeanSum();
    for (int y = 0; y < finerSize.y; ++y)
        for (int x = 0; x < finerSize.x; ++x) addLevelTexel(s, texelFetch(Finer, ivec2(x, y), 0));
    fragColor = vec4(expOfMean(s), s.peak, 0.0, 1.0);
}
