// The ghost vertex shader (shader_4), for the full-screen triangle: texCoord maps the target onto
// the source, and texCoord1..4 are it scaled about the centre by -2, 2, -0.6 and 0.6 (a negative
// scale flips). GL's texture space has +y up, so texCoord.y is 0.5 (1 + y) where Direct3D's is
// 0.5 (1 - y); the chapter's "- 1/128" is integer division (0) in HLSL and Direct3D 9's half-texel
// fix is not needed in GL, so neither is ported.
layout(location = 0) in vec4 Pos;
out vec2 texCoord;
out vec2 texCoord1;
out vec2 texCoord2;
out vec2 texCoord3;
out vec2 texCoord4;

void main() {
    gl_Position = vec4(Pos.xy, 0.0, 1.0);
    texCoord = 0.5 * (1.0 + Pos.xy);
    texCoord1 = (texCoord - 0.5) * (-2.0) + 0.5;
    texCoord2 = (texCoord - 0.5) * (2.0) + 0.5;
    texCoord3 = (texCoord - 0.5) * (-0.6) + 0.5;
    texCoord4 = (texCoord - 0.5) * (0.6) + 0.5;
}
