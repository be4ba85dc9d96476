// SPDX-License-Identifier: Apache-2.0
// Tests of spectral grids, curves, trapezoid integration, wavelength-unit names, Planck's law
// (against the Stefan–Boltzmann law and Wien's displacement law) and photon conversions.
#include "glint/core/spectral.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "glint/core/error.h"
#include "glint/core/units.h"

namespace glint {
namespace spectral_test {

/// Runs `fn`, expects a glint input Error whose message contains `fragment`.
template <typename Fn>
void expect_input_error(Fn&& fn, const std::string& fragment) {
    try {
        fn();
        ADD_FAILURE() << "no error, expected one containing '" << fragment << "'";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input) << e.what();
        EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
}

/// A grid of `count` wavelengths spaced evenly in log λ from lo_um to hi_um.
SpectralGrid log_grid(double lo_um, double hi_um, int count) {
    std::vector<double> wl(count);
    const double ratio = std::log(hi_um / lo_um) / (count - 1);
    for (int i = 0; i < count; ++i) wl[i] = lo_um * std::exp(ratio * i);
    return SpectralGrid(std::move(wl));
}

// ---- SpectralGrid ----------------------------------------------------------------------

TEST(SpectralGrid, RegularCountWithTolerance) {
    const SpectralGrid grid = SpectralGrid::regular(0.4, 0.7, 0.005);
    ASSERT_EQ(grid.size(), 61u);
    EXPECT_DOUBLE_EQ(grid.wavelength_um(0), 0.4);
    EXPECT_DOUBLE_EQ(grid.wavelength_um(1), 0.405);
    EXPECT_EQ(grid.wavelength_um(60), 0.7);
    EXPECT_EQ(grid.min_um(), 0.4);
    EXPECT_EQ(grid.max_um(), 0.7);
    EXPECT_EQ(grid.wavelengths_um().size(), 61u);
}

TEST(SpectralGrid, RegularTruncatesPartialStep) {
    const SpectralGrid grid = SpectralGrid::regular(1.0, 2.05, 0.1);
    EXPECT_EQ(grid.size(), 11u);  // 1.0 ... 2.0
    EXPECT_NEAR(grid.max_um(), 2.0, 1e-12);
}

TEST(SpectralGrid, SinglePoint) {
    const SpectralGrid grid = SpectralGrid::regular(0.55, 0.55, 0.01);
    EXPECT_EQ(grid.size(), 1u);
    const std::vector<double> f = {3.0};
    EXPECT_EQ(integrate_trapezoid(grid, f), 0.0);
}

TEST(SpectralGrid, Arbitrary) {
    const SpectralGrid grid({0.45, 0.55, 0.65, 0.86});
    EXPECT_EQ(grid.size(), 4u);
    EXPECT_EQ(grid.wavelength_um(3), 0.86);
    EXPECT_THROW(grid.wavelength_um(4), Error);
}

TEST(SpectralGrid, Errors) {
    expect_input_error([] { SpectralGrid::regular(0.4, 0.7, 0.0); }, "step 0");
    expect_input_error([] { SpectralGrid::regular(0.4, 0.7, -0.01); }, "expected > 0");
    expect_input_error([] { SpectralGrid::regular(0.7, 0.4, 0.01); }, "below the minimum");
    expect_input_error([] { SpectralGrid::regular(0.0, 0.4, 0.01); }, "minimum wavelength 0");
    expect_input_error([] { SpectralGrid::regular(0.4, NAN, 0.01); }, "finite");
    expect_input_error([] { SpectralGrid::regular(0.4, 1e6, 1e-6); }, "too many");
    expect_input_error([] { SpectralGrid(std::vector<double>{}); }, "at least one");
    expect_input_error([] { SpectralGrid({0.5, 0.5}); }, "strictly increasing");
    expect_input_error([] { SpectralGrid({0.6, 0.5}); }, "wavelength 1 (0.5)");
    expect_input_error([] { SpectralGrid({-0.1, 0.5}); }, "wavelength 0 is -0.1");
    // The context given by the caller is kept.
    try {
        SpectralGrid({0.6, 0.5}, ErrorContext{"a.platform", 12, "<wavelengths>"});
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("a.platform:12: <wavelengths>: ", 0), 0u) << e.what();
    }
}

// ---- SpectralCurve ---------------------------------------------------------------------

TEST(SpectralCurve, LinearInterpolationAndZeroOutside) {
    const SpectralCurve curve({0.4, 0.5, 0.7}, {1.0, 3.0, 2.0});
    EXPECT_EQ(curve.value_at(0.4), 1.0);
    EXPECT_EQ(curve.value_at(0.5), 3.0);
    EXPECT_EQ(curve.value_at(0.7), 2.0);
    EXPECT_NEAR(curve.value_at(0.45), 2.0, 1e-12);
    EXPECT_NEAR(curve.value_at(0.6), 2.5, 1e-12);
    EXPECT_EQ(curve.value_at(0.39), 0.0);
    EXPECT_EQ(curve.value_at(0.71), 0.0);
    EXPECT_EQ(curve.value_at(NAN), 0.0);
}

TEST(SpectralCurve, SinglePoint) {
    const SpectralCurve curve({0.5}, {7.0});
    EXPECT_EQ(curve.value_at(0.5), 7.0);
    EXPECT_EQ(curve.value_at(0.50001), 0.0);
}

TEST(SpectralCurve, Resample) {
    const SpectralCurve curve({0.4, 0.8}, {0.0, 4.0});
    const SpectralGrid grid = SpectralGrid::regular(0.3, 0.9, 0.1);
    const std::vector<double> v = curve.resample(grid);
    ASSERT_EQ(v.size(), 7u);
    const double expected[] = {0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 0.0};
    for (std::size_t i = 0; i < v.size(); ++i) EXPECT_NEAR(v[i], expected[i], 1e-12) << i;
}

TEST(SpectralCurve, Errors) {
    expect_input_error([] { SpectralCurve({0.4, 0.5}, {1.0}); }, "2 wavelengths and 1 values");
    expect_input_error([] { SpectralCurve({0.5, 0.4}, {1.0, 2.0}); }, "strictly increasing");
    expect_input_error([] { SpectralCurve({0.4, 0.5}, {1.0, NAN}); }, "value 1");
    expect_input_error([] { SpectralCurve({}, {}); }, "at least one");
}

// ---- Integration -----------------------------------------------------------------------

TEST(Integration, TrapezoidExactForLinear) {
    const SpectralGrid grid({0.4, 0.43, 0.5, 0.61, 0.9, 1.3});
    std::vector<double> f;
    for (double wl : grid.wavelengths_um()) f.push_back(2.0 * wl + 1.0);
    // ∫ (2λ + 1) dλ from 0.4 to 1.3 = [λ² + λ] = (1.69 + 1.3) − (0.16 + 0.4) = 2.43
    EXPECT_NEAR(integrate_trapezoid(grid, f), 2.43, 1e-14);
}

TEST(Integration, Weighted) {
    const SpectralGrid grid = SpectralGrid::regular(0.4, 0.7, 0.005);
    std::vector<double> f(grid.size(), 2.0), w(grid.size(), 0.5);
    EXPECT_NEAR(integrate_trapezoid(grid, f, w), 0.3, 1e-13);
    expect_input_error([&] { integrate_trapezoid(grid, f, std::vector<double>(3)); },
                       "weight has 3 values, expected 61");
    expect_input_error([&] { integrate_trapezoid(grid, std::vector<double>(2)); },
                       "integrand has 2 values, expected 61");
}

TEST(Integration, GaussianFwhmArea) {
    // ∫ exp(−4 ln2 (λ−c)²/w²) dλ = w sqrt(π / (4 ln 2)). The trapezoid rule on a smooth,
    // rapidly decaying integrand is spectrally accurate, so 1e-6 is loose.
    const double center_um = 0.55, fwhm_um = 0.01;
    const SpectralGrid grid = SpectralGrid::regular(0.45, 0.65, 0.0001);
    std::vector<double> f;
    for (double wl : grid.wavelengths_um()) f.push_back(gaussian_fwhm(wl, center_um, fwhm_um));
    const double expected = fwhm_um * std::sqrt(std::numbers::pi / (4.0 * std::numbers::ln2));
    EXPECT_NEAR(integrate_trapezoid(grid, f) / expected, 1.0, 1e-6);
}

TEST(Gaussian, HalfMaximumAtHalfWidth) {
    EXPECT_EQ(gaussian_fwhm(0.55, 0.55, 0.02), 1.0);
    EXPECT_NEAR(gaussian_fwhm(0.56, 0.55, 0.02), 0.5, 1e-15);
    EXPECT_NEAR(gaussian_fwhm(0.54, 0.55, 0.02), 0.5, 1e-15);
    expect_input_error([] { gaussian_fwhm(0.5, 0.5, 0.0); }, "FWHM 0");
}

// ---- Units -----------------------------------------------------------------------------

TEST(WavelengthUnits, Names) {
    EXPECT_EQ(wavelength_unit_to_um("Micrometers"), 1.0);
    EXPECT_EQ(wavelength_unit_to_um("microns"), 1.0);
    EXPECT_EQ(wavelength_unit_to_um(" um "), 1.0);
    EXPECT_EQ(wavelength_unit_to_um("\xC2\xB5m"), 1.0);
    EXPECT_EQ(wavelength_unit_to_um("NANOMETERS"), 1e-3);
    EXPECT_EQ(wavelength_unit_to_um("nm"), 1e-3);
    expect_input_error([] { wavelength_unit_to_um("furlongs"); },
                       "unknown wavelength unit 'furlongs', expected micrometers");
    expect_input_error([] { wavelength_unit_to_um(""); }, "unknown wavelength unit ''");
}

// ---- Planck ----------------------------------------------------------------------------

/// ∫ B_λ dλ over 0.1–1000 µm on a log grid, in W/(m² sr).
double integrated_planck(double temperature_k) {
    const SpectralGrid grid = log_grid(0.1, 1000.0, 40001);
    std::vector<double> b;
    for (double wl : grid.wavelengths_um()) {
        b.push_back(planck_radiance_w_per_m2_sr_um(wl, temperature_k));
    }
    return integrate_trapezoid(grid, b);
}

TEST(Planck, IntegralMatchesStefanBoltzmann) {
    // ∫₀^∞ B_λ dλ = σT⁴/π. Over 0.1–1000 µm the missing tails are: below 0.1 µm at 5778 K,
    // x = c₂/(λT) ≈ 24.9, fraction ≈ (15/π⁴) x³ e^(−x) ≈ 4e-8; above 1000 µm at 300 K,
    // x ≈ 0.048, fraction ≈ (15/π⁴) x³/3 ≈ 6e-6. The trapezoid error on 40001 log-spaced
    // points (step ratio 1.00023) is ~1e-8. Both are far inside 1e-4, so the test checks
    // the formula and constants, not the quadrature.
    for (double t : {300.0, 5778.0}) {
        const double expected = kStefanBoltzmannWPerM2K4 * std::pow(t, 4) / std::numbers::pi;
        EXPECT_NEAR(integrated_planck(t) / expected, 1.0, 1e-4) << t << " K";
    }
}

TEST(Planck, PeakAtWienDisplacement) {
    for (double t : {300.0, 1000.0, 5778.0}) {
        // Golden-section search for the maximum of B_λ.
        double lo = 0.1, hi = 100.0;
        const double g = (std::sqrt(5.0) - 1.0) / 2.0;
        for (int it = 0; it < 200; ++it) {
            const double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
            if (planck_radiance_w_per_m2_sr_um(a, t) > planck_radiance_w_per_m2_sr_um(b, t)) {
                hi = b;
            } else {
                lo = a;
            }
        }
        const double peak_um = 0.5 * (lo + hi);
        // The maximum is flat (quadratic), so the search locates it to ~sqrt(ε) relative.
        EXPECT_NEAR(peak_um / (kWienDisplacementUmK / t), 1.0, 1e-6) << t << " K";
    }
}

TEST(Planck, KnownValueAndUnits) {
    // B_λ(10 µm, 300 K) = 9.924e6 W/(m² sr m) = 9.924 W/(m² sr µm) (standard tables).
    const double b = planck_radiance_w_per_m2_sr_um(10.0, 300.0);
    EXPECT_NEAR(b, 9.9243, 1e-3);
    EXPECT_NEAR(planck_radiance_w_per_cm2_sr_um(10.0, 300.0), b * 1e-4, 1e-18);
    EXPECT_EQ(planck_radiance_w_per_m2_sr_um(0.5, 0.0), 0.0);
    EXPECT_EQ(planck_radiance_w_per_m2_sr_um(1e-3, 10.0), 0.0);  // exp underflow
    expect_input_error([] { planck_radiance_w_per_m2_sr_um(0.0, 300.0); }, "wavelength 0");
    expect_input_error([] { planck_radiance_w_per_m2_sr_um(1.0, -1.0); }, "temperature -1");
}

// ---- Photons ---------------------------------------------------------------------------

TEST(Photons, EnergyAtHalfMicron) {
    // E = hc/λ = 6.62607015e-34 × 299792458 / 0.5e-6 = 3.97289...e-19 J (≈ 2.48 eV).
    const double expected = 6.62607015e-34 * 299792458.0 / 0.5e-6;
    EXPECT_NEAR(photon_energy_j(0.5) / expected, 1.0, 1e-15);
    EXPECT_NEAR(photon_energy_j(0.5) / kElementaryChargeC, 2.4797, 1e-4);
    EXPECT_NEAR(photons_per_joule(0.5) * photon_energy_j(0.5), 1.0, 1e-15);
    expect_input_error([] { photon_energy_j(-1.0); }, "wavelength -1");
}

TEST(Photons, SpectrumConversion) {
    const SpectralGrid grid({0.5, 1.0});
    const std::vector<double> w = {1.0, 2.0};
    const std::vector<double> p = watts_to_photons_per_s(grid, w);
    ASSERT_EQ(p.size(), 2u);
    EXPECT_NEAR(p[0] / photons_per_joule(0.5), 1.0, 1e-15);
    EXPECT_NEAR(p[1] / (2.0 * photons_per_joule(1.0)), 1.0, 1e-15);
    EXPECT_NEAR(p[1] / p[0], 4.0, 1e-12);
    expect_input_error([&] { watts_to_photons_per_s(grid, std::vector<double>(3)); },
                       "spectrum has 3 values");
}

}  // namespace spectral_test
}  // namespace glint
