#include "reference/AutoExposureReference.h"

#include <algorithm>
#include <cmath>

namespace rmfx::test {

double sanitisedBrightness(glm::dvec3 rgb) {
    auto channel = [](double c) { return std::isnan(c) || c < 0.0 ? 0.0 : std::min(c, 65504.0); };
    return 0.2126 * channel(rgb.r) + 0.7152 * channel(rgb.g) + 0.0722 * channel(rgb.b);
}

double meanBrightness(const RefImage& scene) {
    double sum = 0.0;
    for (const glm::dvec4& t : scene.texels) sum += sanitisedBrightness(glm::dvec3(t));
    return sum / static_cast<double>(scene.texels.size());
}

RefImage brightnessLevel(const RefImage& scene, int level) {
    const int span = 1 << level;
    RefImage out((scene.width + span - 1) / span, (scene.height + span - 1) / span);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            double sum = 0.0, count = 0.0;
            for (int sy = y * span; sy < std::min((y + 1) * span, scene.height); ++sy)
                for (int sx = x * span; sx < std::min((x + 1) * span, scene.width); ++sx) {
                    sum += sanitisedBrightness(glm::dvec3(scene.at(sx, sy)));
                    count += 1.0;
                }
            out.at(x, y) = glm::dvec4(sum / count, count, 0.0, 1.0);
        }
    return out;
}

std::vector<glm::ivec2> chainSizes(glm::ivec2 viewport) {
    std::vector<glm::ivec2> sizes;
    glm::ivec2 size = viewport;
    do {
        size = (size + 1) / 2;
        sizes.push_back(size);
    } while (size != glm::ivec2(1));
    return sizes;
}

double naiveChainMean(const RefImage& scene) {
    RefImage level(scene.width, scene.height);
    for (size_t i = 0; i < scene.texels.size(); ++i)
        level.texels[i] = glm::dvec4(sanitisedBrightness(glm::dvec3(scene.texels[i])));
    while (level.width > 1 || level.height > 1) {
        RefImage next(std::max(1, level.width / 2), std::max(1, level.height / 2));
        for (int y = 0; y < next.height; ++y)
            for (int x = 0; x < next.width; ++x)
                next.at(x, y) = 0.25 * (fetchClamped(level, 2 * x, 2 * y) + fetchClamped(level, 2 * x + 1, 2 * y) +
                                        fetchClamped(level, 2 * x, 2 * y + 1) + fetchClamped(level, 2 * x + 1, 2 * y + 1));
        level = std::move(next);
    }
    return level.at(0, 0).r;
}

double targetExposure(double averageBrightness, double floor) { return 0.5 / std::max(averageBrightness, floor); }

double exposureAfterFrames(double initial, double target, double speed, int frames) {
    double e = initial;
    for (int i = 0; i < frames; ++i) e = e + (target - e) * speed;
    return e;
}

}  // namespace rmfx::test
