// Copies a target to the screen as it is (the screen clips to 0..1 when written to 8 bits).
uniform sampler2D Texture0;
in vec2 vTexCoord;
out vec4 fragColor;

void main() { fragColor = texture(Texture0, vTexCoord); }
