#include "ffx_dof_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace ffxdof::metrics {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kPi = 3.14159265358979323846;

double clamp01(double value) { return std::clamp(value, 0.0, 1.0); }

void checkSameSize(uint32_t w0, uint32_t h0, uint32_t w1, uint32_t h1, const char* what) {
    if (w0 != w1 || h0 != h1) {
        throw std::invalid_argument(std::string(what) + ": sizes differ (" + std::to_string(w0) + "x" +
                                    std::to_string(h0) + " and " + std::to_string(w1) + "x" + std::to_string(h1) + ")");
    }
}

void checkPair(const io::ImageRGBA& a, const io::ImageRGBA& b, const Mask* mask) {
    checkSameSize(a.width, a.height, b.width, b.height, "images");
    if (a.pixels.size() != size_t(a.width) * a.height * 4 || b.pixels.size() != a.pixels.size()) {
        throw std::invalid_argument("image pixel count does not match its size");
    }
    if (mask && mask->size() != size_t(a.width) * a.height) throw std::invalid_argument("mask size differs");
}

// Luminance of clamped RGB, per pixel.
std::vector<double> clampedLuminance(const io::ImageRGBA& image) {
    std::vector<double> result(size_t(image.width) * image.height);
    for (size_t i = 0; i < result.size(); ++i) {
        const float* p = &image.pixels[i * 4];
        result[i] = 0.2126 * clamp01(p[0]) + 0.7152 * clamp01(p[1]) + 0.0722 * clamp01(p[2]);
    }
    return result;
}

// Separable Gaussian blur with edge clamping.
std::vector<double> gaussianBlur(const std::vector<double>& source, uint32_t width, uint32_t height,
                                 const std::vector<double>& kernel) {
    const int radius = int(kernel.size() / 2);
    std::vector<double> horizontal(source.size()), result(source.size());
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            double sum = 0.0;
            for (int k = -radius; k <= radius; ++k) {
                const int sx = std::clamp(int(x) + k, 0, int(width) - 1);
                sum += kernel[k + radius] * source[size_t(y) * width + sx];
            }
            horizontal[size_t(y) * width + x] = sum;
        }
    }
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            double sum = 0.0;
            for (int k = -radius; k <= radius; ++k) {
                const int sy = std::clamp(int(y) + k, 0, int(height) - 1);
                sum += kernel[k + radius] * horizontal[size_t(sy) * width + x];
            }
            result[size_t(y) * width + x] = sum;
        }
    }
    return result;
}

RegionScore regionScore(const io::ImageRGBA& reference, const io::ImageRGBA& test, const Mask& mask) {
    return {psnr(reference, test, &mask), countPixels(mask)};
}

}  // namespace

double meanSquaredError(const io::ImageRGBA& reference, const io::ImageRGBA& test, const Mask* mask) {
    checkPair(reference, test, mask);
    double sum = 0.0;
    size_t count = 0;
    for (size_t i = 0; i < size_t(reference.width) * reference.height; ++i) {
        if (mask && !(*mask)[i]) continue;
        for (int c = 0; c < 3; ++c) {
            const double difference = clamp01(reference.pixels[i * 4 + c]) - clamp01(test.pixels[i * 4 + c]);
            sum += difference * difference;
        }
        ++count;
    }
    return count ? sum / (3.0 * count) : kNaN;
}

double psnrFromMse(double mse) {
    if (std::isnan(mse)) return kNaN;
    if (mse <= 0.0) return std::numeric_limits<double>::infinity();
    return -10.0 * std::log10(mse);
}

double psnr(const io::ImageRGBA& reference, const io::ImageRGBA& test, const Mask* mask) {
    return psnrFromMse(meanSquaredError(reference, test, mask));
}

double maxAbsDifference(const io::ImageRGBA& reference, const io::ImageRGBA& test, const Mask* mask) {
    checkPair(reference, test, mask);
    double largest = 0.0;
    for (size_t i = 0; i < size_t(reference.width) * reference.height; ++i) {
        if (mask && !(*mask)[i]) continue;
        for (int c = 0; c < 3; ++c) {
            largest =
                std::max(largest, std::abs(clamp01(reference.pixels[i * 4 + c]) - clamp01(test.pixels[i * 4 + c])));
        }
    }
    return largest;
}

double ssim(const io::ImageRGBA& reference, const io::ImageRGBA& test) {
    checkPair(reference, test, nullptr);
    const uint32_t w = reference.width, h = reference.height;
    std::vector<double> kernel(11);
    double kernelSum = 0.0;
    for (int i = 0; i < 11; ++i) kernelSum += kernel[i] = std::exp(-double((i - 5) * (i - 5)) / (2.0 * 1.5 * 1.5));
    for (double& k : kernel) k /= kernelSum;

    const std::vector<double> x = clampedLuminance(reference), y = clampedLuminance(test);
    std::vector<double> xx(x.size()), yy(x.size()), xy(x.size());
    for (size_t i = 0; i < x.size(); ++i) xx[i] = x[i] * x[i], yy[i] = y[i] * y[i], xy[i] = x[i] * y[i];
    const std::vector<double> muX = gaussianBlur(x, w, h, kernel), muY = gaussianBlur(y, w, h, kernel);
    const std::vector<double> sXX = gaussianBlur(xx, w, h, kernel), sYY = gaussianBlur(yy, w, h, kernel),
                              sXY = gaussianBlur(xy, w, h, kernel);
    const double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
    double sum = 0.0;
    for (size_t i = 0; i < x.size(); ++i) {
        const double varX = sXX[i] - muX[i] * muX[i], varY = sYY[i] - muY[i] * muY[i];
        const double covariance = sXY[i] - muX[i] * muY[i];
        sum += ((2.0 * muX[i] * muY[i] + c1) * (2.0 * covariance + c2)) /
               ((muX[i] * muX[i] + muY[i] * muY[i] + c1) * (varX + varY + c2));
    }
    return sum / double(x.size());
}

io::ImageR cocRadiusMap(const ref::Camera& camera, const io::ImageR& linearDepth) {
    checkSameSize(camera.width, camera.height, linearDepth.width, linearDepth.height, "camera and depth");
    io::ImageR radius(linearDepth.width, linearDepth.height);
    for (size_t i = 0; i < radius.pixels.size(); ++i) {
        const double depth = linearDepth.pixels[i];
        if (!(std::isfinite(depth) && depth > 0.0)) {
            throw std::invalid_argument("depth at pixel " + std::to_string(i % radius.width) + "," +
                                        std::to_string(i / radius.width) + " is not a positive finite distance");
        }
        radius.pixels[i] = float(camera.cocRadiusPixels(depth));
    }
    return radius;
}

namespace {

// Marks the pixels of `candidates` within `width` px (exact Euclidean distance, centre to centre) of a
// pixel of `sources`: first the distance along each row, then the minimum of dy^2 + dx^2 over the rows
// within the width.
Mask withinDistance(const Mask& sources, const Mask& candidates, uint32_t w, uint32_t h, double width) {
    const size_t count = size_t(w) * h;
    const int band = int(std::floor(width));
    const double limit2 = width * width;
    constexpr int kFar = 1 << 20;
    std::vector<int> rowDistance(count, kFar);
    for (uint32_t y = 0; y < h; ++y) {
        int last = -kFar;
        for (uint32_t x = 0; x < w; ++x) {
            if (sources[size_t(y) * w + x]) last = int(x);
            rowDistance[size_t(y) * w + x] = std::min(kFar, int(x) - last);
        }
        last = 2 * kFar;
        for (int x = int(w) - 1; x >= 0; --x) {
            if (sources[size_t(y) * w + x]) last = x;
            rowDistance[size_t(y) * w + x] = std::min(rowDistance[size_t(y) * w + x], last - x);
        }
    }
    Mask result(count, 0);
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            if (!candidates[i]) continue;
            for (int dy = -band; dy <= band; ++dy) {
                const int sy = int(y) + dy;
                if (sy < 0 || sy >= int(h)) continue;
                const double dx = rowDistance[size_t(sy) * w + x];
                if (dx * dx + double(dy) * dy <= limit2) {
                    result[i] = 1;
                    break;
                }
            }
        }
    }
    return result;
}

}  // namespace

RegionMasks classifyRegions(const io::ImageR& radiusPixels, double haloWidthPixels, double nearEdgeWidthPixels) {
    const uint32_t w = radiusPixels.width, h = radiusPixels.height;
    const size_t count = size_t(w) * h;
    RegionMasks masks{Mask(count, 0), Mask(count, 0), Mask(count, 0), Mask(count, 0), Mask(count, 0)};
    for (size_t i = 0; i < count; ++i) {
        const float r = radiusPixels.pixels[i];
        if (std::abs(r) < 1.0f) {
            masks.inFocus[i] = 1;
        } else if (r > 0.0f) {
            masks.nearField[i] = 1;
        } else {
            masks.farField[i] = 1;
        }
    }
    masks.haloBand = withinDistance(masks.inFocus, masks.farField, w, h, haloWidthPixels);
    Mask notNear(count, 0);
    for (size_t i = 0; i < count; ++i) notNear[i] = masks.nearField[i] ? 0 : 1;
    masks.nearEdge = withinDistance(notNear, masks.nearField, w, h, nearEdgeWidthPixels);
    return masks;
}

size_t countPixels(const Mask& mask) { return size_t(std::count(mask.begin(), mask.end(), uint8_t(1))); }

Comparison compareImages(const io::ImageRGBA& reference, const io::ImageRGBA& test, const io::ImageR* radiusPixels) {
    Comparison result;
    result.psnr = psnr(reference, test);
    result.ssim = ssim(reference, test);
    if (radiusPixels) {
        checkSameSize(reference.width, reference.height, radiusPixels->width, radiusPixels->height,
                      "images and CoC map");
        const RegionMasks masks = classifyRegions(*radiusPixels);
        result.hasRegions = true;
        result.inFocus = regionScore(reference, test, masks.inFocus);
        result.nearField = regionScore(reference, test, masks.nearField);
        result.farField = regionScore(reference, test, masks.farField);
        result.haloBand = regionScore(reference, test, masks.haloBand);
        result.nearEdge = regionScore(reference, test, masks.nearEdge);
    }
    return result;
}

std::string formatComparison(const Comparison& comparison) {
    char line[160];
    std::string text;
    std::snprintf(line, sizeof line, "psnr %.2f dB\nssim %.4f\n", comparison.psnr, comparison.ssim);
    text += line;
    if (comparison.hasRegions) {
        const std::pair<const char*, const RegionScore*> regions[] = {{"in-focus", &comparison.inFocus},
                                                                      {"near-field", &comparison.nearField},
                                                                      {"far-field", &comparison.farField},
                                                                      {"halo-band", &comparison.haloBand},
                                                                      {"near-edge", &comparison.nearEdge}};
        for (const auto& [name, score] : regions) {
            std::snprintf(line, sizeof line, "psnr %s %.2f dB (%zu px)\n", name, score->psnr, score->pixels);
            text += line;
        }
    }
    return text;
}

BokehMeasurement measureBokeh(const io::ImageRGBA& image, const io::ImageRGBA* background) {
    if (background) checkPair(image, *background, nullptr);
    const uint32_t w = image.width, h = image.height;
    std::vector<double> level(size_t(w) * h);
    BokehMeasurement m;
    double sumX = 0.0, sumY = 0.0;
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            double value = luminance(&image.pixels[i * 4]);
            if (background) value -= luminance(&background->pixels[i * 4]);
            level[i] = value;
            m.energy += value;
            sumX += value * (x + 0.5);
            sumY += value * (y + 0.5);
        }
    }
    if (!(m.energy > 0.0)) throw std::invalid_argument("bokeh measurement: the image holds no energy");
    m.centerX = sumX / m.energy;
    m.centerY = sumY / m.energy;
    const auto distance2 = [&](uint32_t x, uint32_t y) {
        const double dx = x + 0.5 - m.centerX, dy = y + 0.5 - m.centerY;
        return dx * dx + dy * dy;
    };
    // A uniform disc of radius R has a mean squared distance of R^2 / 2: a first estimate that finds
    // the inner level, whose half then defines the disc's edge.
    double moment = 0.0;
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) moment += level[size_t(y) * w + x] * distance2(x, y);
    }
    const double firstRadius = std::sqrt(2.0 * std::max(moment, 0.0) / m.energy);
    const auto innerStatistics = [&](double radius, double& mean, double& deviation) {
        double sum = 0.0, sum2 = 0.0;
        size_t count = 0;
        for (uint32_t y = 0; y < h; ++y) {
            for (uint32_t x = 0; x < w; ++x) {
                if (distance2(x, y) > radius * radius) continue;
                const double value = level[size_t(y) * w + x];
                sum += value, sum2 += value * value, ++count;
            }
        }
        if (count == 0) {
            mean = deviation = 0.0;
            return;
        }
        mean = sum / count;
        deviation = std::sqrt(std::max(0.0, sum2 / count - mean * mean));
    };
    double innerLevel = 0.0, deviation = 0.0;
    innerStatistics(std::max(0.75, 0.5 * firstRadius), innerLevel, deviation);
    size_t brightPixels = 0;
    for (double value : level) brightPixels += value > 0.5 * innerLevel ? 1 : 0;
    m.radius = std::sqrt(brightPixels / kPi);
    double mean = 0.0;
    innerStatistics(std::max(0.75, 0.7 * m.radius), mean, deviation);
    m.flatness = mean > 0.0 ? deviation / mean : kNaN;
    m.innerLevel = mean;
    innerStatistics(std::max(1.0, 0.15 * m.radius), m.centreLevel, deviation);

    // Bilinear level at a point (pixel centres at +0.5), zero outside the image.
    const auto levelAt = [&](double px, double py) {
        const double fx = px - 0.5, fy = py - 0.5;
        const double x0 = std::floor(fx), y0 = std::floor(fy);
        double value = 0.0;
        for (int k = 0; k < 4; ++k) {
            const double x = x0 + (k & 1), y = y0 + (k >> 1);
            if (x < 0.0 || y < 0.0 || x >= double(w) || y >= double(h)) continue;
            const double weight = (1.0 - std::abs(fx - x)) * (1.0 - std::abs(fy - y));
            value += weight * level[size_t(y) * w + size_t(x)];
        }
        return value;
    };
    constexpr int kRimDirections = 64;
    const double reachLimit = 2.0 * m.radius + 4.0;
    for (int k = 0; k < kRimDirections; ++k) {
        const double angle = 2.0 * kPi * k / kRimDirections;
        const double dx = std::cos(angle), dy = std::sin(angle);
        double rim = 0.0;
        for (double t = reachLimit; t > 0.0; t -= 0.05) {
            if (levelAt(m.centerX + t * dx, m.centerY + t * dy) >= 0.5 * m.innerLevel) {
                rim = t;
                break;
            }
        }
        m.rimDeviation = std::max(m.rimDeviation, std::abs(rim - m.radius));
    }
    return m;
}

double bokehGlow(const io::ImageRGBA& image, const BokehMeasurement& disc, double distance,
                 const io::ImageRGBA* background) {
    if (background) checkPair(image, *background, nullptr);
    if (!(disc.innerLevel > 0.0)) throw std::invalid_argument("bokehGlow: the disc has no inner level");
    double brightest = 0.0;
    for (uint32_t y = 0; y < image.height; ++y) {
        for (uint32_t x = 0; x < image.width; ++x) {
            const double dx = x + 0.5 - disc.centerX, dy = y + 0.5 - disc.centerY;
            if (dx * dx + dy * dy <= distance * distance) continue;
            const size_t i = size_t(y) * image.width + x;
            double value = luminance(&image.pixels[i * 4]);
            if (background) value -= luminance(&background->pixels[i * 4]);
            brightest = std::max(brightest, value);
        }
    }
    return brightest / disc.innerLevel;
}

BokehCheck checkBokeh(const BokehMeasurement& measured, double expectedRadius, double expectedEnergy,
                      const BokehTolerances& tolerances) {
    BokehCheck check;
    check.radiusOk = std::abs(measured.radius - expectedRadius) <= tolerances.radiusPixels;
    check.flatOk = measured.flatness <= tolerances.flatness;
    check.energyOk = expectedEnergy > 0.0 && std::abs(measured.energy / expectedEnergy - 1.0) <= tolerances.energy;
    char line[256];
    std::snprintf(line, sizeof line,
                  "radius %.2f px (expected %.2f +- %.2f), flatness %.3f (limit %.3f), energy %.4g (expected %.4g "
                  "+- %.0f%%)",
                  measured.radius, expectedRadius, tolerances.radiusPixels, measured.flatness, tolerances.flatness,
                  measured.energy, expectedEnergy, tolerances.energy * 100.0);
    check.summary = line;
    return check;
}

double frameChange(const io::ImageRGBA& previous, const io::ImageRGBA& current) {
    if (previous.width != current.width || previous.height != current.height) {
        throw std::invalid_argument("frameChange: the frames differ in size");
    }
    const auto clamped = [](const float* rgba) {
        const float c[3] = {std::clamp(rgba[0], 0.0f, 1.0f), std::clamp(rgba[1], 0.0f, 1.0f),
                            std::clamp(rgba[2], 0.0f, 1.0f)};
        return luminance(c);
    };
    double sum = 0.0;
    const size_t pixels = size_t(current.width) * current.height;
    for (size_t i = 0; i < pixels; ++i) {
        sum += std::fabs(clamped(&current.pixels[i * 4]) - clamped(&previous.pixels[i * 4]));
    }
    return pixels ? sum / double(pixels) : 0.0;
}

void TemporalChange::add(const io::ImageRGBA& frame) {
    if (!previous_.pixels.empty()) {
        sum_ += frameChange(previous_, frame);
        ++pairs_;
    }
    previous_ = frame;
}

}  // namespace ffxdof::metrics
