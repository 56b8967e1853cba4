// The article's tone mapping: 40 % of the blurred highlights over the original, a vignette of
// (1 - r^2)^4 around the centre, the exposure, and a gamma of 0.55; clamped to the largest half
// float so that a large exposure does not write Inf to the rgba16f output.
#include "finite.glsl"
uniform sampler2D FullSampler;
uniform sampler2D BlurSampler;
uniform float fExposureLevel;
in vec2 vTexCoord;
out vec4 fragColor;

void main() {
    vec4 original = texture(FullSampler, vTexCoord);
    // Without the bloom effect (rmfx render --effects "") nothing is blurred: 0, as the blur of a
    // downsample with nothing above 1 gives.
    vec4 blur = RMFX_EFFECT_bloom ? texture(BlurSampler, vTexCoord) : vec4(0.0);
    vec4 color = mix(original, blur, 0.4);
    vec2 fromCentre = vTexCoord - 0.5;
    float vignette = 1.0 - dot(fromCentre, fromCentre);
    color *= pow(vignette, 4.0);
    color *= fExposureLevel;
    fragColor = vec4(clampToHalfFloat(pow(finiteNonNegative(color.rgb), vec3(0.55))), 1.0);
}
