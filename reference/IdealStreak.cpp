#include "reference/IdealStreak.h"

#include <cmath>

#include "reference/IdealBloom.h"

namespace rmfx::test {

double streakDecay(double length, int height) {
    double e = length * height;
    return e > 0.0 ? std::exp(-1.0 / e) : 0.0;
}

RefImage streakAlong(const RefImage& bright, int dx, int dy, double w) {
    const int width = bright.width, height = bright.height;
    RefImage s(width, height);
    // Visit x + u before x: against the direction of u on both axes.
    for (int j = 0; j < height; ++j) {
        int y = dy > 0 ? height - 1 - j : j;
        for (int i = 0; i < width; ++i) {
            int x = dx > 0 ? width - 1 - i : i;
            int nx = x + dx, ny = y + dy;
            bool inside = nx >= 0 && nx < width && ny >= 0 && ny < height;
            for (int c = 0; c < 3; ++c)
                s.at(x, y)[c] = (1.0 - w) * bright.at(x, y)[c] + (inside ? w * s.at(nx, ny)[c] : 0.0);
        }
    }
    return s;
}

RefImage idealStreak(const RefImage& sanitised, const StreakParameters& p) {
    RefImage bright = brightPass(sanitised, p.threshold);
    double w = streakDecay(p.length, sanitised.height);
    RefImage out = sanitised;
    // Down-right, down-left, up-right, up-left (rows are bottom-up): the order the bench has always
    // summed the four diagonals in, so that its results stay bit-identical.
    for (int dy : {-1, 1})
        for (int dx : {1, -1}) {
            RefImage s = streakAlong(bright, dx, dy, w);
            for (size_t i = 0; i < out.texels.size(); ++i)
                for (int c = 0; c < 3; ++c) out.texels[i][c] += p.strength * 0.25 * s.texels[i][c];
        }
    return out;
}

}  // namespace rmfx::test
