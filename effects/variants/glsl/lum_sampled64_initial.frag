// sampled64, step 2 (the 64x64 level of effects/hdr_lighting.xml's chain, on the downsampled
// Input): per texel, the mean of log(delta + Y) over the downsampled texels of its footprint, which
// partition the image (luminance.glsl), and the largest of their Y.
#include "stage_input.glsl"
#include "variant_target.glsl"
#include "../../glsl/luminance.glsl"
uniform sampler2D Downsampled;
uniform float Luminance_Delta;
uniform vec2 rm_TargetSize;
out vec4 fragColor;

void main() {
    ivec2 k = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(Downsampled, 0);
    ivec2 start = footprintStart(k, ivec2(rm_TargetSize), size);
    ivec2 end = footprintEnd(k, ivec2(rm_TargetSize), size);
    float sum = 0.0, peak = 0.0;
    for (int y = start.y; y < end.y; ++y)
        for (int x = start.x; x < end.x; ++x) {
            float luminance = rec709Luminance(loadTarget(Downsampled, ivec2(x, y)));
            sum += log(Luminance_Delta + luminance);
            peak = max(peak, luminance);
        }
    ivec2 span = end - start;
    fragColor = storeLogLevel(span.x * span.y > 0 ? sum / float(span.x * span.y) : 0.0, peak);
}
