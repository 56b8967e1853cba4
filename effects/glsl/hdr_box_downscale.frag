// Exact Box_Size x Box_Size box average (the scene to the quarter image, 4x4; the star source to
// the bloom source, 2x2).
#include "hdr_filter.glsl"
uniform sampler2D Source;
uniform int Box_Size;
out vec4 fragColor;

void main() { fragColor = storeHDR(boxAverageHDR(Source, ivec2(gl_FragCoord.xy), Box_Size)); }
