// The sky box of shader_6: the environment seen through each pixel, intensity in alpha.
#include "environment_alpha64.glsl"
uniform vec3 rm_CameraPosition;
in vec3 vWorldPosition;
out vec4 fragColor;

void main() { fragColor = environmentAlpha64(normalize(vWorldPosition - rm_CameraPosition)); }
