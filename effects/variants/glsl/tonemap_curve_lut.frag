// The LUT variants' table (an r32f row): texel i holds Ld / L at log2(L) = curveLutLog2(i).
#include "photographic_tonemap.glsl"
uniform vec2 rm_TargetSize;
out vec4 fragColor;

void main() {
    float log2L = curveLutLog2(int(gl_FragCoord.x), int(rm_TargetSize.x));
    fragColor = vec4(photographicRatio(exp2(log2L)), 0.0, 0.0, 1.0);
}
