// The sample's GaussBlur5x5: the 13 texels with |x| + |y| <= 2, Gaussian weights (rho 1) summing to 1.
#include "hdr_filter.glsl"
#include "gaussian.glsl"
uniform sampler2D Source;
out vec4 fragColor;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 sum = vec3(0.0);
    float total = 0.0;
    for (int y = -2; y <= 2; ++y)
        for (int x = -2; x <= 2; ++x) {
            if (abs(x) + abs(y) > 2) continue;
            float w = gaussianDistribution(float(x), float(y), 1.0);
            sum += w * loadHDROrBlack(Source, p + ivec2(x, y));
            total += w;
        }
    fragColor = storeHDR(sum / total);
}
