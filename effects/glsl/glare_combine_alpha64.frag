// The glare composite of shader_6: as glare_combine.frag, each level decoded from its 8-bit
// alpha intensity first.
#include "alpha64.glsl"
uniform float Glow_Factor;
uniform float Glow_Factor2;
uniform float Glow_Factor3;
uniform sampler2D Texture0;
uniform sampler2D Texture1;
uniform sampler2D Texture2;
in vec2 vTexCoord;
out vec4 fragColor;

void main() {
    fragColor = vec4(decodeAlpha64(texture(Texture0, vTexCoord)) * Glow_Factor, 1.0) +
                vec4(decodeAlpha64(texture(Texture1, vTexCoord)) * Glow_Factor2, 0.0) +
                vec4(decodeAlpha64(texture(Texture2, vTexCoord)) * Glow_Factor3, 0.0);
}
