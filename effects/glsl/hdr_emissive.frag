// An emissive light (Light_Index 0, 1) or the panel (2): its radiance, unlit.
#include "hdr_storage.glsl"
#include "hdr_scene.glsl"
uniform int Light_Index;
out vec4 fragColor;

void main() { fragColor = storeHDR(emission(Light_Index)); }
