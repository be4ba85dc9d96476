// SPDX-License-Identifier: Apache-2.0
// Tests of the exo-atmospheric solar spectrum: the ASTM G173 integral, the total with the
// Planck tail against the solar constant, continuity at 4 µm and the 1/d² scaling.
#include "glint/atmosphere/solar.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include "glint/io/input_files.h"

namespace glint::atmosphere {
namespace solar_test {

SolarSpectrum load() {
    return SolarSpectrum::from_astm_g173(
        io::read_input_file(std::filesystem::path(GLINT_SOURCE_DIR) / "data" /
                            SolarSpectrum::kAstmRelativePath),
        SolarSpectrum::kAstmRelativePath);
}

/// ∫ E dλ in W/m² over [lo, hi] µm on a fine regular grid (step 0.0005 µm below 4 µm,
/// matching the table's densest spacing).
double integral_w_per_m2(const SolarSpectrum& sun, double lo_um, double hi_um, double step_um) {
    const SpectralGrid grid = SpectralGrid::regular(lo_um, hi_um, step_um);
    return integrate_trapezoid(grid, sun.resample(grid)) * 1e4;  // W/cm² → W/m²
}

TEST(SolarSpectrum, AstmIntegralMatchesTheDataReadme) {
    const SolarSpectrum sun = load();
    // Exactly the table's trapezoid integral (its own nodes).
    const auto& table = sun.table();
    const SpectralGrid nodes(
        std::vector<double>(table.wavelengths_um().begin(), table.wavelengths_um().end()));
    const double table_w_per_m2 = integrate_trapezoid(nodes, table.values()) * 1e4;
    EXPECT_NEAR(table_w_per_m2, 1348.0, 1348.0 * 0.005);
    // The same through point resampling on a fine grid.
    EXPECT_NEAR(integral_w_per_m2(sun, 0.28, 4.0, 0.0005), table_w_per_m2, 0.001 * table_w_per_m2);
}

TEST(SolarSpectrum, TotalWithPlanckTailIsCloseToTheSolarConstant) {
    const SolarSpectrum sun = load();
    const double table = integral_w_per_m2(sun, 0.28, 4.0, 0.0005);
    const double tail = integral_w_per_m2(sun, 4.0, 1000.0, 0.01);
    // A 5778 K blackbody has ≈ 0.95 % of its energy beyond 4 µm: ≈ 12 W/m² of 1361.
    EXPECT_NEAR(tail, 12.6, 0.1);
    // TSI 1361 W/m² (Kopp & Lean 2011). Measured: 1347.9 + 12.6 = 1360.6 W/m². Tolerance
    // 0.25 % (3.4 W/m²): the table misses the < 0.28 µm part (≈ 0.1 %), the real infrared
    // sun is not exactly a 5778 K blackbody (a ±10 % tail error is ±0.1 %), and TSI itself
    // varies by ≈ ±0.1 % over the solar cycle.
    EXPECT_NEAR(table + tail, 1361.0, 1361.0 * 0.0025);
}

TEST(SolarSpectrum, PlanckTailIsContinuousAt4um) {
    const SolarSpectrum sun = load();
    const double at = sun.irradiance_w_per_cm2_um(4.0);
    const double after = sun.irradiance_w_per_cm2_um(4.0 + 1e-9);
    EXPECT_NEAR(after, at, 1e-6 * at);
    // The table at 4 µm: 0.00868 W m⁻² nm⁻¹ = 0.000868 W cm⁻² µm⁻¹.
    EXPECT_NEAR(at, 0.000868, 1e-12);
    // The scale factor is close to the sun's solid angle at 1 AU, π (R☉ / 1 AU)².
    const double omega_sun = M_PI * std::pow(6.957e8 / 1.495978707e11, 2);
    EXPECT_NEAR(sun.tail_scale_sr(), omega_sun, 0.1 * omega_sun);
}

TEST(SolarSpectrum, ScalesWithInverseSquareDistance) {
    const SolarSpectrum sun = load();
    for (double wl : {0.5, 1.0, 3.0, 10.0}) {
        const double e1 = sun.irradiance_w_per_cm2_um(wl, 1.0);
        EXPECT_GT(e1, 0.0);
        EXPECT_NEAR(sun.irradiance_w_per_cm2_um(wl, 0.983), e1 / (0.983 * 0.983), 1e-12 * e1);
        EXPECT_NEAR(sun.irradiance_w_per_cm2_um(wl, 1.017), e1 / (1.017 * 1.017), 1e-12 * e1);
    }
    EXPECT_THROW((void)sun.irradiance_w_per_cm2_um(0.5, 0.0), Error);
    EXPECT_THROW((void)sun.irradiance_w_per_cm2_um(0.5, NAN), Error);
}

TEST(SolarSpectrum, UnitsAndRange) {
    const SolarSpectrum sun = load();
    // 500 nm: 1.916 W m⁻² nm⁻¹ in the table = 0.1916 W cm⁻² µm⁻¹.
    EXPECT_NEAR(sun.irradiance_w_per_cm2_um(0.5), 0.1916, 1e-12);
    EXPECT_NEAR(sun.irradiance_w_per_cm2_um(0.55), 0.1863, 1e-12);
    EXPECT_EQ(sun.irradiance_w_per_cm2_um(0.2), 0.0);
    const SpectralGrid grid = SpectralGrid::regular(0.4, 0.7, 0.1);
    EXPECT_EQ(sun.resample(grid, 1.0).size(), 4u);
}

TEST(SolarSpectrum, BadFileHasFileAndLine) {
    try {
        (void)SolarSpectrum::from_astm_g173("title\nwavelength,extraterrestrial\n280,0.1\n290,x\n",
                                            "s.csv");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.context().file, "s.csv");
        EXPECT_EQ(e.context().line, 4);
    }
}

}  // namespace solar_test
}  // namespace glint::atmosphere
