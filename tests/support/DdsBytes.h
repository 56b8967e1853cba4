#pragma once
// DDS files built byte by byte for the tests (never copied from anywhere): the 128-byte header of
// a 4x4 texture and DXT colour blocks, whose decoded colours the tests work out by hand.

#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/TestSupport.h"

namespace rmfx::test::dds {

using Bytes = std::vector<uint8_t>;

constexpr uint32_t kCubeMap = 0x200, kAllFaces = 0xFC00, kPositiveX = 0x400, kPositiveZ = 0x4000, kVolume = 0x200000;

inline void put32(Bytes& b, uint32_t v) {
    for (int i = 0; i < 4; ++i) b.push_back(static_cast<uint8_t>(v >> (8 * i)));
}

inline void put16(Bytes& b, uint16_t v) {
    b.push_back(static_cast<uint8_t>(v));
    b.push_back(static_cast<uint8_t>(v >> 8));
}

// "DDS " and the 124-byte DDS_HEADER of a texture (4x4 unless told) compressed as `fourCC`, one
// mip level.
inline Bytes header(const char* fourCC, uint32_t caps2 = 0, uint32_t depth = 0, uint32_t width = 4, uint32_t height = 4) {
    Bytes b{'D', 'D', 'S', ' '};
    put32(b, 124);
    put32(b, 0x1 | 0x2 | 0x4 | 0x1000 | 0x80000 | (depth ? 0x800000 : 0));  // caps height width pixelformat linearsize (depth)
    put32(b, height);
    put32(b, width);
    put32(b, ((width + 3) / 4) * ((height + 3) / 4) * (std::string(fourCC) == "DXT1" ? 8 : 16));  // bytes of the top level
    put32(b, depth);
    put32(b, 1);  // mip levels
    for (int i = 0; i < 11; ++i) put32(b, 0);
    put32(b, 32);   // DDS_PIXELFORMAT size
    put32(b, 0x4);  // DDPF_FOURCC
    b.insert(b.end(), fourCC, fourCC + 4);
    for (int i = 0; i < 5; ++i) put32(b, 0);  // bit count and masks
    put32(b, 0x1000 | (caps2 ? 0x8 : 0));     // DDSCAPS_TEXTURE (| COMPLEX)
    put32(b, caps2);
    for (int i = 0; i < 3; ++i) put32(b, 0);
    EXPECT_EQ(b.size(), 128u);
    return b;
}

// The header of an uncompressed A8R8G8B8 volume texture (texels follow as B, G, R, A bytes, row
// by row, slice by slice).
inline Bytes uncompressedVolumeHeader(uint32_t width, uint32_t height, uint32_t depth) {
    Bytes b{'D', 'D', 'S', ' '};
    put32(b, 124);
    put32(b, 0x1 | 0x2 | 0x4 | 0x8 | 0x1000 | 0x800000);  // caps height width pitch pixelformat depth
    put32(b, height);
    put32(b, width);
    put32(b, width * 4);  // pitch
    put32(b, depth);
    put32(b, 1);  // mip levels
    for (int i = 0; i < 11; ++i) put32(b, 0);
    put32(b, 32);    // DDS_PIXELFORMAT size
    put32(b, 0x41);  // DDPF_RGB | DDPF_ALPHAPIXELS
    put32(b, 0);     // no FourCC
    put32(b, 32);    // bits per texel
    put32(b, 0x00FF0000);
    put32(b, 0x0000FF00);
    put32(b, 0x000000FF);
    put32(b, 0xFF000000);
    put32(b, 0x1000 | 0x8);  // DDSCAPS_TEXTURE | COMPLEX
    put32(b, 0x200000);      // DDSCAPS2_VOLUME
    for (int i = 0; i < 3; ++i) put32(b, 0);
    EXPECT_EQ(b.size(), 128u);
    return b;
}

// A DXT colour block: two RGB565 end points and a 2-bit index per texel, row by row.
inline void colorBlock(Bytes& b, uint16_t c0, uint16_t c1, const std::array<int, 16>& index) {
    put16(b, c0);
    put16(b, c1);
    uint32_t bits = 0;
    for (int i = 0; i < 16; ++i) bits |= static_cast<uint32_t>(index[i]) << (2 * i);
    put32(b, bits);
}

constexpr uint16_t kRed = 0xF800, kGreen = 0x07E0, kBlue = 0x001F, kYellow = 0xFFE0, kMagenta = 0xF81F, kWhite = 0xFFFF;
constexpr std::array<int, 16> kAllZero{};

inline std::filesystem::path writeBytes(const test::ScratchDir& dir, const std::string& name, const Bytes& bytes) {
    std::filesystem::path file = dir / name;
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), static_cast<long>(bytes.size()));
    return file;
}

}  // namespace rmfx::test::dds
