#include "io/image/CubeMapLayout.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <glm/geometric.hpp>

namespace rmfx {

namespace {

constexpr int kMaxFaceSize = 16384;

std::string sizeText(const Image& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height);
}

Image blankFace(const Image& source, int size) {
    Image face;
    face.width = size;
    face.height = size;
    face.channels = source.channels;
    face.highDynamicRange = source.highDynamicRange;
    face.bitsPerChannel = source.bitsPerChannel;
    face.pixels.assign(size_t(size) * size * source.channels, 0.0f);
    return face;
}

// Copies the N x N block at (left, top) of the source; rotated: turned by 180 degrees.
Image copyBlock(const Image& source, int left, int top, int size, bool rotated) {
    Image face = blankFace(source, size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const int sx = rotated ? left + size - 1 - x : left + x;
            const int sy = rotated ? top + size - 1 - y : top + y;
            for (int c = 0; c < source.channels; ++c) face.at(x, y, c) = source.at(sx, sy, c);
        }
    return face;
}

bool consistent(const Image& image) {
    return image.width > 0 && image.height > 0 && image.channels >= 1 && image.channels <= 4 &&
           image.pixels.size() == size_t(image.width) * image.height * image.channels;
}

// Bilinear sample at image coordinates (u, v) in [0, 1], wrapping in u and clamping in v.
void sampleWrapped(const Image& image, double u, double v, float* out) {
    const double fx = u * image.width - 0.5;
    const double fy = std::clamp(v * image.height - 0.5, 0.0, double(image.height - 1));
    const double x0f = std::floor(fx);
    const double y0f = std::floor(fy);
    const double tx = fx - x0f;
    const double ty = fy - y0f;
    const int x0 = ((int(x0f) % image.width) + image.width) % image.width;
    const int x1 = (x0 + 1) % image.width;
    const int y0 = int(y0f);
    const int y1 = std::min(y0 + 1, image.height - 1);
    for (int c = 0; c < image.channels; ++c) {
        const double top = image.at(x0, y0, c) * (1 - tx) + image.at(x1, y0, c) * tx;
        const double bottom = image.at(x0, y1, c) * (1 - tx) + image.at(x1, y1, c) * tx;
        out[c] = static_cast<float>(top * (1 - ty) + bottom * ty);
    }
}

}  // namespace

const char* cubeFaceName(int face) {
    static constexpr const char* names[] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
    return face >= 0 && face < 6 ? names[face] : "?";
}

glm::vec3 cubeFaceTexelDirection(int face, float u, float v) {
    const float a = 2.0f * u - 1.0f;
    const float b = 2.0f * v - 1.0f;
    glm::vec3 d(0.0f);
    switch (face) {
        case PositiveX: d = {1.0f, -b, -a}; break;
        case NegativeX: d = {-1.0f, -b, a}; break;
        case PositiveY: d = {a, 1.0f, b}; break;
        case NegativeY: d = {a, -1.0f, -b}; break;
        case PositiveZ: d = {a, -b, 1.0f}; break;
        case NegativeZ: d = {-a, -b, -1.0f}; break;
        default: return d;
    }
    return glm::normalize(d);
}

glm::vec3 equirectDirection(float u, float v) {
    const double pi = std::numbers::pi;
    const double phi = 2.0 * pi * (double(u) - 0.5);
    const double theta = pi * (0.5 - double(v));
    return {float(std::cos(theta) * std::sin(phi)), float(std::sin(theta)),
            float(-std::cos(theta) * std::cos(phi))};
}

glm::vec2 equirectCoordinates(const glm::vec3& direction) {
    const double pi = std::numbers::pi;
    const glm::dvec3 d = glm::normalize(glm::dvec3(direction));
    const double phi = std::atan2(d.x, -d.z);
    const double theta = std::asin(std::clamp(d.y, -1.0, 1.0));
    double u = phi / (2.0 * pi) + 0.5;
    if (u >= 1.0) u -= 1.0;
    return {float(u), float(0.5 - theta / pi)};
}

Result<CubeFaces> cubeFromCross(const Image& cross) {
    if (!consistent(cross))
        return Error{"cube cross image is empty or inconsistent (" + sizeText(cross) + ")"};
    const bool horizontal = cross.width % 4 == 0 && cross.width / 4 * 3 == cross.height;
    const bool vertical = cross.width % 3 == 0 && cross.width / 3 * 4 == cross.height;
    if (!horizontal && !vertical)
        return Error{"cube cross image is " + sizeText(cross) +
                     "; expected a horizontal cross (4:3) or a vertical cross (3:4) of whole square faces"};
    const int n = horizontal ? cross.width / 4 : cross.width / 3;
    CubeFaces faces;
    faces[PositiveX] = copyBlock(cross, 2 * n, n, n, false);
    faces[NegativeX] = copyBlock(cross, 0, n, n, false);
    faces[PositiveY] = copyBlock(cross, n, 0, n, false);
    faces[NegativeY] = copyBlock(cross, n, 2 * n, n, false);
    faces[PositiveZ] = copyBlock(cross, n, n, n, false);
    faces[NegativeZ] = horizontal ? copyBlock(cross, 3 * n, n, n, false) : copyBlock(cross, n, 3 * n, n, true);
    return faces;
}

Result<CubeFaces> cubeFromEquirect(const Image& panorama, int faceSize) {
    if (!consistent(panorama))
        return Error{"longitude/latitude image is empty or inconsistent (" + sizeText(panorama) + ")"};
    if (panorama.width != 2 * panorama.height)
        return Error{"longitude/latitude image is " + sizeText(panorama) + "; expected width = 2 x height"};
    const int n = faceSize == 0 ? std::max(1, panorama.height / 2) : faceSize;
    if (n < 1 || n > kMaxFaceSize)
        return Error{"cube face size " + std::to_string(n) + " is outside 1.." + std::to_string(kMaxFaceSize)};
    CubeFaces faces;
    for (int f = 0; f < 6; ++f) {
        faces[f] = blankFace(panorama, n);
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const glm::vec3 d = cubeFaceTexelDirection(f, (x + 0.5f) / n, (y + 0.5f) / n);
                const glm::vec2 uv = equirectCoordinates(d);
                sampleWrapped(panorama, uv.x, uv.y, &faces[f].at(x, y, 0));
            }
    }
    return faces;
}

Result<CubeFaces> cubeFromFaces(std::array<Image, 6> faces) {
    for (int f = 0; f < 6; ++f) {
        const Image& face = faces[f];
        const std::string name = std::string("cube face ") + cubeFaceName(f);
        if (!consistent(face))
            return Error{name + " is empty or inconsistent (" + sizeText(face) + ")"};
        if (face.width != face.height)
            return Error{name + " is " + sizeText(face) + "; cube faces must be square"};
        if (face.width != faces[0].width)
            return Error{name + " is " + sizeText(face) + " but +X is " + sizeText(faces[0]) +
                         "; cube faces must have one size"};
        if (face.channels != faces[0].channels)
            return Error{name + " has " + std::to_string(face.channels) + " channels but +X has " +
                         std::to_string(faces[0].channels)};
    }
    return CubeFaces(std::move(faces));
}

Result<CubeFaces> cubeFromImage(const Image& image) {
    if (image.height > 0 && image.width == 2 * image.height)
        return cubeFromEquirect(image);
    if (image.width * 3 == image.height * 4 || image.width * 4 == image.height * 3)
        return cubeFromCross(image);
    return Error{"cube map image is " + sizeText(image) +
                 "; expected a 2:1 longitude/latitude image, a 4:3 horizontal cross or a 3:4 vertical cross"};
}

}  // namespace rmfx
