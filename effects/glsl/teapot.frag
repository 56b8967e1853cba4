// The reflective teapot: a mirror of the environment, scaled by the exposure (shader_1),
// clamped to what the half-float scene holds.
#include "environment.glsl"
uniform float Exposure_Level;
uniform vec3 rm_CameraPosition;
in vec3 vWorldPosition;
in vec3 vWorldNormal;
out vec4 fragColor;

void main() {
    vec3 view = normalize(vWorldPosition - rm_CameraPosition);
    vec3 direction = reflect(view, normalize(vWorldNormal));
    fragColor = vec4(clampToHalfFloat(environmentColor(direction) * Exposure_Level), 1.0);
}
