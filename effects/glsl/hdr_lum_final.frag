// 4x4 -> 1x1, and the exp at the end: r = Lavg = exp(mean(log(delta + Y))), g = the largest
// luminance of the scene. A plain float statistic (rg32f), read by the adaptation and the tone map.
#include "luminance.glsl"
uniform sampler2D Finer;
uniform sampler2D Quarter;  // only its size, which fixes the footprints
out vec4 fragColor;

void main() {
    vec2 reduced = reduceLogLuminance(Finer, ivec2(0), textureSize(Quarter, 0));
    fragColor = vec4(fromLogLuminance(reduced.x), peakFromLogLuminance(reduced.y), 0.0, 1.0);
}
