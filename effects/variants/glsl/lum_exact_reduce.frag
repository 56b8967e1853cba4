// Exact log-average, a further level: each texel merges a block of the finer level's texels,
// weighted by their pixel counts.
#include "exact_log_mean.glsl"
uniform sampler2D Finer;
uniform vec2 rm_TargetSize;
out vec4 fragColor;

void main() {
    ivec2 k = ivec2(gl_FragCoord.xy);
    ivec2 finerSize = textureSize(Finer, 0);
    ivec2 start = blockStart(k, finerSize, ivec2(rm_TargetSize));
    ivec2 end = blockEnd(k, finerSize, ivec2(rm_TargetSize));
    LogMeanSum s = emptyLogMeanSum();
    for (int y = start.y; y < end.y; ++y)
        for (int x = start.x; x < end.x; ++x) addLevelTexel(s, texelFetch(Finer, ivec2(x, y), 0));
    fragColor = storeLogMean(s);
}
