// input_scene.frag for hdr_lighting: the image stored with storeHDR in the encoding HDR_Encoding
// picks, NaN, ±Inf and negative channels as 0.
#include "finite.glsl"
#include "hdr_storage.glsl"
uniform sampler2D Input_Image;
out vec4 fragColor;

void main() { fragColor = storeHDR(clampToHalfFloat(finiteNonNegative(texelFetch(Input_Image, ivec2(gl_FragCoord.xy), 0).rgb))); }
