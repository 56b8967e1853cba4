#include "reference/LuminanceVariantsReference.h"

#include <algorithm>
#include <cmath>

#include "reference/StageInput.h"

namespace rmfx::test {

LogAverage logAverage(const RefImage& image, double delta) {
    double sum = 0.0, peak = 0.0;
    for (const glm::dvec4& texel : image.texels) {
        double y = rec709Luminance(sanitisedTexel(texel));
        sum += std::log(delta + y);
        peak = std::max(peak, y);
    }
    return {std::exp(sum / static_cast<double>(image.texels.size())), peak};
}

RefImage boxDownsampled(const RefImage& input, int factor) {
    RefImage out((input.width + factor - 1) / factor, (input.height + factor - 1) / factor);
    for (int by = 0; by < out.height; ++by)
        for (int bx = 0; bx < out.width; ++bx) {
            glm::dvec3 sum(0.0);
            int count = 0;
            for (int y = by * factor; y < std::min((by + 1) * factor, input.height); ++y)
                for (int x = bx * factor; x < std::min((bx + 1) * factor, input.width); ++x, ++count)
                    sum += sanitisedTexel(input.at(x, y));
            out.at(bx, by) = glm::dvec4(sum / static_cast<double>(count), 1.0);
        }
    return out;
}

int histogramBin(double y, const HistogramSettings& s) {
    if (!(y > 0.0)) return 0;
    double width = (s.maxLog2 - s.minLog2) / s.bins;
    double position = std::floor((std::log2(y) - s.minLog2) / width);
    return static_cast<int>(std::clamp(position, 0.0, static_cast<double>(s.bins - 1)));
}

double histogramBinCentreLog2(int bin, const HistogramSettings& s) {
    return s.minLog2 + (bin + 0.5) * (s.maxLog2 - s.minLog2) / s.bins;
}

std::vector<double> logHistogram(const RefImage& input, const HistogramSettings& settings) {
    std::vector<double> counts(settings.bins, 0.0);
    for (const glm::dvec4& texel : input.texels) counts[histogramBin(rec709Luminance(sanitisedTexel(texel)), settings)] += 1.0;
    return counts;
}

LogAverage histogramLogAverage(const RefImage& input, double delta, const HistogramSettings& settings) {
    std::vector<double> counts = logHistogram(input, settings);
    auto binLog = [&](int bin) { return std::log(delta + std::exp2(histogramBinCentreLog2(bin, settings))); };
    double total = static_cast<double>(input.texels.size());
    double low = std::clamp(settings.low, 0.0, 1.0) * total;
    double high = std::max(std::clamp(settings.high, 0.0, 1.0) * total, low);
    double below = 0.0, sum = 0.0, weight = 0.0;
    int atLow = -1, lastNonEmpty = 0;
    for (int bin = 0; bin < settings.bins; ++bin) {
        double count = counts[bin];
        if (count == 0.0) continue;
        double inside = std::max(std::min(below + count, high) - std::max(below, low), 0.0);
        sum += inside * binLog(bin);
        weight += inside;
        if (atLow < 0 && below + count > low) atLow = bin;
        lastNonEmpty = bin;
        below += count;
    }
    double mean = weight > 0.0 ? sum / weight : binLog(atLow >= 0 ? atLow : lastNonEmpty);
    double peak = 0.0;
    for (const glm::dvec4& texel : input.texels) peak = std::max(peak, rec709Luminance(sanitisedTexel(texel)));
    return {std::exp(mean), peak};
}

}  // namespace rmfx::test
