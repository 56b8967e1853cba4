// The sample's bright-pass filter: what stays bright after tone mapping, minus a threshold, mapped
// into 0..1 with a large offset so that lights stand out from lit surfaces.
#include "hdr_storage.glsl"
#include "tonemap.glsl"
uniform sampler2D Quarter;
uniform sampler2D Adapted;
uniform float Middle_Gray;
out vec4 fragColor;

const float BRIGHT_PASS_THRESHOLD = 5.0;
const float BRIGHT_PASS_OFFSET = 10.0;

void main() {
    vec3 c = loadHDR(Quarter, ivec2(gl_FragCoord.xy));
    float adapted = texelFetch(Adapted, ivec2(0), 0).r;
    vec3 bright = max(exposeToKey(c, Middle_Gray, adapted) - BRIGHT_PASS_THRESHOLD, 0.0);
    fragColor = storeHDR(bright / (BRIGHT_PASS_OFFSET + bright));
}
