// input_scene.frag for an rgba8 scene in the chapter's alpha-64 encoding (alpha64.glsl): the
// multiplier is the largest channel, at least 1, rounded up to a step of 64/255 so that rgb stays
// within 0..1; colours above 64 saturate there, as the encoding does.
#include "alpha64.glsl"
#include "finite.glsl"
uniform sampler2D Input_Image;
uniform float Exposure_Level;
out vec4 fragColor;

void main() {
    vec3 color = finiteNonNegative(texelFetch(Input_Image, ivec2(gl_FragCoord.xy), 0).rgb) * Exposure_Level;
    float peak = max(max(color.r, color.g), color.b);
    float multiplier = min(ceil(max(peak, 1.0) / 64.0 * 255.0) / 255.0 * 64.0, 64.0);
    fragColor = encodeAlpha64(min(color / multiplier, vec3(1.0)), multiplier);
}
