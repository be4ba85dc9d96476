// SPDX-License-Identifier: Apache-2.0
// The PSF of a focal plane (PsfSampler) and its two-step sampling in PixelRaySource:
//  - the Gaussian draw has mean 0 and standard deviation σ per axis, and an image PSF's draws
//    fall in its pixels in proportion to their values, inside its extent;
//  - slanted-edge MTF (the ISO 12233 edge method, written here): a black/white edge at 5° seen
//    through PixelRaySource's sample rays (area point, then PSF offset, projected back through
//    the camera) gives an MTF equal to the pixel aperture's sinc times the Gaussian's
//    exp(−2π²σ²f²) at 0.1–0.5 cycles/pixel within 0.03, for σ = 0.5, 1 and 2 pixels and for an
//    image PSF drawn from the Gaussian formula;
//  - bad PSFs are refused with what is wrong.
#include "glint/sensor/psf.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <memory>
#include <numbers>
#include <optional>
#include <vector>

#include "glint/core/error.h"
#include "glint/core/rng.h"
#include "glint/io/image.h"
#include "glint/motion/euler.h"
#include "glint/motion/rigid.h"
#include "glint/sensor/camera.h"
#include "glint/sensor/pixel_ray_source.h"
#include "glint/test/angles.h"
#include "glint/test/platforms.h"
#include "glint/test/temp_dir.h"

namespace glint::sensor {
namespace psf_test {

using glint::test::kPi;

RandomStream stream(std::uint64_t problem, std::uint64_t sample) {
    return RandomStream(11, {0, 0, 0, problem, sample});
}

TEST(Psf, GaussianDrawHasTheStatedSigma) {
    const PsfSampler psf = PsfSampler::gaussian(1.7);
    EXPECT_EQ(psf.description(), "gaussian sigma 1.7 px");
    constexpr int kDraws = 200000;
    std::array<double, 2> sum{}, sum2{};
    for (int n = 0; n < kDraws; ++n) {
        RandomStream rng = stream(0, static_cast<std::uint64_t>(n));
        const double r1 = rng.uniform();
        const auto d = psf.offset_px(r1, rng.uniform());
        for (int a = 0; a < 2; ++a) {
            sum[a] += d[a];
            sum2[a] += d[a] * d[a];
        }
    }
    for (int a = 0; a < 2; ++a) {
        const double mean = sum[a] / kDraws;
        const double sigma = std::sqrt(sum2[a] / kDraws - mean * mean);
        // 200 000 draws: the mean's standard error is 1.7/447 = 0.004 px, sigma's 0.003 px.
        EXPECT_NEAR(mean, 0.0, 0.02) << a;
        EXPECT_NEAR(sigma, 1.7, 0.015) << a;
    }
    EXPECT_DOUBLE_EQ(psf.reach_px(), 4 * 1.7);
}

TEST(Psf, ImageDrawsFollowThePixelValuesInsideTheExtent) {
    // 4 × 2 pixels over 8 focal-plane pixels: each image pixel is 2 × 2 focal-plane pixels,
    // the image spans x in [-4, 4), y in [-2, 2).
    const std::vector<double> weights = {0, 1, 2, 3,  //
                                         4, 0, 0, 6};
    const PsfSampler psf = PsfSampler::table(weights, 4, 2, 8.0);
    EXPECT_EQ(psf.description(), "4 x 2 image over 8 px");
    std::array<int, 8> counts{};
    constexpr int kDraws = 160000;
    for (int n = 0; n < kDraws; ++n) {
        RandomStream rng = stream(1, static_cast<std::uint64_t>(n));
        const double r1 = rng.uniform();
        const auto d = psf.offset_px(r1, rng.uniform());
        ASSERT_GE(d[0], -4.0);
        ASSERT_LE(d[0], 4.0);
        ASSERT_GE(d[1], -2.0);
        ASSERT_LE(d[1], 2.0);
        const int x = std::min(3, static_cast<int>(std::floor((d[0] + 4.0) / 2.0)));
        const int y = std::min(1, static_cast<int>(std::floor((d[1] + 2.0) / 2.0)));
        ++counts[static_cast<std::size_t>(y * 4 + x)];
    }
    for (std::size_t i = 0; i < weights.size(); ++i) {
        const double expected = kDraws * weights[i] / 16.0;
        // Binomial: at most 160 000 × 6/16 → σ = 194 draws; 5σ.
        EXPECT_NEAR(counts[i], expected, 5 * std::sqrt(expected + 1)) << i;
    }
    EXPECT_DOUBLE_EQ(psf.reach_px(), 0.5 * std::hypot(8.0, 4.0));
}

TEST(Psf, RefusesBadParameters) {
    const auto message_of = [](const auto& make) {
        try {
            make();
        } catch (const Error& e) {
            EXPECT_EQ(e.category(), ErrorCategory::input);
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message_of([] { PsfSampler::gaussian(0.0); }),
              "the PSF width (1 sigma, pixels) must be a finite number > 0, got 0");
    EXPECT_EQ(message_of([] { PsfSampler::gaussian(std::nan("")); }),
              "the PSF width (1 sigma, pixels) must be a finite number > 0, got nan");
    EXPECT_EQ(message_of([] {
                  PsfSampler::table({1, 1}, 2, 1, -3.0);
              }),
              "the PSF scale (the image's extent in pixels) must be a finite number > 0, got -3");
    EXPECT_EQ(message_of([] {
                  PsfSampler::table({0, 0, 0, 0}, 2, 2, 3.0);
              }),
              "the image is all zero");
    EXPECT_EQ(message_of([] {
                  PsfSampler::table({1, -1}, 2, 1, 3.0);
              }),
              "the image holds a negative or non-finite value (-1)");
}

TEST(Psf, FromModelNamesTheElementAndTheImage) {
    model::Psf psf;
    psf.image.text = "airy.png";
    psf.image.resolved = "/nowhere/airy.png";
    psf.scale_px = 10.0;
    psf.where = ErrorContext{"cam.platform", 42, "psf"};
    try {
        PsfSampler::from_model(psf);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::internal) << "the readers read every PSF image";
        EXPECT_NE(std::string(e.what()).find("<psf><image> \"airy.png\" was not read"),
                  std::string::npos)
            << e.what();
    }
    psf.weights = model::WeightImage{4, 4, std::vector<double>(16, 0.0)};
    try {
        PsfSampler::from_model(psf);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_NE(std::string(e.what()).find(
                      "cam.platform:42: psf: <psf><image> \"airy.png\": the image is all zero"),
                  std::string::npos)
            << e.what();
    }
    psf.weights.values[5] = 200.0 / 255.0;
    const PsfSampler loaded = PsfSampler::from_model(psf);
    EXPECT_EQ(loaded.description(), "image airy.png 4 x 4 image over 10 px");
    // Only pixel (1, 1) is lit: x, y in [-5 + 2.5, -5 + 5) = [-2.5, 0).
    for (int n = 0; n < 100; ++n) {
        RandomStream rng = stream(2, static_cast<std::uint64_t>(n));
        const double r1 = rng.uniform();
        const auto d = loaded.offset_px(r1, rng.uniform());
        EXPECT_GE(d[0], -2.5);
        EXPECT_LE(d[0], 0.0);
        EXPECT_GE(d[1], -2.5);
        EXPECT_LE(d[1], 0.0);
    }
}

// ---------------------------------------------------------------------------------------
// Slanted-edge MTF through the pixel ray source.

constexpr double kHeight_m = 1000.0;
constexpr double kFocal_m = 0.1;
constexpr double kPitch_m = 10e-6;
constexpr std::size_t kColumns = 40;
constexpr std::size_t kRows = 160;
constexpr double kEdgeAngle_rad = 5.0 * kPi / 180.0;
constexpr double kBin_px = 0.25;  // ESF oversampling ×4, as ISO 12233

double sinc(double x) { return x == 0.0 ? 1.0 : std::sin(kPi * x) / (kPi * x); }

/// The edge's distance (px) from the image centre along its normal, for a pixel position.
double edge_distance(double column_px, double row_px) {
    return (column_px - 0.5 * kColumns) * std::cos(kEdgeAngle_rad) +
           (row_px - 0.5 * kRows) * std::sin(kEdgeAngle_rad);
}

/// MTF at `frequencies` (cycles/pixel along the edge normal) of pixels imaging a black/white
/// edge through PixelRaySource with `psf`: each pixel's value is the fraction of its sample
/// rays that, projected back through the camera, land on the white side.
std::vector<double> edge_mtf(const PsfSampler* psf, const std::vector<double>& frequencies,
                             std::uint64_t samples) {
    model::DetectorArray a;
    a.x_count = kColumns;
    a.y_count = kRows;
    a.x_spacing_m = a.y_spacing_m = a.x_size_m = a.y_size_m = kPitch_m;
    model::InstrumentProperties p;
    p.focal_length_m = kFocal_m;
    const CameraModel camera(p, a, kColumns, kRows);
    const motion::PoseService poses(test::one_mount_platform(),
                                    std::make_unique<test::HoverTrajectory>(kHeight_m), {}, {});
    const PixelRaySource source(camera, poses, 0, {0.0, 0.0, 0.0}, psf);
    const motion::Rigid to_instrument = motion::inverse(poses.instrument_to_scene(0, 0.0));

    // Edge spread function: pixel values binned by their centre's distance from the edge.
    constexpr double kHalfRange_px = 12.0;
    const auto bins = static_cast<std::size_t>(2 * kHalfRange_px / kBin_px);
    std::vector<double> sum(bins, 0.0), count(bins, 0.0);
    for (std::size_t row = 0; row < kRows; ++row) {
        for (std::size_t column = 0; column < kColumns; ++column) {
            const double d = edge_distance(column + 0.5, row + 0.5);
            if (std::abs(d) >= kHalfRange_px) continue;
            const std::uint64_t problem = row * kColumns + column;
            double white = 0.0;
            for (std::uint64_t n = 0; n < samples; ++n) {
                RandomStream rng = stream(problem, n);
                const radiometry::SampleRay ray = source.generate(problem, n, rng);
                const auto at =
                    camera.project(motion::apply_direction(to_instrument, ray.direction));
                if (at && edge_distance((*at)[0], (*at)[1]) > 0.0) white += 1.0;
            }
            const auto bin = static_cast<std::size_t>((d + kHalfRange_px) / kBin_px);
            sum[bin] += white / static_cast<double>(samples);
            count[bin] += 1.0;
        }
    }
    std::vector<double> esf(bins);
    for (std::size_t i = 0; i < bins; ++i) {
        EXPECT_GT(count[i], 0.0) << "empty ESF bin " << i;
        esf[i] = sum[i] / std::max(count[i], 1.0);
    }
    // Line spread function by central differences; its transform, corrected for the bin
    // average (sinc(f b)) and the difference (sinc(2 f b)) as the ISO method does.
    std::vector<double> mtf;
    for (const double f : frequencies) {
        double re = 0.0, im = 0.0, total = 0.0;
        for (std::size_t i = 1; i + 1 < bins; ++i) {
            const double lsf = 0.5 * (esf[i + 1] - esf[i - 1]);
            const double x = (static_cast<double>(i) + 0.5) * kBin_px - kHalfRange_px;
            re += lsf * std::cos(2 * kPi * f * x);
            im -= lsf * std::sin(2 * kPi * f * x);
            total += lsf;
        }
        mtf.push_back(std::hypot(re, im) / total / (sinc(f * kBin_px) * sinc(2 * f * kBin_px)));
    }
    return mtf;
}

/// The pixel aperture (a 1-pixel square seen along the edge normal) times a Gaussian PSF.
double expected_mtf(double f, double sigma_px) {
    return std::abs(sinc(f * std::cos(kEdgeAngle_rad)) * sinc(f * std::sin(kEdgeAngle_rad))) *
           std::exp(-2 * kPi * kPi * sigma_px * sigma_px * f * f);
}

const std::vector<double> kFrequencies = {0.1, 0.2, 0.3, 0.4, 0.5};

TEST(PsfEdgeMtf, GaussianPsfMatchesTheAnalyticMtf) {
    for (const double sigma : {0.5, 1.0, 2.0}) {
        const PsfSampler psf = PsfSampler::gaussian(sigma);
        const std::vector<double> mtf = edge_mtf(&psf, kFrequencies, 256);
        for (std::size_t k = 0; k < kFrequencies.size(); ++k) {
            // 0.03: the bound; sampling noise (256 rays a pixel, ~50 pixels a bin) is
            // about 0.005.
            EXPECT_NEAR(mtf[k], expected_mtf(kFrequencies[k], sigma), 0.03)
                << "sigma " << sigma << " px, f " << kFrequencies[k] << " cy/px";
        }
    }
}

TEST(PsfEdgeMtf, WithoutAPsfOnlyThePixelApertureRemains) {
    const std::vector<double> mtf = edge_mtf(nullptr, kFrequencies, 256);
    for (std::size_t k = 0; k < kFrequencies.size(); ++k) {
        EXPECT_NEAR(mtf[k], expected_mtf(kFrequencies[k], 0.0), 0.03) << kFrequencies[k];
    }
}

TEST(PsfEdgeMtf, ImagePsfOfTheGaussianFormulaGivesTheGaussiansMtf) {
    // σ = 1 px drawn on 65 × 65 image pixels over 10 focal-plane pixels (±5σ).
    constexpr std::size_t kSize = 65;
    constexpr double kExtent_px = 10.0;
    std::vector<double> weights(kSize * kSize);
    for (std::size_t y = 0; y < kSize; ++y) {
        for (std::size_t x = 0; x < kSize; ++x) {
            const double dx = (x + 0.5) * kExtent_px / kSize - 0.5 * kExtent_px;
            const double dy = (y + 0.5) * kExtent_px / kSize - 0.5 * kExtent_px;
            weights[y * kSize + x] = std::exp(-(dx * dx + dy * dy) / 2.0);
        }
    }
    const PsfSampler psf = PsfSampler::table(weights, kSize, kSize, kExtent_px);
    const std::vector<double> mtf = edge_mtf(&psf, kFrequencies, 256);
    for (std::size_t k = 0; k < kFrequencies.size(); ++k) {
        EXPECT_NEAR(mtf[k], expected_mtf(kFrequencies[k], 1.0), 0.03) << kFrequencies[k];
    }
}

}  // namespace psf_test
}  // namespace glint::sensor
