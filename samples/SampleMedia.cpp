#include "samples/SampleMedia.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "io/image/CubeMapLayout.h"
#include "io/image/ImageIO.h"
#include "model/HdrEncoding.h"

namespace rmfx::samples {

glm::vec3 analyticSky(const glm::vec3& d, const glm::vec3& sunDirection, float sunIntensity) {
    if (d.y < 0.0f) return glm::vec3(0.2f, 0.17f, 0.14f) * (1.0f + d.y) + glm::vec3(0.02f);
    glm::vec3 zenith(0.1f, 0.25f, 0.9f), horizon(0.9f, 1.1f, 1.5f);
    glm::vec3 sky = glm::mix(horizon, zenith, std::sqrt(d.y));
    float cosAngle = glm::dot(d, sunDirection);
    sky += glm::vec3(1.0f, 0.8f, 0.5f) * std::pow(std::max(cosAngle, 0.0f), 64.0f) * 4.0f;
    if (cosAngle > 0.9995f) sky += glm::vec3(1.0f, 0.95f, 0.85f) * sunIntensity;
    return sky;
}

Image makeSkyCross(int n, const glm::vec3& sunDirection, float sunIntensity, int samplesPerAxis) {
    Image image;
    image.width = 4 * n;
    image.height = 3 * n;
    image.channels = 3;
    image.highDynamicRange = true;
    image.pixels.assign(static_cast<size_t>(image.width) * image.height * 3, 0.0f);
    // Block (column, row) of each face in the horizontal cross.
    const int blocks[6][2] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {3, 1}};
    glm::vec3 sun = glm::normalize(sunDirection);
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                glm::vec3 c(0.0f);
                for (int j = 0; j < samplesPerAxis; ++j)
                    for (int i = 0; i < samplesPerAxis; ++i) {
                        float u = (x + (i + 0.5f) / samplesPerAxis) / n, v = (y + (j + 0.5f) / samplesPerAxis) / n;
                        c += analyticSky(glm::normalize(cubeFaceTexelDirection(face, u, v)), sun, sunIntensity);
                    }
                c /= float(samplesPerAxis * samplesPerAxis);
                for (int k = 0; k < 3; ++k) image.at(blocks[face][0] * n + x, blocks[face][1] * n + y, k) = c[k];
            }
    return image;
}

Image makeDiscMask(int size) {
    Image image;
    image.width = image.height = size;
    image.channels = 1;
    image.bitsPerChannel = 8;
    image.pixels.resize(static_cast<size_t>(size) * size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            float dx = (x + 0.5f) / size - 0.5f, dy = (y + 0.5f) / size - 0.5f;
            float edge = (0.4f - std::sqrt(dx * dx + dy * dy)) * size / 2.0f;  // in units of 2 pixels
            float value = std::clamp(edge + 0.5f, 0.0f, 1.0f);
            image.at(x, y, 0) = std::round(value * 255.0f) / 255.0f;
        }
    return image;
}

Result<void> writeTourMedia(const std::filesystem::path& folder) {
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (auto r = writeImage(folder / "mask.png", makeDiscMask(64)); !r) return r;
    return writeImage(folder / "sky_cross.exr", makeSkyCross(32, glm::vec3(-0.35f, 0.12f, -0.93f), 2000.0f));
}

Image encodeAlphaIntensity(const Image& hdr) {
    Image encoded;
    encoded.width = hdr.width;
    encoded.height = hdr.height;
    encoded.channels = 4;
    encoded.bitsPerChannel = 8;
    encoded.pixels.resize(static_cast<size_t>(hdr.width) * hdr.height * 4);
    for (int y = 0; y < hdr.height; ++y)
        for (int x = 0; x < hdr.width; ++x) {
            glm::vec3 c(hdr.at(x, y, 0));
            for (int k = 1; k < std::min(hdr.channels, 3); ++k) c[k] = hdr.at(x, y, k);
            glm::vec4 texel = encodeHdr(HdrEncoding::Rgba8x64, c);
            for (int k = 0; k < 4; ++k) encoded.at(x, y, k) = texel[k];
        }
    return encoded;
}

glm::vec3 decodeAlphaIntensity(float r, float g, float b, float a) {
    return decodeHdr(HdrEncoding::Rgba8x64, glm::vec4(r, g, b, a));
}

Image makeGhostMask(int size) {
    Image image;
    image.width = image.height = size;
    image.channels = 4;
    image.bitsPerChannel = 8;
    image.pixels.resize(static_cast<size_t>(size) * size * 4);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            float dx = (x + 0.5f) / size - 0.5f, dy = (y + 0.5f) / size - 0.5f;
            float t = std::clamp((0.5f - std::sqrt(dx * dx + dy * dy)) / 0.2f, 0.0f, 1.0f);
            float alpha = t * t * (3.0f - 2.0f * t);
            for (int k = 0; k < 3; ++k) image.at(x, y, k) = 1.0f;
            image.at(x, y, 3) = std::round(alpha * 255.0f) / 255.0f;
        }
    return image;
}

Image makeHdrTestScene(int width, int height) {
    Image image;
    image.width = width;
    image.height = height;
    image.channels = 3;
    image.highDynamicRange = true;
    image.pixels.assign(static_cast<size_t>(width) * height * 3, 0.0f);
    auto set = [&](int x, int y, glm::vec3 c) {
        if (x < 0 || y < 0 || x >= width || y >= height) return;
        for (int k = 0; k < 3; ++k) image.at(x, y, k) = c[k];
    };
    // Image rows run top to bottom; v = 0 at the top.
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float u = (x + 0.5f) / width, v = (y + 0.5f) / height;
            glm::vec3 c;
            if (v < 0.55f) {
                float t = v / 0.55f;
                c = glm::mix(glm::vec3(0.3f, 0.6f, 2.0f), glm::vec3(1.6f, 1.4f, 1.1f), t * t);
            } else {
                float t = (v - 0.55f) / 0.45f;
                // Fine stripes give the floor detail that blurs and reductions must keep apart.
                float stripe = 0.75f + 0.25f * std::sin(u * 80.0f);
                c = glm::mix(glm::vec3(0.05f, 0.045f, 0.04f), glm::vec3(0.002f), t) * stripe;
            }
            set(x, y, c);
        }
    auto rect = [&](float u0, float v0, float u1, float v1, glm::vec3 c) {
        for (int y = int(v0 * height); y < int(v1 * height); ++y)
            for (int x = int(u0 * width); x < int(u1 * width); ++x) set(x, y, c);
    };
    rect(0.08f, 0.15f, 0.28f, 0.45f, glm::vec3(20.0f, 19.0f, 17.0f));  // window
    for (int y = 0; y < height; ++y)                                     // lamp disc
        for (int x = 0; x < width; ++x) {
            float dx = (x + 0.5f) / width - 0.62f, dy = (y + 0.5f) / height - 0.3f;
            if (dx * dx + dy * dy < 0.03f * 0.03f) set(x, y, glm::vec3(200.0f, 150.0f, 90.0f));
        }
    int lx = width * 4 / 5, ly = height / 5;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) set(lx + dx, ly + dy, glm::vec3(5000.0f, 4800.0f, 4500.0f));
    set(width / 3, height * 7 / 10, glm::vec3(60000.0f, 60000.0f, 60000.0f));  // a firefly
    for (int x = width / 2; x < width * 9 / 10; ++x) set(x, height * 6 / 10, glm::vec3(50.0f, 30.0f, 10.0f));
    return image;
}

Result<void> writeChapterMedia(const std::filesystem::path& folder) {
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    Image sky = makeSkyCross(256, kChapterSunDirection, kChapterSunIntensity, 4);
    WriteOptions half;
    half.exrHalf = true;
    if (auto r = writeImage(folder / "sky_cross.exr", sky, half); !r) return r;
    if (auto r = writeImage(folder / "sky_cross_alpha64.png", encodeAlphaIntensity(sky)); !r) return r;
    if (auto r = writeImage(folder / "ghost_mask.png", makeGhostMask(128)); !r) return r;
    return writeImage(folder / "hdr_scene.exr", makeHdrTestScene(512, 512));
}

}  // namespace rmfx::samples
