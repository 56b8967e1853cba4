#include "bench/accuracy/IdealStreak.h"

#include <cmath>

#include "bench/accuracy/IdealBloom.h"

namespace rmfx::accuracy {

double streakDecay(double length, int height) {
    double e = length * height;
    return e > 0.0 ? std::exp(-1.0 / e) : 0.0;
}

LinearImage streakAlong(const LinearImage& bright, int dx, int dy, double w) {
    const int width = bright.width, height = bright.height;
    LinearImage s(width, height);
    // Visit x + u before x: against the direction of u on both axes.
    for (int j = 0; j < height; ++j) {
        int y = dy > 0 ? height - 1 - j : j;
        for (int i = 0; i < width; ++i) {
            int x = dx > 0 ? width - 1 - i : i;
            int nx = x + dx, ny = y + dy;
            bool inside = nx >= 0 && nx < width && ny >= 0 && ny < height;
            for (int c = 0; c < 3; ++c)
                s.at(x, y, c) = (1.0 - w) * bright.at(x, y, c) + (inside ? w * s.at(nx, ny, c) : 0.0);
        }
    }
    return s;
}

LinearImage idealStreak(const LinearImage& sanitised, const StreakParameters& p) {
    LinearImage bright = brightPass(sanitised, p.threshold);
    double w = streakDecay(p.length, sanitised.height);
    LinearImage out = sanitised;
    for (int dy : {1, -1})
        for (int dx : {1, -1}) {
            LinearImage s = streakAlong(bright, dx, dy, w);
            for (size_t i = 0; i < out.rgb.size(); ++i) out.rgb[i] += p.strength * 0.25 * s.rgb[i];
        }
    return out;
}

}  // namespace rmfx::accuracy
