// One glare blur pass: the chapter's 9-sample Gauss filter, the 3x3 binomial (1 2 1)/4 x (1 2 1)/4,
// sampling Texture0 one texel of the target being rendered apart. The chapter's table lists
// (-1, 1) twice and misses (-1, -1); the four corners here are the four diagonals.
uniform sampler2D Texture0;
uniform vec2 rm_InvTargetSize;
in vec2 vTexCoord;
out vec4 fragColor;

const vec4 samples[9] = vec4[9](
    vec4(-1.0, -1.0, 0.0, 1.0 / 16.0),
    vec4(-1.0,  1.0, 0.0, 1.0 / 16.0),
    vec4( 1.0, -1.0, 0.0, 1.0 / 16.0),
    vec4( 1.0,  1.0, 0.0, 1.0 / 16.0),
    vec4(-1.0,  0.0, 0.0, 2.0 / 16.0),
    vec4( 1.0,  0.0, 0.0, 2.0 / 16.0),
    vec4( 0.0, -1.0, 0.0, 2.0 / 16.0),
    vec4( 0.0,  1.0, 0.0, 2.0 / 16.0),
    vec4( 0.0,  0.0, 0.0, 4.0 / 16.0));

void main() {
    vec4 color = vec4(0.0);
    for (int i = 0; i < 9; i++)
        color += samples[i].w * texture(Texture0, vTexCoord + samples[i].xy * rm_InvTargetSize);
    fragColor = color;
}
