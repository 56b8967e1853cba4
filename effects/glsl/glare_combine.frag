// The glare composite (shader_2): three blur levels weighted by Glow_Factor, Glow_Factor2 and
// Glow_Factor3, alpha 1, blended additively (src-alpha, one) onto the scene on the screen.
uniform float Glow_Factor;
uniform float Glow_Factor2;
uniform float Glow_Factor3;
uniform sampler2D Texture0;
uniform sampler2D Texture1;
uniform sampler2D Texture2;
in vec2 vTexCoord;
out vec4 fragColor;

void main() {
    fragColor = vec4(texture(Texture0, vTexCoord).rgb * Glow_Factor, 1.0) +
                vec4(texture(Texture1, vTexCoord).rgb * Glow_Factor2, 0.0) +
                vec4(texture(Texture2, vTexCoord).rgb * Glow_Factor3, 0.0);
}
