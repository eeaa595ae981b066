// Image-quality metrics for ffx-dof: PSNR, SSIM, PSNR per depth-of-field region, and bokeh checks.
//
// Conventions. Images are linear RGB. PSNR and SSIM see values clamped to [0, 1] (peak 1), so that a
// few HDR highlights (tens or hundreds) do not swamp the figure: they measure what a display shows.
// PSNR of identical images (MSE 0) is +infinity; PSNR over an empty region is NaN. Images of
// different sizes are an error (std::invalid_argument).
#pragma once

#include "ffx_dof_imageio.h"
#include "ffx_dof_reference.h"

#include <cstdint>
#include <string>
#include <vector>

namespace ffxdof::metrics {

// One byte per pixel, 1 = in the region.
using Mask = std::vector<uint8_t>;

// Mean over pixels (and R, G, B) of the squared difference of clamped values; over the mask's
// pixels when a mask is given.
double meanSquaredError(const io::ImageRGBA& reference, const io::ImageRGBA& test, const Mask* mask = nullptr);
// 10 log10(1 / MSE) in dB.
double psnr(const io::ImageRGBA& reference, const io::ImageRGBA& test, const Mask* mask = nullptr);
double psnrFromMse(double mse);
// Largest |difference| of any clamped R, G or B value, over the mask's pixels when given.
double maxAbsDifference(const io::ImageRGBA& reference, const io::ImageRGBA& test, const Mask* mask = nullptr);

// Rec. 709 luminance of an RGBA pixel.
inline double luminance(const float* rgba) { return 0.2126 * rgba[0] + 0.7152 * rgba[1] + 0.0722 * rgba[2]; }

// Mean SSIM (Wang, Bovik, Sheikh, Simoncelli 2004) of the luminance of the clamped images: an 11x11
// Gaussian window with sigma 1.5, K1 = 0.01, K2 = 0.03, dynamic range 1. The window is clamped at the
// image border (edge pixels repeated), so every pixel counts and tiny images work.
double ssim(const io::ImageRGBA& reference, const io::ImageRGBA& test);

// Signed CoC radius in full-resolution pixels for every pixel of a linear depth image (metres):
// positive in the near field, negative in the far field (Camera::cocRadiusPixels).
io::ImageR cocRadiusMap(const ref::Camera& camera, const io::ImageR& linearDepth);

struct RegionMasks {
    Mask inFocus;    // |radius| < 1 px
    Mask nearField;  // radius >= 1 px (in front of the focus plane)
    Mask farField;   // radius <= -1 px (behind it)
    Mask haloBand;   // far-field pixels within haloWidth px (Euclidean, centre to centre) of an in-focus pixel
    Mask nearEdge;   // near-field pixels within nearEdgeWidth px of a pixel outside the near field (its silhouette)
};
RegionMasks classifyRegions(const io::ImageR& radiusPixels, double haloWidthPixels = 8.0,
                            double nearEdgeWidthPixels = 2.0);
size_t countPixels(const Mask& mask);

struct RegionScore {
    double psnr = 0.0;  // NaN when the region is empty
    size_t pixels = 0;
};

// Everything `ffx-dof compare` and the quality gates report for one pair of images.
struct Comparison {
    double psnr = 0.0;
    double ssim = 0.0;
    bool hasRegions = false;  // the region scores are filled only when a radius map was given
    RegionScore inFocus, nearField, farField, haloBand, nearEdge;
};
Comparison compareImages(const io::ImageRGBA& reference, const io::ImageRGBA& test,
                         const io::ImageR* radiusPixels = nullptr);
// Several lines, "psnr 31.20 dB", "ssim 0.9512", "psnr in-focus 40.10 dB (1234 px)", ...
std::string formatComparison(const Comparison& comparison);

// ---- temporal stability --------------------------------------------------------------------------

// How much a frame changes from the previous one: the mean over pixels of |luminance difference| of
// the clamped values. For a sequence, the mean of it over consecutive frames; the flicker of an effect
// is its output's figure over the truth's for the same camera move (1 = as steady as the truth).
double frameChange(const io::ImageRGBA& previous, const io::ImageRGBA& current);

// Accumulates frameChange over a sequence, one frame at a time (frames need not stay in memory).
class TemporalChange {
public:
    void add(const io::ImageRGBA& frame);  // std::invalid_argument when the size changes
    double mean() const { return pairs_ ? sum_ / double(pairs_) : 0.0; }
    size_t pairs() const { return pairs_; }

private:
    io::ImageRGBA previous_;
    double sum_ = 0.0;
    size_t pairs_ = 0;
};

// ---- bokeh ---------------------------------------------------------------------------------------

// A single bright disc on a known background (image minus background; no background means black).
struct BokehMeasurement {
    double centerX = 0.0, centerY = 0.0;  // luminance centroid, pixels (pixel centres at +0.5)
    double radius = 0.0;                  // sqrt(area / pi) of the pixels brighter than half the disc's inner level
    double flatness = 0.0;                // standard deviation / mean of the luminance within 0.7 radius
    double energy = 0.0;                  // sum of luminance over the image
    double innerLevel = 0.0;              // mean luminance within 0.7 radius
    double centreLevel = 0.0;             // mean luminance within max(1, 0.15 radius) px of the centroid
    // Largest distance of the rim from the circle of `radius` about the centroid, over 64 directions:
    // along each, the farthest point (bilinear, 1/20 px steps) at half the inner level or more.
    double rimDeviation = 0.0;
};
BokehMeasurement measureBokeh(const io::ImageRGBA& image, const io::ImageRGBA* background = nullptr);
// The brightest pixel (luminance, less the background's) farther than `distance` px from the
// measured disc's centroid, over the disc's inner level: the glow or tail beyond the disc.
double bokehGlow(const io::ImageRGBA& image, const BokehMeasurement& disc, double distance,
                 const io::ImageRGBA* background = nullptr);

struct BokehTolerances {
    double radiusPixels = 1.0;  // |radius - expected| <= this
    double flatness = 0.08;     // flatness <= this (a Gaussian blob measures about 0.13)
    double energy = 0.05;       // |energy / expected - 1| <= this
};
struct BokehCheck {
    bool radiusOk = false, flatOk = false, energyOk = false;
    bool ok() const { return radiusOk && flatOk && energyOk; }
    std::string summary;  // the measured and expected figures, one line
};
BokehCheck checkBokeh(const BokehMeasurement& measured, double expectedRadius, double expectedEnergy,
                      const BokehTolerances& tolerances = {});

}  // namespace ffxdof::metrics
