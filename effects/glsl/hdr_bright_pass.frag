// The sample's bright-pass filter (bright_pass.glsl).
#include "hdr_storage.glsl"
#include "bright_pass.glsl"
uniform sampler2D Quarter;
uniform sampler2D Adapted;
uniform float Middle_Gray;
out vec4 fragColor;

void main() {
    vec3 c = loadHDR(Quarter, ivec2(gl_FragCoord.xy));
    float adapted = texelFetch(Adapted, ivec2(0), 0).r;
    fragColor = storeHDR(brightPass(c, Middle_Gray, adapted));
}
