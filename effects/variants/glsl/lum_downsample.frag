// sampled64, step 1: Input to the Downsample size by an exact box average of the sanitised pixels
// (edge blocks average the pixels they have), stored in Target_Format.
#include "variant_target.glsl"
#include "stage_input.glsl"
uniform vec2 rm_TargetSize;
out vec4 fragColor;

void main() {
    int n = reductionFactor(textureSize(Input, 0), ivec2(rm_TargetSize));
    fragColor = storeTarget(boxAverageBrightHDR(Input, ivec2(gl_FragCoord.xy), n, 0, 0.0));
}
