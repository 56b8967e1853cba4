// One streak pass (shader_3): the chapter's 4-sample filter along one diagonal. Sample i lies
// offsetFactor * i texels (of the target being rendered) along `direction` and weighs
// blurFactor^(offsetFactor * i). The weights are not normalised, as in the chapter: a pass gains
// 1 + 0.96 + 0.96^2 + 0.96^3 = 3.77 with offsetFactor 1 and 1 + 0.96^4 + 0.96^8 + 0.96^12 = 3.18
// with offsetFactor 4, 12 in all; so the sum is clamped to the largest half float (finite.glsl).
#include "finite.glsl"
uniform sampler2D Texture0;
uniform vec2 rm_InvTargetSize;
uniform vec2 direction;      // pass constant: (+-1, +-1) in texture space (+y up)
uniform float offsetFactor;  // pass constant: 1 in the first pass, 4 in the second
in vec2 vTexCoord;
out vec4 fragColor;

const float blurFactor = 0.96;
const vec4 samples[4] = vec4[4](
    vec4(0.0, 0.0, 0.0, 0.0),
    vec4(1.0, 1.0, 0.0, 1.0),
    vec4(2.0, 2.0, 0.0, 2.0),
    vec4(3.0, 3.0, 0.0, 3.0));

void main() {
    vec4 color = vec4(0.0);
    for (int i = 0; i < 4; i++)
        color += pow(blurFactor, offsetFactor * samples[i].w) *
                 texture(Texture0, vTexCoord + offsetFactor * samples[i].xy * direction * rm_InvTargetSize);
    fragColor = vec4(clampToHalfFloat(color.rgb), color.a);
}
