// Copies the HDR scene to the screen scaled by the automatic exposure (a 1x1 target), clamped to
// the largest half float: a scene that brightens suddenly meets an exposure made for the dark.
#include "finite.glsl"
uniform sampler2D Texture0;
uniform sampler2D Exposure;
in vec2 vTexCoord;
out vec4 fragColor;

void main() {
    vec4 color = texture(Texture0, vTexCoord);
    fragColor = vec4(clampToHalfFloat(color.rgb * texelFetch(Exposure, ivec2(0), 0).r), color.a);
}
