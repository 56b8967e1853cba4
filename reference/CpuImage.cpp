#include "reference/CpuImage.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace rmfx::test {

RefImage fromImage(const Image& image) {
    RefImage out(image.width, image.height);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            glm::dvec4 v(0.0, 0.0, 0.0, 1.0);
            int row = image.height - 1 - y;
            if (image.channels < 3) {
                v = glm::dvec4(glm::dvec3(image.at(x, row, 0)), image.channels == 2 ? image.at(x, row, 1) : 1.0);
            } else {
                for (int c = 0; c < image.channels; ++c) v[c] = image.at(x, row, c);
            }
            out.at(x, y) = v;
        }
    return out;
}

glm::dvec4 fetchClamped(const RefImage& image, int x, int y) {
    return image.at(std::clamp(x, 0, image.width - 1), std::clamp(y, 0, image.height - 1));
}

BilinearFootprint bilinearFootprint(const RefImage& image, glm::dvec2 uv) {
    double x = uv.x * image.width - 0.5, y = uv.y * image.height - 0.5;
    double x0 = std::floor(x), y0 = std::floor(y);
    int i = static_cast<int>(x0), j = static_cast<int>(y0);
    return {{fetchClamped(image, i, j), fetchClamped(image, i + 1, j), fetchClamped(image, i, j + 1),
             fetchClamped(image, i + 1, j + 1)},
            x - x0, y - y0};
}

glm::dvec4 sampleBilinear(const RefImage& image, glm::dvec2 uv) {
    BilinearFootprint f = bilinearFootprint(image, uv);
    glm::dvec4 bottom = glm::mix(f.texels[0], f.texels[1], f.fx);
    glm::dvec4 top = glm::mix(f.texels[2], f.texels[3], f.fx);
    return glm::mix(bottom, top, f.fy);
}

glm::dvec4 bilinearFootprintRange(const RefImage& image, glm::dvec2 uv) {
    BilinearFootprint f = bilinearFootprint(image, uv);
    glm::dvec4 low = f.texels[0], high = f.texels[0];
    for (const glm::dvec4& t : f.texels) {
        low = glm::min(low, t);
        high = glm::max(high, t);
    }
    return high - low;
}

glm::dvec4 sampleNearest(const RefImage& image, glm::dvec2 uv) {
    return fetchClamped(image, static_cast<int>(std::floor(uv.x * image.width)),
                        static_cast<int>(std::floor(uv.y * image.height)));
}

RefImage shadePixels(int width, int height, const std::function<glm::dvec4(glm::dvec2)>& shade) {
    RefImage out(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) out.at(x, y) = shade(glm::dvec2((x + 0.5) / width, (y + 0.5) / height));
    return out;
}

double roundToHalf(double value) {
    if (std::isnan(value) || value == 0.0) return value;
    double magnitude = std::fabs(value);
    if (magnitude >= 65520.0) return std::copysign(std::numeric_limits<double>::infinity(), value);
    int exponent = std::max(static_cast<int>(std::floor(std::log2(magnitude))), -14);
    double ulp = std::ldexp(1.0, exponent - 10);
    return std::copysign(std::nearbyint(magnitude / ulp) * ulp, value);  // nearbyint: ties to even
}

double roundToUnorm8(double value) {
    if (std::isnan(value)) return 0.0;
    return std::nearbyint(std::clamp(value, 0.0, 1.0) * 255.0) / 255.0;
}

static RefImage mapTexels(const RefImage& image, double (*f)(double)) {
    RefImage out = image;
    for (glm::dvec4& t : out.texels)
        for (int c = 0; c < 4; ++c) t[c] = f(t[c]);
    return out;
}

RefImage roundedToHalf(const RefImage& image) { return mapTexels(image, roundToHalf); }
RefImage roundedToUnorm8(const RefImage& image) { return mapTexels(image, roundToUnorm8); }

RefImage roundedTo(const RefImage& image, TargetRounding rounding) {
    return rounding == TargetRounding::Half ? roundedToHalf(image) : roundedToUnorm8(image);
}

glm::dvec4 encodeAlpha64(glm::dvec3 rgb, double multiplier) { return glm::dvec4(rgb, multiplier / 64.0); }

glm::dvec3 decodeAlpha64(glm::dvec4 encoded) { return glm::dvec3(encoded) * (encoded.a * 64.0); }

RefImage decodedAlpha64(const RefImage& image) {
    RefImage out = image;
    for (glm::dvec4& t : out.texels) t = glm::dvec4(decodeAlpha64(t), 1.0);
    return out;
}

RefImage blendedAdditive(const RefImage& dst, const RefImage& src) {
    RefImage out = dst;
    for (size_t i = 0; i < out.texels.size() && i < src.texels.size(); ++i)
        out.texels[i] += glm::dvec4(glm::dvec3(src.texels[i]) * src.texels[i].a, 0.0);
    return out;
}

double maxColorChannel(const RefImage& image) {
    double m = 0.0;
    for (const glm::dvec4& t : image.texels) m = std::max({m, t.r, t.g, t.b});
    return m;
}

double maxAbsDifference(const RefImage& a, const RefImage& b, int channels) {
    return maxRelativeDifference(a, b, 0.0, channels);
}

double maxRelativeDifference(const RefImage& a, const RefImage& b, double floor, int channels) {
    if (a.width != b.width || a.height != b.height) return std::numeric_limits<double>::infinity();
    double worst = 0.0;
    for (size_t i = 0; i < a.texels.size(); ++i)
        for (int c = 0; c < channels; ++c) {
            double d = std::fabs(a.texels[i][c] - b.texels[i][c]);
            if (floor > 0.0) d /= std::max(std::fabs(b.texels[i][c]), floor);
            if (std::isnan(d)) return std::numeric_limits<double>::infinity();
            worst = std::max(worst, d);
        }
    return worst;
}

double maxDifferenceOverBound(const RefImage& a, const RefImage& b, double relative, double floor, const RefImage& allowance,
                              int channels) {
    if (a.width != b.width || a.height != b.height || allowance.width != b.width || allowance.height != b.height)
        return std::numeric_limits<double>::infinity();
    double worst = 0.0;
    for (size_t i = 0; i < a.texels.size(); ++i)
        for (int c = 0; c < channels; ++c) {
            const double d = std::fabs(a.texels[i][c] - b.texels[i][c]) /
                             (relative * std::max(std::fabs(b.texels[i][c]), floor) + allowance.texels[i][c]);
            if (std::isnan(d)) return std::numeric_limits<double>::infinity();
            worst = std::max(worst, d);
        }
    return worst;
}

double worstExcess(const RefImage& gl, const RefImage& ref, double relative, double absolute) {
    if (gl.width != ref.width || gl.height != ref.height) return INFINITY;
    double worst = -INFINITY;
    for (size_t i = 0; i < gl.texels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            double d = std::fabs(gl.texels[i][c] - ref.texels[i][c]);
            if (std::isnan(d)) return INFINITY;
            worst = std::max(worst, d - (relative * std::fabs(ref.texels[i][c]) + absolute));
        }
    return worst;
}

}  // namespace rmfx::test
