#pragma once
// The streak composite (shader_3): the four directions, each weighted by Glow_Factor with alpha
// 0.15, summed and clamped to 1, so it is blended (src-alpha, one) onto the screen at alpha 0.6.
// The including shader defines streakColor, which turns a texel of a streak target into colour.
uniform float Glow_Factor;
uniform sampler2D Texture0;
uniform sampler2D Texture1;
uniform sampler2D Texture2;
uniform sampler2D Texture3;
in vec2 vTexCoord;
out vec4 fragColor;

vec3 streakColor(vec4 texel);

void main() {
    fragColor = min(vec4(1.0),
                    vec4(streakColor(texture(Texture0, vTexCoord)) * Glow_Factor, 0.15) +
                    vec4(streakColor(texture(Texture1, vTexCoord)) * Glow_Factor, 0.15) +
                    vec4(streakColor(texture(Texture2, vTexCoord)) * Glow_Factor, 0.15) +
                    vec4(streakColor(texture(Texture3, vTexCoord)) * Glow_Factor, 0.15));
}
