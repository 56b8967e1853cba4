// The ghost composite (shader_4): the ghosts at alpha 0.8, blended (src-alpha, one) onto the screen.
uniform sampler2D Texture0;
in vec2 vTexCoord;
out vec4 fragColor;

void main() { fragColor = vec4(texture(Texture0, vTexCoord).xyz, 0.8); }
