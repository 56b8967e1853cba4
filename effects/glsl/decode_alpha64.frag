// Copies an 8-bit target with intensity in alpha to the screen, decoded to rgb * (a * 64).
#include "alpha64.glsl"
uniform sampler2D Texture0;
in vec2 vTexCoord;
out vec4 fragColor;

void main() { fragColor = vec4(decodeAlpha64(texture(Texture0, vTexCoord)), 1.0); }
