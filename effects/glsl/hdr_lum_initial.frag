// First level of the log-average (64x64): per texel, the mean of log(1 + Y / delta) over the quarter
// texels of its footprint, the log of the largest luminance of the full-size scene pixels under
// it (the white point of the photographic operator is the image's brightest pixel, not the
// brightest 4x4 average), and the brightest channel of those quarter texels as the bright pass
// reads them (at least 0; BRIGHTEST_NOT_FINITE for a texel with a NaN or infinite channel), which
// bounds what the bright pass can write (hdr_glare_gate.frag).
#include "hdr_filter.glsl"
#include "bright_pass.glsl"
#include "luminance.glsl"
uniform sampler2D Quarter;
uniform sampler2D Scene;
uniform vec2 rm_TargetSize;
out vec4 fragColor;

const int QUARTER = 4;  // scene pixels per quarter texel, each way

void main() {
    ivec2 k = ivec2(gl_FragCoord.xy);
    ivec2 quarterSize = textureSize(Quarter, 0);
    ivec2 start = footprintStart(k, ivec2(rm_TargetSize), quarterSize);
    ivec2 end = footprintEnd(k, ivec2(rm_TargetSize), quarterSize);
    float sum = 0.0, brightest = 0.0;
    for (int y = start.y; y < end.y; ++y)
        for (int x = start.x; x < end.x; ++x) {
            vec3 c = loadHDR(Quarter, ivec2(x, y));
            sum += logLuminance(luminance(c));
            brightest = max(brightest, brightestChannel(c));
        }
    ivec2 span = end - start;
    float mean = span.x * span.y > 0 ? sum / float(span.x * span.y) : 0.0;

    ivec2 sceneEnd = min(end * QUARTER, textureSize(Scene, 0));
    float peak = 0.0;
    for (int y = start.y * QUARTER; y < sceneEnd.y; ++y)
        for (int x = start.x * QUARTER; x < sceneEnd.x; ++x)
            peak = max(peak, luminance(finiteNonNegative(loadHDR(Scene, ivec2(x, y)))));
    fragColor = storeLogLevel(mean, logLuminance(peak), brightest);
}
