// A lit surface of the HDRLighting scene; Albedo and Glossiness are pass constants.
#include "hdr_storage.glsl"
#include "hdr_scene.glsl"
uniform vec3 Albedo;
uniform float Glossiness;
uniform vec3 rm_CameraPosition;
in vec3 vWorldPosition;
in vec3 vWorldNormal;
out vec4 fragColor;

void main() { fragColor = storeHDR(shadeSurface(Albedo, Glossiness, vWorldPosition, vWorldNormal, rm_CameraPosition)); }
