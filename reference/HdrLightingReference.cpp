#include "reference/HdrLightingReference.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace rmfx::test::hdr {

glm::dvec3 finiteNonNegative(glm::dvec3 c) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(c[i]) || c[i] < 0.0) c[i] = 0.0;
    return c;
}

double luminance(glm::dvec3 c) { return std::max(glm::dot(c, kLuminanceWeights), 0.0); }

RefImage boxDownscale(const RefImage& image, int n) {
    RefImage out((image.width + n - 1) / n, (image.height + n - 1) / n);
    for (int by = 0; by < out.height; ++by)
        for (int bx = 0; bx < out.width; ++bx) {
            glm::dvec3 sum(0.0);
            int count = 0;
            for (int y = by * n; y < std::min(by * n + n, image.height); ++y)
                for (int x = bx * n; x < std::min(bx * n + n, image.width); ++x, ++count)
                    sum += finiteNonNegative(glm::dvec3(image.at(x, y)));
            out.at(bx, by) = glm::dvec4(sum / double(count), 1.0);
        }
    return out;
}

LogAverage logAverage(const RefImage& quarter, const RefImage& scene) {
    LogAverage result;
    double sum = 0.0;
    for (const glm::dvec4& t : quarter.texels) sum += std::log(kLogDelta + luminance(glm::dvec3(t)));
    result.average = std::exp(sum / double(quarter.texels.size()));
    for (const glm::dvec4& t : scene.texels) result.peak = std::max(result.peak, luminance(finiteNonNegative(glm::dvec3(t))));
    return result;
}

double adaptationStep(double adapted, double current, double dt) {
    return adapted + (current - adapted) * (1.0 - std::pow(0.98, 30.0 * dt));
}

double adaptedAfter(double initial, double current, double seconds) {
    return current + (initial - current) * std::pow(0.98, 30.0 * seconds);
}

glm::dvec3 exposeToKey(glm::dvec3 c, double key, double adapted) { return c * (key / (adapted + 0.001)); }

RefImage brightPass(const RefImage& quarter, double adapted, double key) {
    RefImage out = quarter;
    for (glm::dvec4& t : out.texels) {
        glm::dvec3 bright = glm::max(exposeToKey(glm::dvec3(t), key, adapted) - kBrightPassThreshold, 0.0);
        t = glm::dvec4(bright / (kBrightPassOffset + bright), 1.0);
    }
    return out;
}

double gaussianDistribution(double x, double y, double rho) {
    return std::exp(-(x * x + y * y) / (2.0 * rho * rho)) / std::sqrt(2.0 * std::numbers::pi * rho * rho);
}

std::vector<Tap> gauss5x5Kernel() {
    std::vector<Tap> taps;
    double total = 0.0;
    for (int y = -2; y <= 2; ++y)
        for (int x = -2; x <= 2; ++x)
            if (std::abs(x) + std::abs(y) <= 2) {
                taps.push_back({x, y, gaussianDistribution(x, y, 1.0)});
                total += taps.back().weight;
            }
    for (Tap& t : taps) t.weight /= total;
    return taps;
}

std::vector<double> bloomKernel() {
    std::vector<double> weights;
    double total = 0.0;
    for (int i = -7; i <= 7; ++i) {
        weights.push_back(gaussianDistribution(i, 0.0, 3.0));
        total += weights.back();
    }
    for (double& w : weights) w /= total;
    return weights;
}

static glm::dvec3 texelOrBlack(const RefImage& image, int x, int y) {
    if (x < 0 || y < 0 || x >= image.width || y >= image.height) return glm::dvec3(0.0);
    return glm::dvec3(image.at(x, y));
}

RefImage convolve(const RefImage& image, const std::vector<Tap>& taps) {
    RefImage out(image.width, image.height);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            glm::dvec3 sum(0.0);
            for (const Tap& t : taps) sum += t.weight * texelOrBlack(image, x + t.x, y + t.y);
            out.at(x, y) = glm::dvec4(sum, 1.0);
        }
    return out;
}

RefImage bloomPass(const RefImage& image, bool horizontal) {
    std::vector<Tap> taps;
    std::vector<double> weights = bloomKernel();
    for (int i = -7; i <= 7; ++i) taps.push_back({horizontal ? i : 0, horizontal ? 0 : i, weights[size_t(i + 7)]});
    return convolve(image, taps);
}

std::vector<StarLine> starLines(int type) {
    const int counts[5] = {4, 4, 6, 2, 8};
    const double attenuations[4] = {0.85, 0.95, 0.96, 0.96};
    int n = counts[std::clamp(type, 0, 4)];
    double inclination = type == 2 ? 20.0 * std::numbers::pi / 180.0 : 0.0;
    std::vector<StarLine> lines;
    for (int i = 0; i < n; ++i) {
        double attenuation = type == 4 ? (i % 2 == 0 ? 0.95 : 0.88) : attenuations[std::clamp(type, 0, 3)];
        lines.push_back({inclination + 2.0 * std::numbers::pi / n * i, attenuation});
    }
    return lines;
}

glm::dvec3 starColor(int colorRow, int sample, double chromaticAberration) {
    const glm::dvec3 white(0.63);
    const glm::dvec3 chromatic[8] = {{0.5, 0.5, 0.5}, {0.8, 0.3, 0.3}, {1.0, 0.2, 0.2}, {0.5, 0.2, 0.6},
                                     {0.2, 0.2, 1.0}, {0.2, 0.3, 0.7}, {0.2, 0.6, 0.2}, {0.3, 0.5, 0.3}};
    double ratio = (colorRow + 1) / 3.0;
    glm::dvec3 c = chromatic[sample] + (white - chromatic[sample]) * ratio;
    return white + (c - white) * chromaticAberration;
}

std::array<StarTap, 8> starTaps(const StarLine& line, int pass, glm::ivec2 sourceSize, double chromaticAberration) {
    std::array<StarTap, 8> taps{};
    double reach = std::pow(8.0, pass);
    // Direct3D's v points down the screen; GL's up: the sample's (sin, cos) step is (sin, -cos) here.
    glm::dvec2 step = glm::dvec2(std::sin(line.angleRadians), -std::cos(line.angleRadians)) * reach;
    double attenuationScale = (std::atan(std::numbers::pi / 8.0) + 0.1) * 280.0 / (sourceSize.x + sourceSize.y) * 1.2 * reach;
    for (int i = 0; i < 8; ++i) {
        taps[size_t(i)].offset = step * double(i);
        bool dropped = std::fabs(taps[size_t(i)].offset.x) >= 0.9 * sourceSize.x ||
                       std::fabs(taps[size_t(i)].offset.y) >= 0.9 * sourceSize.y;
        taps[size_t(i)].weight = dropped ? glm::dvec3(0.0)
                                         : starColor(2 - pass, i, chromaticAberration) *
                                               (std::pow(line.attenuation, attenuationScale * i) * (pass + 1) * 0.5);
    }
    return taps;
}

glm::dvec3 bilinearOrBlack(const RefImage& image, glm::dvec2 position) {
    glm::dvec2 p = position - 0.5;
    int x = int(std::floor(p.x)), y = int(std::floor(p.y));
    double fx = p.x - x, fy = p.y - y;
    glm::dvec3 bottom = texelOrBlack(image, x, y) * (1 - fx) + texelOrBlack(image, x + 1, y) * fx;
    glm::dvec3 top = texelOrBlack(image, x, y + 1) * (1 - fx) + texelOrBlack(image, x + 1, y + 1) * fx;
    return bottom * (1 - fy) + top * fy;
}

RefImage starLinePass(const RefImage& source, const StarLine& line, int pass, double chromaticAberration) {
    std::array<StarTap, 8> taps = starTaps(line, pass, {source.width, source.height}, chromaticAberration);
    RefImage out(source.width, source.height);
    for (int y = 0; y < source.height; ++y)
        for (int x = 0; x < source.width; ++x) {
            glm::dvec3 sum(0.0);
            for (const StarTap& t : taps)
                if (t.weight != glm::dvec3(0.0)) sum += t.weight * bilinearOrBlack(source, glm::dvec2(x + 0.5, y + 0.5) + t.offset);
            out.at(x, y) = glm::dvec4(sum, 1.0);
        }
    return out;
}

RefImage starMerge(const std::vector<RefImage>& lines) {
    RefImage out(lines.front().width, lines.front().height);
    for (const RefImage& line : lines)
        for (size_t i = 0; i < out.texels.size(); ++i) out.texels[i] += glm::dvec4(glm::dvec3(line.texels[i]), 0.0) / double(lines.size());
    for (glm::dvec4& t : out.texels) t.a = 1.0;
    return out;
}

double blueShiftCoefficient(double adapted) { return std::clamp(1.0 - (adapted + 1.5) / 4.1, 0.0, 1.0); }

glm::dvec3 blueShift(glm::dvec3 c, double adapted) {
    glm::dvec3 rod = glm::dot(c, kLuminanceWeights) * kBlueShiftVector;
    return c + (rod - c) * blueShiftCoefficient(adapted);
}

glm::dvec3 toneMapPerChannel(glm::dvec3 c, double key, double adapted) {
    glm::dvec3 exposed = exposeToKey(c, key, adapted);
    return exposed / (1.0 + exposed);
}

glm::dvec3 toneMapPhotographic(glm::dvec3 c, double key, double adapted, double white) {
    double y = luminance(c);
    if (y <= 0.0) return glm::dvec3(0.0);
    double l = key * y / (adapted + 0.001);
    double ld = l * (1.0 + l / (white * white)) / (1.0 + l);
    return c * (ld / y);
}

RefImage finalComposite(const RefImage& scene, const RefImage& bloom, const RefImage& star, double adapted,
                        double peak, const FinalSettings& s) {
    RefImage out(scene.width, scene.height);
    double white = s.whitePoint > 0.0 ? s.whitePoint : s.key * peak / (adapted + 0.001);
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) {
            glm::dvec3 c = finiteNonNegative(glm::dvec3(scene.at(x, y)));
            if (s.blueShift) c = blueShift(c, adapted);
            if (s.toneMapOperator == 1) c = toneMapPerChannel(c, s.key, adapted);
            if (s.toneMapOperator == 2) c = toneMapPhotographic(c, s.key, adapted, white);
            glm::dvec2 pixel(x + 0.5, y + 0.5);
            c += s.starScale * bilinearOrBlack(star, pixel / 4.0) + s.bloomScale * bilinearOrBlack(bloom, pixel / 8.0);
            out.at(x, y) = glm::dvec4(c, 1.0);
        }
    return out;
}

}  // namespace rmfx::test::hdr
