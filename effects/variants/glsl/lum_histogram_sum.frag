// histogram, step 2: the tiles' partial counts added (their peaks: the largest), one row.
#include "log_histogram.glsl"
uniform sampler2D Tiles;
out vec4 fragColor;

void main() {
    int column = int(gl_FragCoord.x);
    int rows = textureSize(Tiles, 0).y;
    vec4 total = vec4(0.0);
    for (int row = 0; row < rows; ++row) {
        vec4 partial = texelFetch(Tiles, ivec2(column, row), 0);
        if (column == HISTOGRAM_STATS_TEXEL) total = vec4(max(total.r, partial.r), total.g + partial.g, 0.0, 0.0);
        else total += partial;
    }
    fragColor = total;
}
