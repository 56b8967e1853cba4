// The composite of shader_5: the glare levels weighted by Glow_Factor, Glow_Factor2 and
// Glow_Factor3 (alpha 1), the ghosts as they are (Texture0) and the four streaks weighted by
// Streak_Factor, blended additively (src-alpha, one) onto the scene on the screen. Unlike the
// streak composite of shader_3 nothing is clamped. An effect left out or switched off adds nothing
// and its targets are not sampled.
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
    // Each effect's terms only when it runs (RMFX_EFFECT_*: docs/workspace-format.md), in the
    // chapter's order of additions, so all three give the chapter's sums exactly.
    vec3 rgb = vec3(0.0);

    // Glow
    if (RMFX_EFFECT_glare)
        rgb = texture(Texture1, vTexCoord).rgb * Glow_Factor + texture(Texture2, vTexCoord).rgb * Glow_Factor2 +
              texture(Texture3, vTexCoord).rgb * Glow_Factor3;

    // Ghost
    if (RMFX_EFFECT_ghost) rgb += texture(Texture0, vTexCoord).rgb;

    // Streak
    if (RMFX_EFFECT_streak)
        rgb += texture(Texture4, vTexCoord).rgb * Streak_Factor + texture(Texture5, vTexCoord).rgb * Streak_Factor +
               texture(Texture6, vTexCoord).rgb * Streak_Factor + texture(Texture7, vTexCoord).rgb * Streak_Factor;

    fragColor = vec4(rgb, 1.0);
}
