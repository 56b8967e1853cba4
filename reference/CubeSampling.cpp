#include "reference/CubeSampling.h"

#include <cmath>

#include <glm/common.hpp>

namespace rmfx::test {

static glm::dvec4 texel(const Image& face, int x, int y) {
    glm::dvec4 v(0.0, 0.0, 0.0, 1.0);
    if (face.channels < 3) return glm::dvec4(glm::dvec3(face.at(x, y, 0)), 1.0);
    for (int c = 0; c < face.channels; ++c) v[c] = face.at(x, y, c);
    return v;
}

CubeSample sampleCubeBilinear(const CubeFaces& faces, glm::dvec3 r) {
    glm::dvec3 a = glm::abs(r);
    int face;
    double sc, tc, ma;
    if (a.x >= a.y && a.x >= a.z) {
        face = r.x > 0 ? 0 : 1;
        sc = r.x > 0 ? -r.z : r.z;
        tc = -r.y;
        ma = a.x;
    } else if (a.y >= a.z) {
        face = r.y > 0 ? 2 : 3;
        sc = r.x;
        tc = r.y > 0 ? r.z : -r.z;
        ma = a.y;
    } else {
        face = r.z > 0 ? 4 : 5;
        sc = r.z > 0 ? r.x : -r.x;
        tc = -r.y;
        ma = a.z;
    }
    const Image& image = faces[face];
    const int n = image.width;
    double x = (sc / ma + 1.0) / 2.0 * n - 0.5, y = (tc / ma + 1.0) / 2.0 * n - 0.5;
    double x0 = std::floor(x), y0 = std::floor(y);
    int i = static_cast<int>(x0), j = static_cast<int>(y0);
    CubeSample sample;
    if (i < 0 || j < 0 || i + 1 >= n || j + 1 >= n) {
        sample.nearEdge = true;
        return sample;
    }
    double fx = x - x0, fy = y - y0;
    glm::dvec4 top = glm::mix(texel(image, i, j), texel(image, i + 1, j), fx);
    glm::dvec4 bottom = glm::mix(texel(image, i, j + 1), texel(image, i + 1, j + 1), fx);
    sample.value = glm::mix(top, bottom, fy);
    return sample;
}

}  // namespace rmfx::test
