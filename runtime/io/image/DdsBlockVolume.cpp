#include "io/image/DdsBlockVolume.h"

#include <array>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "io/image/ImageFileError.h"

namespace rmfx {
namespace {

constexpr size_t kHeaderBytes = 128;  // "DDS " and the 124-byte DDS_HEADER
constexpr uint32_t kDepthFlag = 0x800000;         // DDSD_DEPTH
constexpr uint32_t kVolumeCaps = 0x200000;        // DDSCAPS2_VOLUME
constexpr int64_t kMaxTexels = int64_t(1) << 28;  // as ImageIO's limit

uint32_t word(const std::vector<uint8_t>& b, size_t at) {
    return uint32_t(b[at]) | uint32_t(b[at + 1]) << 8 | uint32_t(b[at + 2]) << 16 | uint32_t(b[at + 3]) << 24;
}

using Rgba = std::array<uint8_t, 4>;

Rgba fromRgb565(uint16_t c) {
    const int r = (c >> 11) & 31, g = (c >> 5) & 63, b = c & 31;
    return {uint8_t(r << 3 | r >> 2), uint8_t(g << 2 | g >> 4), uint8_t(b << 3 | b >> 2), 255};
}

// (wa·a + wb·b) / (wa + wb), rounded to the nearest byte.
uint8_t blend(int a, int wa, int b, int wb) { return uint8_t((wa * a + wb * b + (wa + wb) / 2) / (wa + wb)); }

// The 16 colours of a colour block at `block`; DXT1 alone has the three-colour mode.
std::array<Rgba, 16> colourBlock(const uint8_t* block, bool dxt1) {
    const uint16_t c0 = uint16_t(block[0] | block[1] << 8), c1 = uint16_t(block[2] | block[3] << 8);
    std::array<Rgba, 4> palette{fromRgb565(c0), fromRgb565(c1), Rgba{}, Rgba{}};
    for (int c = 0; c < 3; ++c) {
        if (!dxt1 || c0 > c1) {
            palette[2][c] = blend(palette[0][c], 2, palette[1][c], 1);
            palette[3][c] = blend(palette[0][c], 1, palette[1][c], 2);
        } else {
            palette[2][c] = blend(palette[0][c], 1, palette[1][c], 1);
        }
    }
    palette[2][3] = 255;
    palette[3][3] = !dxt1 || c0 > c1 ? 255 : 0;  // transparent black
    const uint32_t indices = uint32_t(block[4]) | uint32_t(block[5]) << 8 | uint32_t(block[6]) << 16 | uint32_t(block[7]) << 24;
    std::array<Rgba, 16> out;
    for (int i = 0; i < 16; ++i) out[size_t(i)] = palette[(indices >> (2 * i)) & 3];
    return out;
}

// DXT4/5's alpha block: two end points and a 3-bit index per texel.
std::array<uint8_t, 16> interpolatedAlpha(const uint8_t* block) {
    const int a0 = block[0], a1 = block[1];
    std::array<uint8_t, 8> palette{uint8_t(a0), uint8_t(a1)};
    if (a0 > a1) {
        for (int k = 2; k < 8; ++k) palette[size_t(k)] = blend(a0, 8 - k, a1, k - 1);
    } else {
        for (int k = 2; k < 6; ++k) palette[size_t(k)] = blend(a0, 6 - k, a1, k - 1);
        palette[6] = 0;
        palette[7] = 255;
    }
    uint64_t bits = 0;
    for (int i = 0; i < 6; ++i) bits |= uint64_t(block[2 + i]) << (8 * i);
    std::array<uint8_t, 16> out;
    for (int i = 0; i < 16; ++i) out[size_t(i)] = palette[(bits >> (3 * i)) & 7];
    return out;
}

// DXT2/3's alpha block: 4 bits per texel.
std::array<uint8_t, 16> explicitAlpha(const uint8_t* block) {
    std::array<uint8_t, 16> out;
    for (int i = 0; i < 16; ++i) out[size_t(i)] = uint8_t(((block[i / 2] >> (4 * (i % 2))) & 15) * 17);
    return out;
}

}  // namespace

Result<Image> readBlockCompressedDdsVolume(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return imageFileError(file, "cannot open the file");
    std::vector<uint8_t> bytes(kHeaderBytes);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(kHeaderBytes)) || word(bytes, 0) != 0x20534444 ||
        word(bytes, 4) != 124)
        return imageFileError(file, "not a DDS file (no DDS header)");
    const uint32_t flags = word(bytes, 8), caps2 = word(bytes, 112);
    const uint32_t height = word(bytes, 12), width = word(bytes, 16), depth = word(bytes, 24);
    if (!(flags & kDepthFlag) || !(caps2 & kVolumeCaps) || depth < 1) return imageFileError(file, "not a DDS volume texture");
    const std::string fourCC(reinterpret_cast<const char*>(&bytes[84]), 4);
    const bool dxt1 = fourCC == "DXT1";
    const bool explicitAlphaBlock = fourCC == "DXT2" || fourCC == "DXT3";
    const bool interpolatedAlphaBlock = fourCC == "DXT4" || fourCC == "DXT5";
    if (!dxt1 && !explicitAlphaBlock && !interpolatedAlphaBlock)
        return imageFileError(file, "not a DXT1…DXT5-compressed DDS volume (its format is '" + fourCC + "')");
    if (width < 1 || height < 1 || width > 65536 || height > 65536 || depth > 65536 ||
        int64_t(width) * height * depth > kMaxTexels)
        return imageFileError(file, "volume too large or empty (" + std::to_string(width) + "x" + std::to_string(height) + "x" +
                                        std::to_string(depth) + ")");
    const size_t blocksAcross = (width + 3) / 4, blocksDown = (height + 3) / 4;
    const size_t blockBytes = dxt1 ? 8 : 16;
    const size_t sliceBytes = blocksAcross * blocksDown * blockBytes;
    // The size is checked before anything is allocated: a header can claim gigabytes.
    const size_t needed = sliceBytes * depth;
    std::error_code ec;
    const uintmax_t fileBytes = std::filesystem::file_size(file, ec);
    const size_t present = ec || fileBytes < kHeaderBytes ? 0 : size_t(fileBytes - kHeaderBytes);
    if (present < needed)
        return imageFileError(file, "truncated: " + std::to_string(depth) + " slices of " + std::to_string(width) + "x" +
                                        std::to_string(height) + " " + fourCC + " need " + std::to_string(needed) +
                                        " bytes after the header, the file has " + std::to_string(present));
    std::vector<uint8_t> data(needed);
    if (!in.read(reinterpret_cast<char*>(data.data()), std::streamsize(data.size())))
        return imageFileError(file, "cannot read its blocks");

    Image image;
    image.width = int(width);
    image.height = int(height);
    image.depth = int(depth);
    image.channels = 4;
    image.bitsPerChannel = 8;
    image.pixels.assign(size_t(width) * height * depth * 4, 0.0f);
    for (size_t z = 0; z < depth; ++z)
        for (size_t by = 0; by < blocksDown; ++by)
            for (size_t bx = 0; bx < blocksAcross; ++bx) {
                const uint8_t* block = &data[z * sliceBytes + (by * blocksAcross + bx) * blockBytes];
                std::array<uint8_t, 16> alpha{};
                if (explicitAlphaBlock) alpha = explicitAlpha(block);
                if (interpolatedAlphaBlock) alpha = interpolatedAlpha(block);
                const std::array<Rgba, 16> colour = colourBlock(dxt1 ? block : block + 8, dxt1);
                for (size_t i = 0; i < 16; ++i) {
                    const size_t x = bx * 4 + i % 4, y = by * 4 + i / 4;
                    if (x >= width || y >= height) continue;
                    float* texel = &image.pixels[((z * height + y) * width + x) * 4];
                    for (int c = 0; c < 3; ++c) texel[c] = colour[i][size_t(c)] / 255.0f;
                    texel[3] = (dxt1 ? colour[i][3] : alpha[i]) / 255.0f;
                }
            }
    return image;
}

}  // namespace rmfx
