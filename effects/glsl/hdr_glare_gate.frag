// The glare's gate (1x1, <effect gate>): 1 where the bright pass may write a non-zero pixel this
// frame, 0 only where it writes zero everywhere (bright_pass.glsl), from the brightest channel of
// the quarter image that the luminance chain carries (measured.b). Where it is 0, content skip
// leaves out the bright pass, its blur and the bloom and star that start from them: two 1x1 draws
// decide what a 1/4-size bright pass and its count would.
#include "bright_pass.glsl"
uniform sampler2D Measured;
uniform sampler2D Adapted;
uniform float Middle_Gray;
out vec4 fragColor;

void main() {
    float brightest = texelFetch(Measured, ivec2(0), 0).b;
    float adapted = texelFetch(Adapted, ivec2(0), 0).r;
    fragColor = vec4(brightPassMayPass(brightest, Middle_Gray, adapted) ? 1.0 : 0.0, 0.0, 0.0, 1.0);
}
