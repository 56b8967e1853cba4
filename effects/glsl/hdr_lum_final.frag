// 4x4 -> 1x1, and the exp at the end: r = Lavg = exp(mean(log(delta + Y))), g = the largest
// luminance of the scene, b = the brightest channel of the quarter image (the glare's gate reads
// it: hdr_glare_gate.frag). A plain float statistic (rgba32f), read by the adaptation, the gate and
// the tone map.
#include "luminance.glsl"
uniform sampler2D Finer;
uniform sampler2D Quarter;  // only its size, which fixes the footprints
out vec4 fragColor;

void main() {
    vec3 reduced = reduceLogLuminance(Finer, ivec2(0), textureSize(Quarter, 0));
    fragColor = vec4(fromLogLuminance(reduced.x), peakFromLogLuminance(reduced.y), reduced.z, 1.0);
}
