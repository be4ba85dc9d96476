// SPDX-License-Identifier: Apache-2.0
// The output units as users see them: the docs/units.md table of every flux × area × aperture ×
// temporal × normalization combination (80 rows) must be exactly what OutputUnits produces
// (tests/integration/sensor/output_units_fixture_test.cpp reads a real platform's units).
//
// To regenerate the docs table after a deliberate change: run
//   build/release/tests/test_sensor --gtest_filter='OutputUnitsDocs.*'
// and paste the expected table printed in the failure message into docs/units.md.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "glint/core/diagnostics.h"
#include "glint/model/derived.h"
#include "glint/model/names.h"
#include "glint/model/platform.h"
#include "glint/sensor/output_units.h"

namespace glint::sensor {
namespace output_units_docs_test {

using model::AreaUnits;
using model::FluxUnits;

std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

/// The manual's Table 1 rows: watts (all but temporal + normalized) and photons/s (not
/// normalized), with or without an aperture, all in cm2.
bool in_manual_table1(FluxUnits flux, AreaUnits area, bool temporal, bool normalized) {
    if (area != AreaUnits::cm2) return false;
    if (flux == FluxUnits::watts) return !(temporal && normalized);
    if (flux == FluxUnits::photons_per_second) return !normalized;
    return false;
}

const char* yes_no(bool value) { return value ? "yes" : "no"; }

/// The table rows as OutputUnits describes each combination (one Gaussian channel).
std::string generated_table() {
    const SpectralGrid grid = SpectralGrid::regular(0.4, 0.7, 0.01);
    std::string table =
        "| fluxunits | areaunits | aperture | temporal integration | normalized | data units | "
        "Table 1 |\n|---|---|---|---|---|---|---|\n";
    for (const FluxUnits flux : {FluxUnits::watts, FluxUnits::milliwatts, FluxUnits::microwatts,
                                 FluxUnits::photons_per_second, FluxUnits::electrons_per_second}) {
        for (const AreaUnits area : {AreaUnits::cm2, AreaUnits::m2}) {
            for (const bool aperture : {false, true}) {
                for (const bool temporal : {false, true}) {
                    for (const bool normalized : {false, true}) {
                        model::CaptureMethod method;
                        method.image_file.flux_units = flux;
                        method.image_file.area_units = area;
                        method.temporal_integration.time_s = temporal ? 0.1 : 0.0;
                        model::Channel channel;
                        channel.name = "c";
                        channel.center_um = 0.55;
                        channel.width_um = 0.05;
                        channel.normalize = normalized;
                        method.spectral_response.channels = {channel};
                        model::InstrumentProperties properties;
                        properties.focal_length_m = 1.14;
                        if (aperture) properties.aperture_diameter_m = 0.09;
                        const OutputUnits units(method, properties, grid);
                        const std::string text = units.description().data_units;
                        EXPECT_EQ(text,
                                  data_units_string(flux, area, aperture, temporal, normalized));
                        table += std::string("| ") + model::name_of(flux) + " | " +
                                 model::name_of(area) + " | " + yes_no(aperture) + " | " +
                                 yes_no(temporal) + " | " + yes_no(normalized) + " | `" + text +
                                 "` | " +
                                 (in_manual_table1(flux, area, temporal, normalized) ? "✓" : "") +
                                 " |\n";
                    }
                }
            }
        }
    }
    return table;
}

TEST(OutputUnitsDocs, UnitsMdHoldsTheGeneratedTable) {
    const std::string docs =
        read_text(std::filesystem::path(GLINT_SOURCE_DIR) / "docs" / "units.md");
    const std::string table = generated_table();
    EXPECT_NE(docs.find("## Output units (Table 1)"), std::string::npos);
    EXPECT_NE(docs.find(table), std::string::npos)
        << "docs/units.md does not hold the generated table; expected:\n"
        << table;
    // 80 rows plus the header and the rule; 10 rows marked as the manual's.
    std::size_t lines = 0, marked = 0;
    for (std::size_t at = 0; (at = table.find('\n', at)) != std::string::npos; ++at) ++lines;
    for (std::size_t at = 0; (at = table.find("✓", at)) != std::string::npos; ++at) ++marked;
    EXPECT_EQ(lines, 82u);
    EXPECT_EQ(marked, 10u);
}

}  // namespace output_units_docs_test
}  // namespace glint::sensor
