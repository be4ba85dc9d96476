// SPDX-License-Identifier: Apache-2.0
// TDI accumulation: N stages of a static flat field raise the SNR by √N; dark current is
// integrated over every stage; read noise is counted once (charge-domain TDI) or once per
// stage (digital TDI).
#include <gtest/gtest.h>

#include <cmath>

#include "detect_test_support.h"

namespace glint::detect {
namespace tdi_test {

using test::fluence_for;
using test::moments;

constexpr std::size_t kSamples = 256;
constexpr std::size_t kLines = 256;

double snr(const DetectionChain& chain, double fluence) {
    const auto m = moments(test::flat_field(chain, fluence, kLines));
    return m.mean / std::sqrt(m.variance);
}

TEST(Tdi, SnrGrowsAsTheSquareRootOfTheStages) {
    // Per stage: 2000 signal electrons, 1 dark electron; read noise 5 e once.
    constexpr double kSignalE = 2000, kDarkE = 1, kReadE = 5;
    for (std::size_t stages : {4u, 16u}) {
        DetectionSettings one = test::settings(kReadE, kDarkE, 0, 1e9, 32);
        one.output = DetectOutput::electrons;
        DetectionSettings many = test::settings(kReadE, kDarkE, 0, 1e9, 32, 0.01, stages);
        many.output = DetectOutput::electrons;
        const DetectionChain single(one, kSamples);
        const DetectionChain tdi(many, kSamples);
        EXPECT_NEAR(many.detector->dark_electrons(stages), kDarkE * stages, 1e-9);
        // The input of a TDI pixel is its stage-summed fluence: N × one stage's.
        const double gain =
            snr(tdi, stages * fluence_for(kSignalE)) / snr(single, fluence_for(kSignalE));
        const double n = static_cast<double>(stages);
        EXPECT_NEAR(gain / std::sqrt(n), 1.0, 0.05) << stages << " stages";
        // The exact expectation: S N / sqrt(N (S + D) + R²) over S / sqrt(S + D + R²).
        const double expected =
            (n * kSignalE / std::sqrt(n * (kSignalE + kDarkE) + kReadE * kReadE)) /
            (kSignalE / std::sqrt(kSignalE + kDarkE + kReadE * kReadE));
        EXPECT_NEAR(gain / expected, 1.0, 0.02) << stages << " stages";
    }
}

TEST(Tdi, ReadNoiseOnceInChargeModeAndPerStageInDigitalMode) {
    constexpr std::size_t kStages = 16;
    constexpr double kReadE = 10;
    for (TdiMode mode : {TdiMode::charge, TdiMode::digital}) {
        DetectionSettings s = test::settings(kReadE, 0.0, 0, 1e9, 32, 0.01, kStages);
        s.output = DetectOutput::electrons;
        s.tdi_mode = mode;
        const auto m = moments(test::flat_field(DetectionChain(s, kSamples), 0.0, kLines));
        const double expected = kReadE * kReadE * (mode == TdiMode::digital ? kStages : 1);
        EXPECT_NEAR(m.variance / expected, 1.0, 0.03) << tdi_mode_name(mode);
        EXPECT_NEAR(m.mean, 0.0, 5 * std::sqrt(expected / (kSamples * kLines)));
    }
}

TEST(Tdi, ResolvedFromATdiFocalPlane) {
    model::FocalPlane fp = test::focal_plane();
    fp.capture_method.temporal_integration.tdi = true;
    fp.detector_array.y_count = 12;
    const DetectionSettings s = resolve_detection(fp, test::properties_with_aperture(), {}, 1);
    EXPECT_EQ(s.tdi_stages, 12u);
    EXPECT_EQ(s.tdi_mode, TdiMode::charge);
    // Dark electrons of 12 stages of 10 ms on a 10 µm pixel at 1e-5 A/m².
    EXPECT_NEAR(s.detector->dark_electrons(12), 1e-5 * 1e-10 * 0.01 * 12 / 1.602176634e-19, 1e-9);
    DetectorOverrides digital;
    digital.tdi_mode = TdiMode::digital;
    EXPECT_EQ(resolve_detection(fp, test::properties_with_aperture(), digital, 1).tdi_mode,
              TdiMode::digital);
}

}  // namespace tdi_test
}  // namespace glint::detect
