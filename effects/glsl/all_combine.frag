// The composite of shader_5: the glare levels weighted by Glow_Factor, Glow_Factor2 and
// Glow_Factor3 (alpha 1), the ghosts as they are (Texture0) and the four streaks weighted by
// Streak_Factor, blended additively (src-alpha, one) onto the scene on the screen. Unlike the
// streak composite of shader_3 nothing is clamped.
uniform float Glow_Factor;
uniform float Glow_Factor2;
uniform float Glow_Factor3;
uniform float Streak_Factor;
uniform sampler2D Texture0;
uniform sampler2D Texture1;
uniform sampler2D Texture2;
uniform sampler2D Texture3;
uniform sampler2D Texture4;
uniform sampler2D Texture5;
uniform sampler2D Texture6;
uniform sampler2D Texture7;
in vec2 vTexCoord;
out vec4 fragColor;

void main() {
    vec4 col;

    // Glow
    col = vec4(texture(Texture1, vTexCoord).rgb * Glow_Factor, 1.0) +
          vec4(texture(Texture2, vTexCoord).rgb * Glow_Factor2, 0.0) +
          vec4(texture(Texture3, vTexCoord).rgb * Glow_Factor3, 0.0);

    // Ghost
    col += vec4(texture(Texture0, vTexCoord).rgb, 0.0);

    // Streak
    col += vec4(texture(Texture4, vTexCoord).rgb * Streak_Factor, 0.0) +
           vec4(texture(Texture5, vTexCoord).rgb * Streak_Factor, 0.0) +
           vec4(texture(Texture6, vTexCoord).rgb * Streak_Factor, 0.0) +
           vec4(texture(Texture7, vTexCoord).rgb * Streak_Factor, 0.0);

    fragColor = col;
}
