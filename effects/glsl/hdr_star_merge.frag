// The star: the mean of the type's lines.
#include "hdr_storage.glsl"
#include "star.glsl"
uniform sampler2D Star_Line_0;
uniform sampler2D Star_Line_1;
uniform sampler2D Star_Line_2;
uniform sampler2D Star_Line_3;
uniform sampler2D Star_Line_4;
uniform sampler2D Star_Line_5;
uniform sampler2D Star_Line_6;
uniform sampler2D Star_Line_7;
uniform int Star_Type;
out vec4 fragColor;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int n = starLineCount(Star_Type);
    vec3 sum = loadHDR(Star_Line_0, p) + loadHDR(Star_Line_1, p);
    if (n > 2) sum += loadHDR(Star_Line_2, p) + loadHDR(Star_Line_3, p);
    if (n > 4) sum += loadHDR(Star_Line_4, p) + loadHDR(Star_Line_5, p);
    if (n > 6) sum += loadHDR(Star_Line_6, p) + loadHDR(Star_Line_7, p);
    fragColor = storeHDR(sum / float(n));
}
