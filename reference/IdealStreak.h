#pragma once
// The streak stage's ideal (effects/variants/streak.xml), what `rmfx bench` measures the streak
// variants against: result* = S + Streak_Strength · ¼ Σ_u streak_u over the four diagonals u,
// streak_u(x) = (1 − w) Σ_k≥0 w^k B(x + k u) with w = exp(−1 / (Streak_Length · H)),
// B = max(S − Streak_Threshold, 0), black outside. Float64 on rgb; alpha is not used.

#include "reference/CpuImage.h"

namespace rmfx::test {

struct StreakParameters {
    double threshold = 1.0;
    double strength = 0.5;
    double length = 0.19;  // e-folding length, fraction of the image height
};

// Per-step decay of one full-resolution diagonal step.
double streakDecay(double length, int height);

// streak_u for the direction u = (dx, dy) (each ±1, in RefImage's coordinates: dy = +1 is up),
// exactly, by the recursion s(x) = (1 − w) B(x) + w s(x + u).
RefImage streakAlong(const RefImage& bright, int dx, int dy, double w);

RefImage idealStreak(const RefImage& sanitised, const StreakParameters& p);

}  // namespace rmfx::test
