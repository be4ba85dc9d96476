// SPDX-License-Identifier: Apache-2.0
// Photon transfer (EMVA 1288 style) on flat fields: the variance of the digital counts
// against their mean at nine exposure levels gives the ADC's conversion gain (the slope),
// dark frames give the read-noise floor and the dark-current mean, and no-noise mode gives
// the exact deterministic count.
#include <gtest/gtest.h>

#include <cmath>

#include "detect_test_support.h"
#include "glint/detect/adc.h"

namespace glint::detect {
namespace photon_transfer_test {

using test::fluence_for;
using test::moments;

// 12 bits over [-1000, 39950] e: K = 4095 / 40950 = 0.1 DN/e exactly; the negative minimum
// is an offset that keeps the read noise of dark pixels above the ADC's floor.
constexpr double kMinE = -1000;
constexpr double kMaxE = 39950;
constexpr double kGain = 0.1;
constexpr double kReadNoiseE = 30;
constexpr double kDarkE = 50;
constexpr std::size_t kSamples = 256;
constexpr std::size_t kLines = 256;

TEST(PhotonTransfer, SlopeIsTheConversionGainAndDarkFramesGiveReadNoise) {
    const DetectionChain chain(test::settings(kReadNoiseE, kDarkE, kMinE, kMaxE, 12), kSamples);
    ASSERT_DOUBLE_EQ(chain.settings().detector->gain_dn_per_e(), kGain);
    const double levels_e[] = {0, 500, 1000, 2000, 4000, 8000, 12000, 16000, 24000};
    std::vector<double> means;
    std::vector<double> variances;
    for (std::size_t i = 0; i < std::size(levels_e); ++i) {
        const auto m = moments(test::flat_field(chain, fluence_for(levels_e[i]), kLines, i));
        // The mean count is K (signal + dark − min), to within rounding.
        const double standard_error = std::sqrt(m.variance / (kSamples * kLines));
        EXPECT_NEAR(m.mean, kGain * (levels_e[i] + kDarkE - kMinE), 5 * standard_error)
            << levels_e[i];
        means.push_back(m.mean);
        variances.push_back(m.variance);
    }
    // Weighted least-squares line var = a + slope × mean (weights 1/var², the variance of a
    // sample variance being proportional to var²).
    double sw = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < means.size(); ++i) {
        const double w = 1.0 / (variances[i] * variances[i]);
        sw += w;
        sx += w * means[i];
        sy += w * variances[i];
        sxx += w * means[i] * means[i];
        sxy += w * means[i] * variances[i];
    }
    const double slope = (sw * sxy - sx * sy) / (sw * sxx - sx * sx);
    const double intercept = (sy - slope * sx) / sw;
    EXPECT_NEAR(slope / kGain, 1.0, 0.02) << "conversion gain from the photon-transfer slope";

    // var = K mean + K² (σ_read² + min) + 1/12, since mean = K (signal + dark − min).
    const double fitted_read_e = std::sqrt((intercept - 1.0 / 12.0) / (kGain * kGain) - kMinE);
    EXPECT_NEAR(fitted_read_e / kReadNoiseE, 1.0, 0.05) << "read-noise floor from the fit";

    // Dark frame (EMVA's σ_y.dark): var = K² (σ_read² + dark) + 1/12.
    const double dark_mean_e = means[0] / kGain + kMinE;
    const double read_noise_e =
        std::sqrt((variances[0] - 1.0 / 12.0) / (kGain * kGain) - dark_mean_e);
    EXPECT_NEAR(read_noise_e / kReadNoiseE, 1.0, 0.05) << "read-noise floor " << read_noise_e;
}

TEST(PhotonTransfer, DarkFramesGiveTheDarkCurrentMean) {
    // Electrons out, no read noise: the mean is J A t / e.
    DetectionSettings s = test::settings(0.0, kDarkE, 0, 1e6, 32);
    s.output = DetectOutput::electrons;
    const DetectionChain chain(s, kSamples);
    EXPECT_NEAR(s.detector->dark_electrons(1), kDarkE, 1e-9);
    const auto m = moments(test::flat_field(chain, 0.0, kLines));
    const double standard_error = std::sqrt(kDarkE / (kSamples * kLines));
    EXPECT_NEAR(m.mean, kDarkE, 4 * standard_error);
    EXPECT_NEAR(m.variance / kDarkE, 1.0, 0.03) << "dark current is Poisson";
}

TEST(PhotonTransfer, NoNoiseGivesTheExactMeanCount) {
    DetectionSettings s = test::settings(kReadNoiseE, kDarkE, kMinE, kMaxE, 12);
    s.noise = false;
    const DetectionChain chain(s, 16);
    for (double level : {0.0, 123.4, 5000.0, 39000.0, 1e6}) {
        const auto values = test::flat_field(chain, fluence_for(level), 2);
        const double expected =
            std::min(4095.0, std::floor((level + kDarkE - kMinE) * kGain + 0.5));
        for (double v : values) ASSERT_EQ(v, expected) << level;
    }
    s.output = DetectOutput::electrons;
    const DetectionChain electrons(s, 4);
    for (double v : test::flat_field(electrons, fluence_for(777.0), 1)) {
        EXPECT_DOUBLE_EQ(v, 777.0 + kDarkE);
    }
}

}  // namespace photon_transfer_test
}  // namespace glint::detect
