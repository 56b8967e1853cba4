#version 450 core
uniform sampler2D source;
uniform vec2 Offset;
in vec2 vTexCoord;
out vec4 color;
void main() { color = texture(source, vTexCoord + Offset); }
