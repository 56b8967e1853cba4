// One ghost pass (shader_4): the source (Texture0) at the four scaled coordinates of ghost.vert,
// each masked by the alpha of the circular mask (Texture1) at the same coordinate, summed and
// scaled by Glow_Factor. Both samplers clamp, so coordinates outside [0, 1] read the mask's
// transparent edge. Four samples at Glow_Factor up to 1 can exceed the largest half float: clamped.
#include "finite.glsl"
uniform float Glow_Factor;
uniform sampler2D Texture0;
uniform sampler2D Texture1;
in vec2 texCoord1;
in vec2 texCoord2;
in vec2 texCoord3;
in vec2 texCoord4;
out vec4 fragColor;

void main() {
    vec4 col1 = texture(Texture0, texCoord1) * texture(Texture1, texCoord1).a;
    vec4 col2 = texture(Texture0, texCoord2) * texture(Texture1, texCoord2).a;
    vec4 col3 = texture(Texture0, texCoord3) * texture(Texture1, texCoord3).a;
    vec4 col4 = texture(Texture0, texCoord4) * texture(Texture1, texCoord4).a;
    vec4 sum = (col1 + col2 + col3 + col4) * Glow_Factor;
    fragColor = vec4(clampToHalfFloat(sum.rgb), sum.a);
}
