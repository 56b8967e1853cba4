#pragma once
// Float64 references of the DirectX SDK HDRLighting sample's maths (effects/hdr_lighting.xml),
// written from the sample's definitions (shared/seeds/001_…, shared/context/hdr-facts.md), not from
// the shaders. Images are RefImage (row 0 at the bottom); texel coordinates as in GL, texel (i, j)
// covering [i, i+1) x [j, j+1).

#include <array>
#include <vector>

#include <glm/vec3.hpp>

#include "reference/CpuImage.h"

namespace rmfx::test::hdr {

constexpr glm::dvec3 kLuminanceWeights{0.2125, 0.7154, 0.0721};
constexpr double kLogDelta = 0.0001;
constexpr double kBrightPassThreshold = 5.0;
constexpr double kBrightPassOffset = 10.0;
constexpr glm::dvec3 kBlueShiftVector{1.05, 0.97, 1.27};

// NaN, ±Inf and negative channels become 0 (the pipeline's first read of the scene).
glm::dvec3 finiteNonNegative(glm::dvec3 c);
double luminance(glm::dvec3 c);  // weights above, clamped at 0

// Each n x n block's mean over the texels it has (partial blocks at the right and top edges), of
// the sanitised texels: ceil(w / n) x ceil(h / n).
RefImage boxDownscale(const RefImage& image, int n);

struct LogAverage {
    double average = 0.0;  // exp(mean over the quarter texels of log(delta + Y))
    double peak = 0.0;     // the largest luminance of the (sanitised) full-size scene
};
LogAverage logAverage(const RefImage& quarter, const RefImage& scene);

// adapted + (current - adapted)(1 - 0.98^(30 dt)), and its closed form after `seconds` at any rate.
double adaptationStep(double adapted, double current, double dt);
double adaptedAfter(double initial, double current, double seconds);

glm::dvec3 exposeToKey(glm::dvec3 c, double key, double adapted);  // c · key / (adapted + 0.001)
RefImage brightPass(const RefImage& quarter, double adapted, double key);

// The sample's Gaussian 1/sqrt(2π ρ²) exp(-(x² + y²)/(2ρ²)).
double gaussianDistribution(double x, double y, double rho);
struct Tap {
    int x, y;
    double weight;
};
std::vector<Tap> gauss5x5Kernel();    // 13 taps |x| + |y| <= 2, ρ = 1, normalised to sum 1
std::vector<double> bloomKernel();    // 15 weights for offsets -7 .. 7, σ = 3, normalised to sum 1
// Convolutions with black outside the image.
RefImage convolve(const RefImage& image, const std::vector<Tap>& taps);
RefImage bloomPass(const RefImage& image, bool horizontal);

// Star types 0 Cross, 1 CrossFilter, 2 SnowCross, 3 Vertical, 4 SunnyCross.
struct StarLine {
    double angleRadians;  // clockwise from up on the screen
    double attenuation;
};
std::vector<StarLine> starLines(int type);
glm::dvec3 starColor(int colorRow, int sample, double chromaticAberration);
// The weight of sample i (0 .. 7) of pass p (0 .. 2) of a line, for a source of the given size,
// and its offset in texels; a zero weight where the sample drops the tap (0.9 of the image away).
struct StarTap {
    glm::dvec2 offset;
    glm::dvec3 weight;
};
std::array<StarTap, 8> starTaps(const StarLine& line, int pass, glm::ivec2 sourceSize, double chromaticAberration);
// Bilinear interpolation at a position in texels, black outside the image.
glm::dvec3 bilinearOrBlack(const RefImage& image, glm::dvec2 position);
RefImage starLinePass(const RefImage& source, const StarLine& line, int pass, double chromaticAberration);
RefImage starMerge(const std::vector<RefImage>& lines);  // mean of the lines

double blueShiftCoefficient(double adapted);  // saturate(1 - (adapted + 1.5) / 4.1)
glm::dvec3 blueShift(glm::dvec3 c, double adapted);
glm::dvec3 toneMapPerChannel(glm::dvec3 c, double key, double adapted);
// Reinhard et al. 2002: L = key Y / (adapted + 0.001), Ld = L (1 + L / white²) / (1 + L), c · Ld / Y.
glm::dvec3 toneMapPhotographic(glm::dvec3 c, double key, double adapted, double white);

struct FinalSettings {
    double key = 0.18;
    int toneMapOperator = 1;  // 0 none, 1 per channel, 2 photographic
    double whitePoint = 0.0;  // photographic: 0 means key · peak / (adapted + 0.001)
    bool blueShift = true;
    double bloomScale = 1.0;
    double starScale = 0.5;
};
// The final pass: output pixel (x, y) from the full-size scene, the 1/8 bloom and 1/4 star images
// (upsampled bilinearly, black outside), the adapted luminance and the scene's peak luminance.
RefImage finalComposite(const RefImage& scene, const RefImage& bloom, const RefImage& star, double adapted,
                        double peak, const FinalSettings& settings);

}  // namespace rmfx::test::hdr
