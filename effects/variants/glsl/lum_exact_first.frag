// Exact log-average, first level: each texel covers a block of Input pixels.
#include "exact_log_mean.glsl"
uniform vec2 rm_TargetSize;
out vec4 fragColor;

void main() {
    ivec2 k = ivec2(gl_FragCoord.xy);
    ivec2 inputSize = textureSize(Input, 0);
    ivec2 start = blockStart(k, inputSize, ivec2(rm_TargetSize));
    ivec2 end = blockEnd(k, inputSize, ivec2(rm_TargetSize));
    LogMeanSum s = emptyLogMeanSum();
    for (int y = start.y; y < end.y; ++y)
        for (int x = start.x; x < end.x; ++x) addPixel(s, sanitisedInput(ivec2(x, y)));
    fragColor = storeLogMean(s);
}
