// Tone map with the curve computed per pixel and sqrt (gamma 2) in place of the sRGB OETF.
#include "photographic_tonemap.glsl"
#include "variant_target.glsl"
uniform sampler2D Hdr;
out vec4 fragColor;

void main() {
    vec3 rgb = loadTarget(Hdr, ivec2(gl_FragCoord.xy));
    fragColor = vec4(sqrt(toneMapped(rgb, photographicRatio(scaledLuminance(rgb)))), 1.0);
}
