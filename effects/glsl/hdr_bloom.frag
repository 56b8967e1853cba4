// One direction of the separable bloom: 15 taps (-7 .. 7 texels along Blur_Direction), Gaussian
// with deviation 3 as in the sample, normalised to sum to 1.
#include "hdr_filter.glsl"
#include "gaussian.glsl"
uniform sampler2D Source;
uniform vec2 Blur_Direction;
out vec4 fragColor;

const int BLOOM_RADIUS = 7;
const float BLOOM_DEVIATION = 3.0;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 sum = vec3(0.0);
    float total = 0.0;
    for (int i = -BLOOM_RADIUS; i <= BLOOM_RADIUS; ++i) {
        float w = gaussianDistribution(float(i), 0.0, BLOOM_DEVIATION);
        sum += w * loadHDROrBlack(Source, p + i * ivec2(Blur_Direction));
        total += w;
    }
    fragColor = storeHDR(sum / total);
}
