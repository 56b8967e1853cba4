#pragma once
// A small, well-formed EXR whose header claims a huge image: a 16x16 zip-compressed file with
// its data and display windows widened to WIDTHxHEIGHT and an offset table of that many chunks
// (all pointing at the one chunk there is). OpenImageIO opens it and reports the claimed size;
// decoding it would allocate the whole image before finding the chunks wrong. This is what an
// 8 KB file claiming 16000x16000 looks like to a reader.

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>

namespace rmfx::test {

inline bool writeExrClaimingSize(const std::filesystem::path& file, int width, int height) {
    const std::filesystem::path small = file.string() + ".16x16.exr";
    OIIO::ImageSpec spec(16, 16, 4, OIIO::TypeDesc::HALF);
    spec.attribute("compression", "zip");  // 16 scanlines a chunk
    auto out = OIIO::ImageOutput::create(small.string());
    std::vector<float> pixels(16 * 16 * 4, 0.5f);
    if (!out || !out->open(small.string(), spec) || !out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) || !out->close())
        return false;
    std::stringstream read;
    read << std::ifstream(small, std::ios::binary).rdbuf();
    std::filesystem::remove(small);
    std::string bytes = read.str();
    for (const char* name : {"dataWindow", "displayWindow"}) {
        const std::string key = std::string(name) + '\0' + "box2i" + '\0';
        const size_t at = bytes.find(key);
        if (at == std::string::npos) return false;
        int32_t box[4];
        std::memcpy(box, &bytes[at + key.size() + 4], sizeof box);
        box[2] = box[0] + width - 1;
        box[3] = box[1] + height - 1;
        std::memcpy(&bytes[at + key.size() + 4], box, sizeof box);
    }
    // The one-entry offset table is the 8 bytes that hold their own end: the chunk's offset.
    size_t tableStart = 0;
    for (size_t i = 8; i + 8 <= bytes.size() && !tableStart; ++i) {
        uint64_t value;
        std::memcpy(&value, &bytes[i], 8);
        if (value == i + 8) tableStart = i;
    }
    if (!tableStart) return false;
    const std::string header = bytes.substr(0, tableStart), chunk = bytes.substr(tableStart + 8);
    const size_t chunks = (size_t(height) + 15) / 16;
    const uint64_t chunkOffset = header.size() + chunks * 8;
    std::string file_bytes = header;
    for (size_t i = 0; i < chunks; ++i) file_bytes.append(reinterpret_cast<const char*>(&chunkOffset), 8);
    file_bytes += chunk;
    std::ofstream(file, std::ios::binary) << file_bytes;
    return true;
}

}  // namespace rmfx::test
