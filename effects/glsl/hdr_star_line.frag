// Pass Star_Pass (0, 1, 2) of line Star_Line of the star. All STAR_MAX_LINES x STAR_PASSES passes
// are declared; lines beyond the type's count write black and are not merged.
#include "hdr_filter.glsl"
#include "star.glsl"
uniform sampler2D Star_Input;
uniform int Star_Type;
uniform int Star_Line;
uniform int Star_Pass;
uniform float Chromatic_Aberration;
out vec4 fragColor;

void main() {
    if (Star_Line >= starLineCount(Star_Type)) {
        fragColor = storeHDR(vec3(0.0));
        return;
    }
    vec2 size = vec2(textureSize(Star_Input, 0));
    float reach = pow(float(STAR_SAMPLES), float(Star_Pass));
    float angle = starLineAngle(Star_Type, Star_Line);
    // The sample steps (sin, cos) in Direct3D texture space, v pointing down: -cos with v up.
    vec2 step = vec2(sin(angle), -cos(angle)) * reach;
    // The sample's attenuation exponent per texel, scaled to the star source's size.
    float attenuationScale = (atan(3.14159265358979 / 8.0) + 0.1) * 280.0 / (size.x + size.y) * 1.2 * reach;
    float attenuation = starAttenuation(Star_Type, Star_Line);
    vec3 sum = vec3(0.0);
    for (int i = 0; i < STAR_SAMPLES; ++i) {
        vec2 offset = step * float(i);
        if (any(greaterThanEqual(abs(offset), 0.9 * size))) continue;  // the sample drops taps 0.9 of the image away
        vec3 weight = starColor(STAR_PASSES - 1 - Star_Pass, i, Chromatic_Aberration) *
                      (pow(attenuation, attenuationScale * float(i)) * float(Star_Pass + 1) * 0.5);
        sum += weight * bilinearHDROrBlack(Star_Input, gl_FragCoord.xy + offset);
    }
    fragColor = storeHDR(sum);
}
