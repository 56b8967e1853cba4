#include "io/image/ImageCompare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

namespace rmfx {

namespace {

namespace algo = OIIO::ImageBufAlgo;

OIIO::ImageBuf toBuffer(const Image& image) {
    OIIO::ImageBuf buffer(OIIO::ImageSpec(image.width, image.height, image.channels, OIIO::TypeDesc::FLOAT));
    buffer.set_pixels(buffer.roi(), OIIO::TypeDesc::FLOAT, image.pixels.data());
    return buffer;
}

Image toImage(const OIIO::ImageBuf& buffer) {
    Image image;
    image.width = buffer.spec().width;
    image.height = buffer.spec().height;
    image.channels = buffer.spec().nchannels;
    image.highDynamicRange = true;
    image.pixels.resize(static_cast<size_t>(image.width) * image.height * image.channels);
    buffer.get_pixels(buffer.roi(), OIIO::TypeDesc::FLOAT, image.pixels.data());
    return image;
}

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", v);
    return text;
}

// A NaN matches a NaN and an infinity the same infinity; anything else against a non-finite value
// is a mismatch. (OpenImageIO's compare takes +inf and −inf as equal, so this is counted here.)
// Empty when every non-finite value has its match.
std::string nonFiniteMismatch(const Image& actual, const Image& reference) {
    long long count = 0;
    size_t first = 0;
    for (size_t i = 0; i < actual.pixels.size(); ++i) {
        float a = actual.pixels[i], b = reference.pixels[i];
        if ((std::isfinite(a) && std::isfinite(b)) || (std::isnan(a) && std::isnan(b)) || a == b) continue;
        if (count++ == 0) first = i;
    }
    if (count == 0) return "";
    size_t pixel = first / actual.channels;
    return std::to_string(count) + (count == 1 ? " value is" : " values are") +
           " NaN or infinite in one image and not the same in the other; the first at x=" +
           std::to_string(pixel % actual.width) + " y=" + std::to_string(pixel / actual.width) + " channel " +
           std::to_string(first % actual.channels) + ": render " + number(actual.pixels[first]) + ", reference " +
           number(reference.pixels[first]);
}

}  // namespace

bool ImageComparison::passed() const {
    return problem.empty() && std::all_of(checks.begin(), checks.end(), [](const LimitCheck& c) { return c.passed(); });
}

std::string ImageComparison::describe() const {
    std::string error = metric == ErrorMetric::Relative ? "relative error " : "error ";
    std::string out = problem;
    auto clause = [&](const std::string& text) { out += (out.empty() ? "" : "; ") + text; };
    auto compared = [](const LimitCheck& c) {
        return number(c.value) + (c.passed() ? " ≤ " : " > ") + number(c.limit);
    };
    std::string where = metrics.maxError > 0 ? " at x=" + std::to_string(metrics.maxX) + " y=" +
                                                   std::to_string(metrics.maxY) + " channel " +
                                                   std::to_string(metrics.maxChannel)
                                             : "";
    if (checks.empty() && difference.empty()) return out;
    if (checks.empty()) {
        clause("max " + error + number(metrics.maxError) + where + ", mean " + error + number(metrics.meanError));
        return out;
    }
    for (const LimitCheck& c : checks) {
        switch (c.kind) {
            case LimitCheck::Kind::Max: clause("max " + error + compared(c) + where); break;
            case LimitCheck::Kind::Mean: clause("mean " + error + compared(c)); break;
            case LimitCheck::Kind::FailFraction:
                clause("fail fraction " + compared(c) + " (" + std::to_string(metrics.failingPixels) + " of " +
                       std::to_string(metrics.pixelCount) + " pixels with " + error + "> " +
                       number(pixelThreshold.value_or(0.0)) + ")");
                break;
        }
    }
    return out;
}

ImageComparison compareImages(const Image& actual, const Image& reference, const CompareLimits& limits) {
    ImageComparison result;
    result.metric = limits.metric;
    result.pixelThreshold = limits.pixel;
    if (actual.width != reference.width || actual.height != reference.height) {
        result.problem = "size: the render is " + std::to_string(actual.width) + "x" + std::to_string(actual.height) +
                         ", the reference " + std::to_string(reference.width) + "x" + std::to_string(reference.height);
        return result;
    }
    if (actual.channels != reference.channels) {
        result.problem = "channels: the render has " + std::to_string(actual.channels) + ", the reference " +
                         std::to_string(reference.channels);
        return result;
    }
    result.problem = nonFiniteMismatch(actual, reference);
    OIIO::ImageBuf a = toBuffer(actual), b = toBuffer(reference);

    OIIO::ImageBuf difference = algo::absdiff(a, b);
    if (limits.metric == ErrorMetric::Relative)
        difference = algo::div(difference, algo::max(algo::abs(b), static_cast<float>(limits.floor)));
    // Matching NaNs and infinities leave NaN here (inf − inf, NaN − NaN): no error. A mismatch is
    // result.problem already.
    difference = algo::fixNonFinite(difference, algo::NONFINITE_BLACK);

    // Against black, compare gives the largest error and where it is, the mean over every value,
    // and the pixels with a channel above the threshold.
    OIIO::ImageBuf black(difference.spec());
    algo::zero(black);
    float threshold = limits.pixel ? static_cast<float>(*limits.pixel) : std::numeric_limits<float>::max();
    algo::CompareResults measured = algo::compare(difference, black, threshold, threshold);
    CompareMetrics& m = result.metrics;
    m.maxError = measured.maxerror;
    m.maxX = measured.maxx;
    m.maxY = measured.maxy;
    m.maxChannel = measured.maxc;
    m.meanError = measured.meanerror;
    m.pixelCount = static_cast<long long>(actual.width) * actual.height;
    m.failingPixels = limits.pixel ? static_cast<long long>(measured.nfail) : 0;

    if (limits.max) result.checks.push_back({LimitCheck::Kind::Max, m.maxError, *limits.max});
    if (limits.mean) result.checks.push_back({LimitCheck::Kind::Mean, m.meanError, *limits.mean});
    if (limits.pixel) result.checks.push_back({LimitCheck::Kind::FailFraction, m.failFraction(), limits.failFraction});
    result.difference = toImage(difference);
    return result;
}

}  // namespace rmfx
