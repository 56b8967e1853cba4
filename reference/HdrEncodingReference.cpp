#include "reference/HdrEncodingReference.h"

#include <algorithm>
#include <cmath>

namespace rmfx::test {
namespace {

glm::dvec3 sanitised(glm::dvec3 c, double limit) {
    for (int k = 0; k < 3; ++k) c[k] = std::isnan(c[k]) ? 0.0 : std::clamp(c[k], 0.0, limit);
    return c;
}

double peak(glm::dvec3 c) { return std::max({c.r, c.g, c.b}); }

// HDRFormats: value / max clamped to [0, 1], × (2^bits − 1), rounded to nearest.
RefEncoded linear(glm::dvec3 rgb, double max, double levels) {
    RefEncoded out;
    glm::dvec3 c = sanitised(rgb, max);
    for (int k = 0; k < 3; ++k) {
        double q = std::floor(c[k] / max * levels + 0.5);
        out.codes[k] = static_cast<std::uint64_t>(q);
        out.decoded[k] = q / levels * max;
    }
    return out;
}

// EXT_texture_shared_exponent, N = 9, B = 15.
RefEncoded rgb9e5(glm::dvec3 rgb) {
    RefEncoded out;
    glm::dvec3 c = sanitised(rgb, 511.0 / 512.0 * 65536.0);
    double maxc = peak(c);
    double floorLog2 = maxc > 0.0 ? std::floor(std::log2(maxc)) : -1e9;
    int e = static_cast<int>(std::max(-16.0, floorLog2)) + 1 + 15;
    if (std::floor(maxc / std::pow(2.0, e - 15 - 9) + 0.5) == 512.0) e += 1;
    double step = std::pow(2.0, e - 15 - 9);
    for (int k = 0; k < 3; ++k) {
        double m = std::floor(c[k] / step + 0.5);
        out.codes[k] = static_cast<std::uint64_t>(m);
        out.decoded[k] = m * step;
    }
    out.codes[3] = static_cast<std::uint64_t>(e);
    return out;
}

// Ward's Radiance RGBE.
RefEncoded rgbe8(glm::dvec3 rgb) {
    RefEncoded out;
    glm::dvec3 c = sanitised(rgb, 255.0 * std::pow(2.0, 119));
    double maxc = peak(c);
    if (maxc <= 1e-32) return out;
    int e = 0;
    double m = std::frexp(maxc, &e);
    double scale = m * 256.0 / maxc;
    out.codes[3] = static_cast<std::uint64_t>(e + 128);
    for (int k = 0; k < 3; ++k) {
        out.codes[k] = static_cast<std::uint64_t>(std::floor(c[k] * scale));
        out.decoded[k] = (static_cast<double>(out.codes[k]) + 0.5) * std::pow(2.0, static_cast<int>(out.codes[3]) - 136);
    }
    return out;
}

// The chapter: decoded rgb · (1 + 64 a); a is the smallest 8-bit step whose multiplier covers the
// peak; colours brighter than 65 are scaled to 65 keeping hue.
RefEncoded rgba8x64(glm::dvec3 rgb) {
    RefEncoded out;
    glm::dvec3 c = sanitised(rgb, 1e30);
    double p = peak(c);
    if (p > 65.0) {
        c *= 65.0 / p;
        p = 65.0;
    }
    double alpha = p > 1.0 ? std::min(std::ceil((p - 1.0) / 64.0 * 255.0), 255.0) : 0.0;
    double multiplier = 1.0 + 64.0 * alpha / 255.0;
    out.codes[3] = static_cast<std::uint64_t>(alpha);
    for (int k = 0; k < 3; ++k) {
        double q = std::floor(std::clamp(c[k] / multiplier, 0.0, 1.0) * 255.0 + 0.5);
        out.codes[k] = static_cast<std::uint64_t>(q);
        out.decoded[k] = q / 255.0 * multiplier;
    }
    return out;
}

}  // namespace

RefEncoded referenceEncode(HdrEncoding encoding, glm::dvec3 rgb) {
    switch (encoding) {
        case HdrEncoding::Float: {
            RefEncoded out;
            out.decoded = rgb;
            return out;
        }
        case HdrEncoding::Rgb16: return linear(rgb, 100.0, 65535.0);
        case HdrEncoding::Rgb32: return linear(rgb, 10000.0, 4294967295.0);
        case HdrEncoding::Rgb9e5: return rgb9e5(rgb);
        case HdrEncoding::Rgbe8: return rgbe8(rgb);
        case HdrEncoding::Rgba8x64: return rgba8x64(rgb);
    }
    return {};
}

double referenceErrorBound(HdrEncoding encoding, glm::dvec3 rgb) {
    double p = peak(sanitised(rgb, 1e300));
    switch (encoding) {
        case HdrEncoding::Float: return 0.0;
        case HdrEncoding::Rgb16: return 100.0 / 65535.0 / 2.0;
        case HdrEncoding::Rgb32: return 10000.0 / 4294967295.0 / 2.0;
        // Half a step of 2^(e − 24), and the peak's mantissa is at least 256, or 255.75 when it
        // rounded up to 512 and moved to the next exponent: 1/511.5 of the peak.
        case HdrEncoding::Rgb9e5: return std::max(p / 511.5, std::ldexp(1.0, -25));
        case HdrEncoding::Rgbe8: return std::max(std::ldexp(p, -8), 1e-32);
        case HdrEncoding::Rgba8x64: return 0.5 / 255.0 * std::max(1.0, std::min(p, 65.0) + 64.0 / 255.0);
    }
    return 0.0;
}

}  // namespace rmfx::test
