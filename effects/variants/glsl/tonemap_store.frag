// The tone map stage's input: S · Exposure in Target_Format.
#include "stage_input.glsl"
#include "variant_target.glsl"
uniform float Exposure;
out vec4 fragColor;

void main() { fragColor = storeTarget(sanitisedInput(ivec2(gl_FragCoord.xy)) * Exposure); }
