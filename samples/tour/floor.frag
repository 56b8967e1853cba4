#version 450 core
uniform sampler2D mask;
uniform bool Show_Floor;
in vec2 vTexCoord;
out vec4 color;
void main() {
    float m = texture(mask, vTexCoord * 4.0).r;
    color = vec4(vec3(0.2 + 0.6 * m), Show_Floor ? 0.8 : 0.0);
}
