// SPDX-License-Identifier: Apache-2.0
// read_data_tables (glint/inputs/data_tables.h): glint's own data files read as inputs are —
// the solar spectrum always, the gas band-model table only when asked for — and a missing or
// malformed file refused naming it.
#include "glint/inputs/data_tables.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "glint/core/error.h"
#include "glint/test/temp_dir.h"

namespace glint::inputs {
namespace data_tables_test {

const std::filesystem::path kData = std::filesystem::path(GLINT_SOURCE_DIR) / "data";

TEST(DataTables, TheSolarSpectrumAlwaysAndTheGasTableWhenAsked) {
    const atmosphere::DataTables without = read_data_tables(kData, false);
    ASSERT_TRUE(without.sun);
    EXPECT_FALSE(without.gases);
    // ASTM G173 at 0.5 µm: 1.9165 W m⁻² nm⁻¹ = 0.19165 W cm⁻² µm⁻¹.
    EXPECT_NEAR(without.sun->irradiance_w_per_cm2_um(0.5), 0.19165, 1e-4);
    const atmosphere::DataTables with = read_data_tables(kData, true);
    ASSERT_TRUE(with.gases);
    EXPECT_GT(with.gases->wavelengths_um().size(), 2u);
}

TEST(DataTables, AMissingOrMalformedFileIsRefusedByName) {
    const test::TempDir dir;
    try {
        (void)read_data_tables(dir.path(), false);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::io);
        EXPECT_NE(e.context().file.find("solar/astm_g173.csv"), std::string::npos)
            << e.context().file;
    }
    std::filesystem::create_directories(dir / "solar");
    std::ofstream(dir / "solar/astm_g173.csv")
        << "title\nwavelength,extraterrestrial\n280,0.1\n290,x\n";
    try {
        (void)read_data_tables(dir.path(), false);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_EQ(e.context().line, 4);
    }
}

}  // namespace data_tables_test
}  // namespace glint::inputs
