#include "reference/RayCastImage.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace rmfx::test {

RayCastImage rayCastImage(const MeshRayCast& cast, const SurfaceShading& shade, glm::dvec4 background,
                          const SurfaceFilter& comparable) {
    const glm::ivec2 size = cast.size();
    RayCastImage out;
    out.lower = RefImage(size.x, size.y, background);
    out.upper = out.lower;
    out.compared.assign(size_t(size.x) * size.y, 0);
    for (int j = 0; j < size.y; ++j)
        for (int i = 0; i < size.x; ++i) {
            const glm::dvec2 centre = cast.centre(i, j);
            const auto hit = cast.at(centre.x, centre.y);
            bool compared = cast.settled(i, j);
            if (hit) {
                const ExpectedRange range = shade(*hit);
                out.lower.at(i, j) = range.lower;
                out.upper.at(i, j) = range.upper;
                ++out.surfacePixels;
                compared = compared && (!comparable || comparable(*hit, i, j));
                if (compared) ++out.comparedSurfacePixels;
            }
            out.compared[size_t(j) * size.x + i] = compared;
        }
    return out;
}

RayCastDifference worstExcess(const RefImage& image, const RayCastImage& reference, int channels) {
    RayCastDifference d;
    if (image.width != reference.lower.width || image.height != reference.lower.height) {
        d.worst = std::numeric_limits<double>::infinity();
        return d;
    }
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            if (!reference.compared[size_t(y) * image.width + x]) continue;
            for (int c = 0; c < channels; ++c) {
                const double v = image.at(x, y)[c];
                double e = std::max({reference.lower.at(x, y)[c] - v, v - reference.upper.at(x, y)[c], 0.0});
                if (std::isnan(v)) e = std::numeric_limits<double>::infinity();
                if (e > d.worst || d.x < 0) d = {e, x, y, c};
            }
        }
    return d;
}

std::string RayCastDifference::describe(const RefImage& image, const RayCastImage& reference) const {
    std::ostringstream s;
    if (x < 0) return "no pixel compared";
    const glm::dvec4 got = image.at(x, y), lo = reference.lower.at(x, y), hi = reference.upper.at(x, y);
    s << "worst at pixel (" << x << ", " << y << " from the bottom) channel " << channel << ": got " << got[channel]
      << ", expected within [" << lo[channel] << ", " << hi[channel] << "]; pixel (" << got.r << ", " << got.g
      << ", " << got.b << ", " << got.a << "); " << reference.comparedSurfacePixels << " of "
      << reference.surfacePixels << " surface pixels compared";
    return s.str();
}

}  // namespace rmfx::test
