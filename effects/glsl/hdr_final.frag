// The sample's final pass: blue shift under low light, tone mapping (Tone_Map_Operator: 0 none,
// 1 the sample's per-channel operator, 2 Reinhard et al.'s photographic operator), then the star
// and the bloom, already in display range, added on top when their effects run.
#include "hdr_filter.glsl"
#include "tonemap.glsl"
#include "blue_shift.glsl"
uniform sampler2D Scene;
uniform sampler2D Bloom;
uniform sampler2D Star;
uniform sampler2D Adapted;
uniform sampler2D Measured;
uniform float Middle_Gray;
uniform float White_Point;
uniform float Bloom_Scale;
uniform float Star_Scale;
uniform int Tone_Map_Operator;
uniform bool Blue_Shift;
out vec4 fragColor;

void main() {
    vec3 c = finiteNonNegative(loadHDR(Scene, ivec2(gl_FragCoord.xy)));
    float adapted = texelFetch(Adapted, ivec2(0), 0).r;
    if (Blue_Shift) c = blueShift(c, adapted);
    if (Tone_Map_Operator == 1) {
        c = toneMapPerChannel(c, Middle_Gray, adapted);
    } else if (Tone_Map_Operator == 2) {
        // 0: the image's largest luminance, scaled like every other, maps to white.
        float peak = texelFetch(Measured, ivec2(0), 0).g;
        float white = White_Point > 0.0 ? White_Point : peak * exposureScale(Middle_Gray, adapted);
        c = toneMapPhotographic(c, Middle_Gray, adapted, white);
    }
    // Quarter and eighth texels cover 4x4 and 8x8 scene pixels exactly (see hdr_filter.glsl).
    if (RMFX_EFFECT_star) c += Star_Scale * bilinearHDROrBlack(Star, gl_FragCoord.xy / 4.0);
    if (RMFX_EFFECT_bloom) c += Bloom_Scale * bilinearHDROrBlack(Bloom, gl_FragCoord.xy / 8.0);
    fragColor = vec4(c, 1.0);
}
