// histogram, the 1x1 result: the pixels sorted by bin, those with ranks between Histogram_Low and
// Histogram_High of the count (partial bins weigh the part inside), each standing for its bin's
// centre: r = exp(their mean of log(delta + 2^centre)), g = the largest Y. With Low >= High the
// bin at rank Low stands alone.
#include "log_histogram.glsl"
uniform sampler2D Histogram;
uniform float Luminance_Delta;
uniform float Histogram_Low;
uniform float Histogram_High;
out vec4 fragColor;

float binCount(int bin) { return texelFetch(Histogram, ivec2(bin / 4, 0), 0)[bin % 4]; }
float binLogLuminance(int bin) { return log(Luminance_Delta + exp2(histogramBinCentreLog2(bin))); }

void main() {
    vec4 stats = texelFetch(Histogram, ivec2(HISTOGRAM_STATS_TEXEL, 0), 0);
    float total = stats.g;
    float low = clamp(Histogram_Low, 0.0, 1.0) * total;
    float high = max(clamp(Histogram_High, 0.0, 1.0) * total, low);
    float below = 0.0, sum = 0.0, weight = 0.0;
    int atLow = -1, lastNonEmpty = 0;
    for (int bin = 0; bin < histogramBins(); ++bin) {
        float count = binCount(bin);
        if (count == 0.0) continue;
        float inside = max(min(below + count, high) - max(below, low), 0.0);
        sum += inside * binLogLuminance(bin);
        weight += inside;
        if (atLow < 0 && below + count > low) atLow = bin;
        lastNonEmpty = bin;
        below += count;
    }
    float mean = weight > 0.0 ? sum / weight : binLogLuminance(atLow >= 0 ? atLow : lastNonEmpty);
    fragColor = vec4(exp(mean), stats.r, 0.0, 1.0);
}
