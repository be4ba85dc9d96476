// SPDX-License-Identifier: Apache-2.0
// The output units of a real platform file: capture_full.platform, read through the legacy
// reader, gives the units and values of the DIRSIG5 BasicPlatform manual for its
// photons-per-m² Bayer focal plane.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/diagnostics.h"
#include "glint/dirsig/readers.h"
#include "glint/model/derived.h"
#include "glint/model/names.h"
#include "glint/model/platform.h"
#include "glint/sensor/output_units.h"

namespace glint::sensor {
namespace output_units_fixture_test {

TEST(OutputUnitsFixture, BayerFocalPlaneOfCaptureFull) {
    dirsig::ReadOptions options;
    options.paths.environment = [](const std::string&) -> std::optional<std::string> {
        return std::nullopt;
    };
    Diagnostics diagnostics;
    const model::Platform platform = dirsig::read_platform(
        std::filesystem::path(GLINT_TEST_DATA_DIR) / "platform" / "capture_full.platform", options,
        diagnostics);
    ASSERT_FALSE(diagnostics.has_errors());
    const auto instruments = model::list_instruments(platform);
    ASSERT_FALSE(instruments.empty());
    const model::Instrument& camera = *instruments.front().instrument;
    ASSERT_FALSE(camera.focal_planes.empty());
    const model::CaptureMethod& bayer = camera.focal_planes.front().capture_method;
    const SpectralGrid grid = model::bandpass_grid(bayer.spectral_response.bandpass);

    // photonspersecond, m2, aperture (50 mm, 0.025 m, τ 0.9), 1 ms, Green normalized.
    const OutputUnits units(bayer, camera.properties, grid);
    const UnitsDescription& d = units.description();
    EXPECT_TRUE(d.aperture);
    EXPECT_TRUE(d.temporal_integration);
    EXPECT_EQ(d.integration_time_s, 0.001);
    const double g = (1.0 + 4.0 * 2.0 * 2.0) / (0.9 * std::numbers::pi);  // F# = 2
    EXPECT_NEAR(d.g_number_per_sr, g, 1e-12);
    EXPECT_EQ(d.data_units, "Photons/m2");
    EXPECT_EQ(d.per_channel_units,
              (std::vector<std::string>{"Photons/m2", "Photons/(m2 um)", "Photons/m2"}));

    // Green: tophat 0.51–0.59 µm, gain 2, bias 0.5, normalized; flat L = 1 W/(cm² sr µm):
    // 2 · 10⁴ · 1 ms / G# · L · (mean of λ/(hc) over the box = 0.55 µm/(hc)) + 0.5.
    std::vector<double> radiance(grid.size(), 1.0);
    std::vector<double> out(units.channels());
    units.apply(radiance, out);
    const double photons_per_j_055 = 0.55e-6 / (6.62607015e-34 * 299792458.0);
    const double expected = 2.0 * 1e4 * 0.001 / g * photons_per_j_055 + 0.5;
    EXPECT_NEAR(out[1], expected, 1e-12 * expected);
    EXPECT_EQ(units.centers_um()[1], 0.55);
    EXPECT_EQ(units.fwhm_um()[1], 0.08);
}

}  // namespace output_units_fixture_test
}  // namespace glint::sensor
