#include "io/image/MipChain.h"

#include <algorithm>
#include <cstddef>

#include "io/image/ImageIO.h"

namespace rmfx {
namespace {

// For one axis reduced from `from` texels to `to`: for each output texel, the input texels its
// footprint [i*from/to, (i+1)*from/to) covers and the share of the footprint each covers.
struct AxisTap {
    int source;
    double weight;
};

std::vector<std::vector<AxisTap>> axisTaps(int from, int to) {
    std::vector<std::vector<AxisTap>> taps(static_cast<size_t>(to));
    const double scale = static_cast<double>(from) / to;
    for (int i = 0; i < to; ++i) {
        const double begin = i * scale, end = (i + 1) * scale;
        for (int s = static_cast<int>(begin); s < from && s < end; ++s) {
            const double covered = std::min<double>(s + 1, end) - std::max<double>(s, begin);
            if (covered > 0) taps[static_cast<size_t>(i)].push_back({s, covered / scale});
        }
    }
    return taps;
}

bool isColourChannel(int channel, int channels) {
    const bool hasAlpha = channels == 2 || channels == 4;
    return !hasAlpha || channel < channels - 1;
}

// One level down: separable, along x, then y, then z, each sum in double.
std::vector<float> reduce(const float* above, int w, int h, int d, int channels, int nw, int nh, int nd) {
    const auto tx = axisTaps(w, nw), ty = axisTaps(h, nh), tz = axisTaps(d, nd);
    const size_t ch = static_cast<size_t>(channels);
    // Output texel i of `taps`, at `outStride` apart, from inputs `inStride` apart, for `count` rows.
    const auto pass = [ch](const float* in, float* out, const std::vector<std::vector<AxisTap>>& taps,
                           size_t inStride, size_t outStride, size_t rows, size_t rowIn, size_t rowOut,
                           size_t inner) {
        for (size_t r = 0; r < rows; ++r)
            for (size_t i = 0; i < taps.size(); ++i)
                for (size_t k = 0; k < inner; ++k)
                    for (size_t c = 0; c < ch; ++c) {
                        double sum = 0.0;
                        for (const AxisTap& t : taps[i])
                            sum += t.weight * in[r * rowIn + static_cast<size_t>(t.source) * inStride + k * ch + c];
                        out[r * rowOut + i * outStride + k * ch + c] = static_cast<float>(sum);
                    }
    };
    const size_t W = static_cast<size_t>(w), H = static_cast<size_t>(h), D = static_cast<size_t>(d);
    const size_t NW = static_cast<size_t>(nw), NH = static_cast<size_t>(nh), ND = static_cast<size_t>(nd);
    std::vector<float> alongX(NW * H * D * ch);
    pass(above, alongX.data(), tx, ch, ch, H * D, W * ch, NW * ch, 1);
    std::vector<float> alongY(NW * NH * D * ch);
    pass(alongX.data(), alongY.data(), ty, NW * ch, NW * ch, D, NW * H * ch, NW * NH * ch, NW);
    if (nd == d) return alongY;
    std::vector<float> alongZ(NW * NH * ND * ch);
    pass(alongY.data(), alongZ.data(), tz, NW * NH * ch, NW * NH * ch, 1, 0, 0, NW * NH);
    return alongZ;
}

}  // namespace

std::vector<Image> mipLevelsBelow(const Image& base, int levels, MipEncoding encoding) {
    std::vector<Image> below;
    const int channels = base.channels;
    const bool srgb = encoding == MipEncoding::Srgb;
    std::vector<float> linear;  // the level above as linear light, where base is sRGB-encoded
    if (srgb) {
        linear.resize(base.pixels.size());
        for (size_t i = 0; i < base.pixels.size(); ++i)
            linear[i] = isColourChannel(static_cast<int>(i % static_cast<size_t>(channels)), channels)
                            ? srgbDecode(base.pixels[i])
                            : base.pixels[i];
    }
    int w = base.width, h = base.height, d = std::max(base.depth, 1);
    for (int l = 1; l < levels; ++l) {
        const int nw = std::max(1, base.width >> l), nh = std::max(1, base.height >> l);
        const int nd = base.depth > 1 ? std::max(1, base.depth >> l) : 1;
        const float* above = srgb ? linear.data() : l == 1 ? base.pixels.data() : below.back().pixels.data();
        std::vector<float> level = reduce(above, w, h, d, channels, nw, nh, nd);
        w = nw, h = nh, d = nd;
        Image out;
        out.width = w;
        out.height = h;
        out.depth = base.depth > 1 ? d : base.depth;
        out.channels = channels;
        out.highDynamicRange = base.highDynamicRange;
        out.bitsPerChannel = base.bitsPerChannel;
        out.pixels = level;
        if (srgb) {
            for (size_t i = 0; i < out.pixels.size(); ++i)
                if (isColourChannel(static_cast<int>(i % static_cast<size_t>(channels)), channels))
                    out.pixels[i] = srgbEncode(out.pixels[i]);
            linear = std::move(level);
        }
        below.push_back(std::move(out));
    }
    return below;
}

}  // namespace rmfx
