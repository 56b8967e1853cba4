// The reflective teapot of shader_6: a mirror of the environment, intensity in alpha.
#include "environment_alpha64.glsl"
uniform vec3 rm_CameraPosition;
in vec3 vWorldPosition;
in vec3 vWorldNormal;
out vec4 fragColor;

void main() {
    vec3 view = normalize(vWorldPosition - rm_CameraPosition);
    fragColor = environmentAlpha64(reflect(view, normalize(vWorldNormal)));
}
