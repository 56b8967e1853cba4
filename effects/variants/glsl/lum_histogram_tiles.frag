// histogram, step 1: texel (g, t) counts the pixels of tile t of Input (tiles partition it as the
// footprints of luminance.glsl do, 16 x 16 of them) that fall in bins 4g .. 4g + 3; texel
// (HISTOGRAM_STATS_TEXEL, t) holds the tile's largest Y and its pixel count.
#include "stage_input.glsl"
#include "log_histogram.glsl"
#include "../../glsl/luminance.glsl"
out vec4 fragColor;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    ivec2 tile = ivec2(texel.y % HISTOGRAM_TILES, texel.y / HISTOGRAM_TILES);
    ivec2 size = textureSize(Input, 0);
    ivec2 start = footprintStart(tile, ivec2(HISTOGRAM_TILES), size);
    ivec2 end = footprintEnd(tile, ivec2(HISTOGRAM_TILES), size);
    if (texel.x == HISTOGRAM_STATS_TEXEL) {
        float peak = 0.0;
        for (int y = start.y; y < end.y; ++y)
            for (int x = start.x; x < end.x; ++x) peak = max(peak, rec709Luminance(sanitisedInput(ivec2(x, y))));
        ivec2 span = end - start;
        fragColor = vec4(peak, float(span.x * span.y), 0.0, 0.0);
        return;
    }
    int first = 4 * texel.x;
    vec4 counts = vec4(0.0);
    if (first < histogramBins())
        for (int y = start.y; y < end.y; ++y)
            for (int x = start.x; x < end.x; ++x) {
                int slot = histogramBin(rec709Luminance(sanitisedInput(ivec2(x, y)))) - first;
                if (slot >= 0 && slot < 4) counts[slot] += 1.0;
            }
    fragColor = counts;
}
