#include "reference/GlareVariantsReference.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

namespace rmfx::test {
namespace {

glm::dvec3 rgb(const glm::dvec4& c) { return glm::dvec3(c); }

glm::dvec3 fetchOrBlack(const RefImage& image, int x, int y) {
    if (x < 0 || y < 0 || x >= image.width || y >= image.height) return glm::dvec3(0.0);
    return rgb(image.at(x, y));
}

RefImage map(int width, int height, const auto& shade) {
    RefImage out(width, height, glm::dvec4(0.0, 0.0, 0.0, 1.0));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) out.at(x, y) = glm::dvec4(shade(x, y), 1.0);
    return out;
}

double bilinearVariance(double offset) {
    double f = offset - std::floor(offset);
    return f * (1.0 - f);
}
double upsampleBilinearVariance(double o) { return 0.5 * (bilinearVariance(o - 0.25) + bilinearVariance(o + 0.25)); }

const double kKawaseSteps[5] = {0.5, 1.5, 2.5, 2.5, 3.5};

void gauss9Weights(double sigma, double w[5]) {
    double s = std::max(sigma, 1e-6), sum = 0.0;
    for (int k = 0; k <= 4; ++k) {
        w[k] = std::exp(-double(k * k) / (2.0 * s * s));
        sum += k == 0 ? w[k] : 2.0 * w[k];
    }
    for (int k = 0; k <= 4; ++k) w[k] /= sum;
}

RefImage gauss9Pass(const RefImage& src, glm::ivec2 axis, double sigma) {
    double w[5];
    gauss9Weights(sigma, w);
    return map(src.width, src.height, [&](int x, int y) {
        glm::dvec3 sum = w[0] * fetchOrBlack(src, x, y);
        for (int k = 1; k <= 4; ++k)
            sum += w[k] * (fetchOrBlack(src, x + k * axis.x, y + k * axis.y) + fetchOrBlack(src, x - k * axis.x, y - k * axis.y));
        return sum;
    });
}

RefImage linear9Pass(const RefImage& src, glm::dvec2 axis, double sigma) {
    double w[5];
    gauss9Weights(sigma, w);
    return map(src.width, src.height, [&](int x, int y) {
        glm::dvec2 c(x + 0.5, y + 0.5);
        glm::dvec3 sum = w[0] * bilinearOrBlack(src, c);
        for (int k = 1; k <= 3; k += 2) {
            double weight = w[k] + w[k + 1];
            double offset = weight > 0.0 ? (k * w[k] + (k + 1) * w[k + 1]) / weight : k;
            sum += weight * (bilinearOrBlack(src, c + offset * axis) + bilinearOrBlack(src, c - offset * axis));
        }
        return sum;
    });
}

RefImage gauss49Pass(const RefImage& src, double sigma) {
    double s = std::max(sigma, 1e-6), total = 0.0;
    double w[7][7];
    for (int j = -3; j <= 3; ++j)
        for (int i = -3; i <= 3; ++i) total += w[j + 3][i + 3] = std::exp(-double(i * i + j * j) / (2.0 * s * s));
    return map(src.width, src.height, [&](int x, int y) {
        glm::dvec3 sum(0.0);
        for (int j = -3; j <= 3; ++j)
            for (int i = -3; i <= 3; ++i) sum += w[j + 3][i + 3] * fetchOrBlack(src, x + i, y + j);
        return sum / total;
    });
}

RefImage kawasePass(const RefImage& src, double o) {
    return map(src.width, src.height, [&](int x, int y) {
        glm::dvec2 c(x + 0.5, y + 0.5);
        return 0.25 * (bilinearOrBlack(src, c + glm::dvec2(-o, -o)) + bilinearOrBlack(src, c + glm::dvec2(o, -o)) +
                       bilinearOrBlack(src, c + glm::dvec2(-o, o)) + bilinearOrBlack(src, c + glm::dvec2(o, o)));
    });
}

// A pyramid downsample into ceil(size / 2): the output texel's centre is the source corner 2 t + 1.
RefImage pyramidDown(const RefImage& src, int kind, double r) {
    return map((src.width + 1) / 2, (src.height + 1) / 2, [&](int x, int y) {
        glm::dvec2 c(2.0 * x + 1.0, 2.0 * y + 1.0);
        auto at = [&](double dx, double dy) { return bilinearOrBlack(src, c + r * glm::dvec2(dx, dy)); };
        if (kind == 0) return (4.0 * at(0, 0) + at(-1, -1) + at(1, -1) + at(-1, 1) + at(1, 1)) / 8.0;
        return 0.125 * (at(-1, 1) + at(1, 1) + at(-1, -1) + at(1, -1)) + 0.125 * at(0, 0) +
               0.0625 * (at(0, 2) + at(-2, 0) + at(2, 0) + at(0, -2)) +
               0.03125 * (at(-2, 2) + at(2, 2) + at(-2, -2) + at(2, -2));
    });
}

// A pyramid upsample into `size`: output texel t's centre lies at (t + 0.5) / 2 in the source.
RefImage pyramidUp(const RefImage& src, glm::ivec2 size, int kind, double r) {
    return map(size.x, size.y, [&](int x, int y) {
        glm::dvec2 c((x + 0.5) / 2.0, (y + 0.5) / 2.0);
        auto at = [&](double dx, double dy) { return bilinearOrBlack(src, c + r * glm::dvec2(dx, dy)); };
        if (kind == 0)
            return (at(-2, 0) + at(2, 0) + at(0, -2) + at(0, 2) + 2.0 * (at(-1, -1) + at(1, -1) + at(-1, 1) + at(1, 1))) / 12.0;
        glm::dvec3 sum(0.0);
        for (int j = -1; j <= 1; ++j)
            for (int i = -1; i <= 1; ++i) sum += double((2 - std::abs(i)) * (2 - std::abs(j))) * at(i, j);
        return sum / 16.0;
    });
}

}  // namespace

RefImage sanitised(const RefImage& input) {
    RefImage out = input;
    for (auto& t : out.texels)
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(t[c]) || !(t[c] > 0.0)) t[c] = 0.0;
    return out;
}

int reductionFactor(glm::ivec2 inputSize, glm::ivec2 reduced) {
    for (int n = 2; n <= 8; n *= 2)
        if (reducedSize(inputSize, n) == reduced) return n;
    return std::max(1, (inputSize.y + reduced.y - 1) / std::max(reduced.y, 1));
}

glm::ivec2 reducedSize(glm::ivec2 size, int n) { return glm::max((size + n - 1) / n, glm::ivec2(1)); }

RefImage reducedBright(const RefImage& input, int n, double threshold) {
    RefImage s = sanitised(input);
    glm::ivec2 size = reducedSize({input.width, input.height}, n);
    return map(size.x, size.y, [&](int bx, int by) {
        glm::dvec3 sum(0.0);
        int count = 0;
        for (int y = by * n; y < std::min(by * n + n, input.height); ++y)
            for (int x = bx * n; x < std::min(bx * n + n, input.width); ++x, ++count)
                sum += glm::max(rgb(s.at(x, y)) - threshold, glm::dvec3(0.0));
        return sum / double(std::max(count, 1));
    });
}

glm::dvec3 bilinearOrBlack(const RefImage& image, glm::dvec2 position) {
    glm::dvec2 p = position - 0.5;
    glm::dvec2 fl = glm::floor(p);
    glm::dvec2 f = p - fl;
    int i = int(fl.x), j = int(fl.y);
    glm::dvec3 bottom = glm::mix(fetchOrBlack(image, i, j), fetchOrBlack(image, i + 1, j), f.x);
    glm::dvec3 top = glm::mix(fetchOrBlack(image, i, j + 1), fetchOrBlack(image, i + 1, j + 1), f.x);
    return glm::mix(bottom, top, f.y);
}

glm::dvec3 bilinearClamped(const RefImage& image, glm::dvec2 position) {
    glm::dvec2 p = position - 0.5;
    glm::dvec2 fl = glm::floor(p);
    glm::dvec2 f = p - fl;
    int i = int(fl.x), j = int(fl.y);
    return glm::mix(glm::mix(rgb(fetchClamped(image, i, j)), rgb(fetchClamped(image, i + 1, j)), f.x),
                    glm::mix(rgb(fetchClamped(image, i, j + 1)), rgb(fetchClamped(image, i + 1, j + 1)), f.x), f.y);
}

const std::vector<BloomBlur>& allBloomBlurs() {
    static const std::vector<BloomBlur> all{BloomBlur::Gauss9x1, BloomBlur::Gauss9x2,  BloomBlur::Gauss9x4,
                                            BloomBlur::Gauss49,  BloomBlur::Linear9x2, BloomBlur::Kawase,
                                            BloomBlur::DualFilter, BloomBlur::Tent13};
    return all;
}

std::string bloomBlurName(BloomBlur blur) {
    switch (blur) {
        case BloomBlur::Gauss9x1: return "gauss9x1";
        case BloomBlur::Gauss9x2: return "gauss9x2";
        case BloomBlur::Gauss9x4: return "gauss9x4";
        case BloomBlur::Gauss49: return "gauss49";
        case BloomBlur::Linear9x2: return "linear9x2";
        case BloomBlur::Kawase: return "kawase";
        case BloomBlur::DualFilter: return "dual_filter";
        case BloomBlur::Tent13: return "tent13";
    }
    return "?";
}

double kawaseVariance(double s) {
    double v = 0.0;
    for (double step : kKawaseSteps) v += s * s * step * step + bilinearVariance(s * step);
    return v;
}

double kawaseScale(double sigma) {
    double target = sigma * sigma;
    double lo = std::sqrt(std::max(target - 1.25, 0.0) / 27.25), hi = sigma / std::sqrt(27.25);
    for (int k = 0; k < 24; ++k) {
        double mid = 0.5 * (lo + hi);
        (kawaseVariance(mid) < target ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

double dualFilterVariance(double r) {
    double down = 0.125 + 0.5 * (r * r + bilinearVariance(r + 0.5));
    double up = 4.0 / 3.0 * r * r + (upsampleBilinearVariance(0.0) + upsampleBilinearVariance(2.0 * r)) / 6.0 +
                2.0 / 3.0 * upsampleBilinearVariance(r);
    return 5.0 * down + 20.0 * up;
}

double tent13Variance(double r) {
    double down = 1.5 * r * r + 0.25 * bilinearVariance(0.5) + 0.25 * bilinearVariance(2.0 * r + 0.5) +
                  0.5 * bilinearVariance(r + 0.5);
    double up = 0.5 * r * r + 0.5 * upsampleBilinearVariance(0.0) + 0.5 * upsampleBilinearVariance(r);
    return 5.0 * down + 20.0 * up;
}

double pyramidRadius(int kind, double sigma) {
    double target = sigma * sigma;
    double a = kind == 0 ? 2.5 + 80.0 / 3.0 : 17.5;
    double lo = 0.0, hi = sigma / std::sqrt(a);
    for (int k = 0; k < 24; ++k) {
        double mid = 0.5 * (lo + hi);
        double v = kind == 0 ? dualFilterVariance(mid) : tent13Variance(mid);
        (v < target ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

RefImage bloomBlur(BloomBlur blur, const RefImage& down, double sigmaD) {
    auto gaussChain = [&](int n) {
        RefImage image = down;
        for (int i = 0; i < n; ++i) {
            image = gauss9Pass(image, {1, 0}, sigmaD / std::sqrt(double(n)));
            image = gauss9Pass(image, {0, 1}, sigmaD / std::sqrt(double(n)));
        }
        return image;
    };
    switch (blur) {
        case BloomBlur::Gauss9x1: return gaussChain(1);
        case BloomBlur::Gauss9x2: return gaussChain(2);
        case BloomBlur::Gauss9x4: return gaussChain(4);
        case BloomBlur::Gauss49: return gauss49Pass(down, sigmaD);
        case BloomBlur::Linear9x2: {
            RefImage image = down;
            for (int i = 0; i < 2; ++i) {
                image = linear9Pass(image, {1, 0}, sigmaD / std::sqrt(2.0));
                image = linear9Pass(image, {0, 1}, sigmaD / std::sqrt(2.0));
            }
            return image;
        }
        case BloomBlur::Kawase: {
            double s = kawaseScale(sigmaD);
            RefImage image = down;
            for (double step : kKawaseSteps) image = kawasePass(image, s * step);
            return image;
        }
        case BloomBlur::DualFilter:
        case BloomBlur::Tent13: {
            int kind = blur == BloomBlur::DualFilter ? 0 : 1;
            double r = pyramidRadius(kind, sigmaD);
            RefImage level1 = pyramidDown(down, kind, r);
            RefImage level2 = pyramidDown(level1, kind, r);
            RefImage up1 = pyramidUp(level2, {level1.width, level1.height}, kind, r);
            return pyramidUp(up1, {down.width, down.height}, kind, r);
        }
    }
    return down;
}

RefImage stageComposite(const RefImage& input, const RefImage& reduced, int n, double strength) {
    RefImage s = sanitised(input);
    return map(input.width, input.height, [&](int x, int y) {
        glm::dvec2 p((x + 0.5) / n, (y + 0.5) / n);
        return rgb(s.at(x, y)) + strength * bilinearClamped(reduced, p);
    });
}

StageImages bloomStage(const RefImage& input, BloomBlur blur, const BloomSettings& settings, int n) {
    StageImages out;
    out.down = reducedBright(input, n, settings.threshold);
    double sigmaD = settings.sigma * input.height / n;
    out.blurred.push_back(bloomBlur(blur, out.down, sigmaD));
    out.result = stageComposite(input, out.blurred[0], n, settings.strength);
    return out;
}

RefImage streakPass(const RefImage& source, glm::ivec2 direction, int pass, double stepDecay) {
    int stride = 1 << (2 * pass);
    return map(source.width, source.height, [&](int x, int y) {
        glm::dvec3 sum(0.0);
        for (int i = 0; i < 4; ++i)
            sum += std::exp(-stepDecay * stride * i) *
                   fetchOrBlack(source, x + direction.x * stride * i, y + direction.y * stride * i);
        return pass == 0 ? (1.0 - std::exp(-stepDecay)) * sum : sum;
    });
}

StageImages streakStage(const RefImage& input, int passes, const StreakSettings& settings, int n) {
    StageImages out;
    out.down = reducedBright(input, n, settings.threshold);
    double stepDecay = n / (settings.length * input.height);
    RefImage sum(out.down.width, out.down.height, glm::dvec4(0.0));
    for (glm::ivec2 direction : {glm::ivec2(1, 1), glm::ivec2(-1, 1), glm::ivec2(1, -1), glm::ivec2(-1, -1)}) {
        RefImage image = out.down;
        for (int p = 0; p < passes; ++p) image = streakPass(image, direction, p, stepDecay);
        for (size_t i = 0; i < sum.texels.size(); ++i) sum.texels[i] += 0.25 * image.texels[i];
        out.blurred.push_back(std::move(image));
    }
    out.result = stageComposite(input, sum, n, settings.strength);
    return out;
}

}  // namespace rmfx::test
