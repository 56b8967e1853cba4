// sampled64, the 1x1 result from the 4x4 level: r = exp(the footprint-weighted mean of
// log(delta + Y)), g = the largest Y of the downsampled image (not of Input: this variant never
// reads Input at full resolution after step 1).
#include "../../glsl/luminance.glsl"
uniform sampler2D Finer;
uniform sampler2D Quarter;  // the downsampled image; only its size, which fixes the footprints
out vec4 fragColor;

void main() {
    vec2 reduced = reduceLogLuminance(Finer, ivec2(0), textureSize(Quarter, 0)).xy;
    fragColor = vec4(exp(reduced.x), reduced.y, 0.0, 1.0);
}
