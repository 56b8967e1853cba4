#version 450 core
// Adapted luminance: moves towards the luminance of the small image's mean by Speed each frame.
uniform sampler2D previous;
uniform sampler2D small;
uniform float Speed;
out vec4 color;
void main() {
    vec3 mean = textureLod(small, vec2(0.5), 20.0).rgb;  // the top of the mip chain
    float current = max(dot(mean, vec3(0.2126, 0.7152, 0.0722)), 1e-4);
    float adapted = texelFetch(previous, ivec2(0), 0).r;
    color = vec4(vec3(mix(adapted, current, Speed)), 1.0);
}
