#include "io/image/ImageCompare.h"
#include "io/image/codecs/CodecFunctions.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include "core/Percentile.h"
#include "core/ShortNumber.h"

namespace rmfx::codecs {

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
           std::to_string(first % actual.channels) + ": render " + shortNumber(actual.pixels[first]) + ", reference " +
           shortNumber(reference.pixels[first]);
}

// |a − b| per channel, or relative to the reference.
OIIO::ImageBuf channelDifference(const Image& actual, const Image& reference, const CompareLimits& limits) {
    OIIO::ImageBuf a = toBuffer(actual), b = toBuffer(reference);
    OIIO::ImageBuf difference = algo::absdiff(a, b);
    if (limits.metric == ErrorMetric::Relative)
        difference = algo::div(difference, algo::max(algo::abs(b), static_cast<float>(limits.floor)));
    // Matching NaNs and infinities leave NaN here (inf − inf, NaN − NaN): no error. A mismatch is
    // ImageComparison::problem already.
    return algo::fixNonFinite(difference, algo::NONFINITE_BLACK);
}

// ΔE_ITP per pixel, one channel. One or two channels are grey (and alpha), three or four RGB
// (and alpha), as image files hold them.
Image itpDifference(const Image& actual, const Image& reference, double luminance) {
    Image out;
    out.width = actual.width;
    out.height = actual.height;
    out.channels = 1;
    out.highDynamicRange = true;
    out.pixels.resize(static_cast<size_t>(actual.width) * actual.height);
    const size_t channels = static_cast<size_t>(actual.channels);
    const size_t colourChannels = channels <= 2 ? 1 : 3;
    auto itp = [&](const float* v) {
        return colourChannels == 1 ? itpFromBt709(v[0], v[0], v[0], luminance)
                                   : itpFromBt709(v[0], v[1], v[2], luminance);
    };
    for (size_t p = 0; p < out.pixels.size(); ++p) {
        const float* a = &actual.pixels[p * channels];
        const float* b = &reference.pixels[p * channels];
        // A NaN or infinity, matched in the other image or not, leaves the pixel's error 0: a
        // mismatch is ImageComparison::problem already.
        bool finite = true;
        for (size_t c = 0; c < colourChannels; ++c) finite = finite && std::isfinite(a[c]) && std::isfinite(b[c]);
        if (finite) out.pixels[p] = static_cast<float>(deltaEItp(itp(a), itp(b)));
    }
    return out;
}

}  // namespace

ImageComparison compareImages(const Image& actual, const Image& reference, const CompareLimits& limits) {
    ImageComparison result;
    result.metric = limits.metric;
    if (limits.percentile) result.percentile = limits.percentile->percentile;
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
    OIIO::ImageBuf difference = limits.metric == ErrorMetric::Itp
                                    ? toBuffer(itpDifference(actual, reference, limits.luminance))
                                    : channelDifference(actual, reference, limits);

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
    result.difference = toImage(difference);
    if (limits.percentile && !result.difference.empty()) {
        std::vector<double> errors(result.difference.pixels.begin(), result.difference.pixels.end());
        m.percentileError = percentile(std::move(errors), limits.percentile->percentile / 100.0);
    }

    if (limits.max) result.checks.push_back({LimitCheck::Kind::Max, m.maxError, *limits.max});
    if (limits.mean) result.checks.push_back({LimitCheck::Kind::Mean, m.meanError, *limits.mean});
    if (limits.percentile)
        result.checks.push_back({LimitCheck::Kind::Percentile, m.percentileError, limits.percentile->max});
    if (limits.pixel) result.checks.push_back({LimitCheck::Kind::FailFraction, m.failFraction(), limits.failFraction});
    return result;
}

}  // namespace rmfx::codecs
