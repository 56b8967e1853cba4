// An image given with rmfx render --input scene=FILE, in place of the drawn scene: times
// Exposure_Level as the scene's shaders do, NaN, ±Inf and negative channels as 0 (finite.glsl),
// clamped to the largest half float. The image is at the viewport's size (rmfx resamples it), so
// each pixel reads its own texel.
#include "finite.glsl"
uniform sampler2D Input_Image;
uniform float Exposure_Level;
out vec4 fragColor;

void main() {
    vec3 color = finiteNonNegative(texelFetch(Input_Image, ivec2(gl_FragCoord.xy), 0).rgb);
    fragColor = vec4(clampToHalfFloat(color * Exposure_Level), 1.0);
}
