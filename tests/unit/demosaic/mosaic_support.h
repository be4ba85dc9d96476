// SPDX-License-Identifier: Apache-2.0
// Test helpers of the demosaic tests: full-colour truth images (flat fields, ramps, a colour
// edge chart) and the test's own CFA sampling of them, written independently of lib/demosaic
// from the layouts drawn in cfa.h.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "glint/demosaic/demosaic.h"

namespace glint::demosaic::test {

/// A full-colour truth: R, G, B and (for TrueSense) pan at every pixel.
struct Truth {
    std::size_t width = 0;
    std::size_t height = 0;
    std::vector<std::array<double, 4>> rgbp;  ///< R, G, B, pan

    const std::array<double, 4>& at(std::size_t x, std::size_t y) const {
        return rgbp[y * width + x];
    }
};

/// The filter letter of a pixel, from the drawings: Bayer phase names read row by row, and
/// the TrueSense rows "PGPR", "GPRP", "PBPG", "BPGP".
inline char filter_letter(CfaPattern pattern, BayerPhase phase, std::size_t x, std::size_t y) {
    if (pattern == CfaPattern::truesense) {
        static const char* const kRows[4] = {"PGPR", "GPRP", "PBPG", "BPGP"};
        return kRows[y % 4][x % 4];
    }
    const std::string name = bayer_phase_name(phase);  // e.g. "grbg"
    return static_cast<char>(name[(y % 2) * 2 + (x % 2)] - 'a' + 'A');
}

inline std::size_t channel_of_letter(char letter) {
    switch (letter) {
        case 'R':
            return 0;
        case 'G':
            return 1;
        case 'B':
            return 2;
        default:
            return 3;
    }
}

/// Samples `truth` through the filter array.
inline Plane mosaic_of(const Truth& truth, CfaPattern pattern, BayerPhase phase) {
    Plane plane{truth.width, truth.height, std::vector<double>(truth.width * truth.height)};
    for (std::size_t y = 0; y < truth.height; ++y) {
        for (std::size_t x = 0; x < truth.width; ++x) {
            plane.at(x, y) = truth.at(x, y)[channel_of_letter(filter_letter(pattern, phase, x, y))];
        }
    }
    return plane;
}

/// A flat field.
inline Truth flat_truth(std::size_t width, std::size_t height, std::array<double, 4> value) {
    return Truth{width, height, std::vector<std::array<double, 4>>(width * height, value)};
}

/// Each channel a different linear function of x and y.
inline Truth ramp_truth(std::size_t width, std::size_t height) {
    Truth t{width, height, {}};
    for (std::size_t y = 0; y < height; ++y) {
        for (std::size_t x = 0; x < width; ++x) {
            const double fx = static_cast<double>(x);
            const double fy = static_cast<double>(y);
            t.rgbp.push_back({100 + 3 * fx + 2 * fy, 400 - 5 * fx + 7 * fy, 250 + 0.5 * fx - 4 * fy,
                              300 + fx + fy});
        }
    }
    return t;
}

/// A colour edge chart: a checkerboard of 12-pixel squares turned by 5°, bright (1) and
/// dark (0.25), times a colour whose hue turns smoothly across the chart (moderate
/// saturation: each channel 0.6 ± 0.15 of 3000 DN). Every pixel is the mean of 4 × 4 point
/// samples, so edges are area-sampled as a sensor sees them. Slanted edges in every hue,
/// with the inter-channel correlation of natural scenes that MHC relies on.
inline Truth edge_chart(std::size_t width, std::size_t height) {
    constexpr int kSub = 4;
    constexpr double kPi = 3.14159265358979323846;
    const double angle = 5.0 * kPi / 180.0;
    Truth t{width, height, {}};
    for (std::size_t y = 0; y < height; ++y) {
        for (std::size_t x = 0; x < width; ++x) {
            std::array<double, 3> c{};
            for (int j = 0; j < kSub; ++j) {
                for (int i = 0; i < kSub; ++i) {
                    const double fx = static_cast<double>(x) + (i + 0.5) / kSub;
                    const double fy = static_cast<double>(y) + (j + 0.5) / kSub;
                    const double u = std::cos(angle) * fx + std::sin(angle) * fy;
                    const double v = -std::sin(angle) * fx + std::cos(angle) * fy + 50.0;
                    const bool bright =
                        static_cast<long>(std::floor(u / 12.0) + std::floor(v / 12.0)) % 2 == 0;
                    const double phase =
                        2.0 * kPi *
                        (fx / static_cast<double>(width) + 0.3 * fy / static_cast<double>(height));
                    for (int k = 0; k < 3; ++k) {
                        const double hue = 0.6 + 0.15 * std::cos(phase - 2.1 * k);
                        c[static_cast<std::size_t>(k)] +=
                            3000.0 * (bright ? 1.0 : 0.25) * hue / (kSub * kSub);
                    }
                }
            }
            t.rgbp.push_back({c[0], c[1], c[2], (c[0] + c[1] + c[2]) / 3});
        }
    }
    return t;
}

/// Mean absolute error of the R, G, B of `image` against `truth` over pixels at least
/// `margin` from every edge.
inline double mean_abs_error(const RgbImage& image, const Truth& truth, std::size_t margin) {
    double sum = 0;
    std::size_t n = 0;
    for (std::size_t y = margin; y + margin < truth.height; ++y) {
        for (std::size_t x = margin; x + margin < truth.width; ++x) {
            for (std::size_t c = 0; c < 3; ++c, ++n) {
                sum += std::fabs(image.at(x, y, c) - truth.at(x, y)[c]);
            }
        }
    }
    return sum / static_cast<double>(n);
}

/// Deterministic pseudo-random values in [0, 4096) (a small LCG; tests only).
inline Plane random_plane(std::size_t width, std::size_t height, unsigned seed) {
    Plane plane{width, height, {}};
    std::uint64_t state = 0x9e3779b97f4a7c15ull * (seed + 1);
    for (std::size_t i = 0; i < width * height; ++i) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        plane.values.push_back(static_cast<double>((state >> 33) % 4096));
    }
    return plane;
}

constexpr BayerPhase kPhases[] = {BayerPhase::rggb, BayerPhase::grbg, BayerPhase::gbrg,
                                  BayerPhase::bggr};

}  // namespace glint::demosaic::test
