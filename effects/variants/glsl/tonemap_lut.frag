// Tone map with Ld / L looked up in a table by log2(L), linearly filtered (clamped at its ends),
// and the exact sRGB OETF.
#include "photographic_tonemap.glsl"
#include "variant_target.glsl"
uniform sampler2D Hdr;
uniform sampler2D Curve_Lut;
out vec4 fragColor;

void main() {
    vec3 rgb = loadTarget(Hdr, ivec2(gl_FragCoord.xy));
    float l = scaledLuminance(rgb);
    int entries = textureSize(Curve_Lut, 0).x;
    float ratio = l > 0.0 ? texture(Curve_Lut, vec2(curveLutCoordinate(log2(l), entries), 0.5)).r : 1.0;
    fragColor = vec4(srgbEncode(toneMapped(rgb, ratio)), 1.0);
}
