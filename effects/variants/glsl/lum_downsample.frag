// sampled64, step 1: Input to the Downsample size by an exact box average of the sanitised pixels
// (edge blocks average the pixels they have), stored in Target_Format. Needs the pass constant
// HDR_Encoding = 0: boxAverageHDR reads Input, a float texture, through loadHDR.
#include "stage_input.glsl"
#include "target_format.glsl"
#include "downsample_factor.glsl"
uniform vec2 rm_TargetSize;
out vec4 fragColor;

void main() {
    int n = downsampleFactor(textureSize(Input, 0), ivec2(rm_TargetSize));
    fragColor = storeTarget(boxAverageHDR(Input, ivec2(gl_FragCoord.xy), n));
}
