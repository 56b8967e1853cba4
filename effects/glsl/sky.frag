// The sky box: the environment seen through each pixel, scaled by the exposure (shader_1),
// clamped to what the half-float scene holds.
#include "environment.glsl"
uniform float Exposure_Level;
uniform vec3 rm_CameraPosition;
in vec3 vWorldPosition;
out vec4 fragColor;

void main() {
    vec3 direction = normalize(vWorldPosition - rm_CameraPosition);
    fragColor = vec4(clampToHalfFloat(environmentColor(direction) * Exposure_Level), 1.0);
}
