#pragma once
// The DirectX sample's Gaussian, 1 / sqrt(2 pi rho²) exp(-(x² + y²) / (2 rho²)); its kernels are
// normalised here to sum to 1 (see the 5x5 and bloom shaders).
float gaussianDistribution(float x, float y, float rho) {
    return exp(-(x * x + y * y) / (2.0 * rho * rho)) / sqrt(2.0 * 3.14159265358979 * rho * rho);
}
