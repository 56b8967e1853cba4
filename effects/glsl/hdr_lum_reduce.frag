// 64x64 -> 16x16 -> 4x4 of the log-average: weighted means of the log-luminance, max of the peaks
// and of the brightest channels.
#include "luminance.glsl"
uniform sampler2D Finer;
uniform sampler2D Quarter;  // only its size, which fixes the footprints
out vec4 fragColor;

void main() {
    vec3 reduced = reduceLogLuminance(Finer, ivec2(gl_FragCoord.xy), textureSize(Quarter, 0));
    fragColor = storeLogLevel(reduced.x, reduced.y, reduced.z);
}
