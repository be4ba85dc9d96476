// SPDX-License-Identifier: Apache-2.0
// Tests of a `.mat` entry's THERM parameters (mat_therm.cpp): the keys of a real Lake Tahoe
// style entry converted to SI (cal/(g C), g/cm³, cal/(cm h C), cm), glint's readings said once
// per file however many materials use them, VISIBLE_EMISSIVITY as the older solar
// absorptance, and each bad key with its message and place.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "glint/dirsig/scene_reader.h"
#include "glint/test/diagnostics.h"
#include "glint/test/temp_dir.h"

namespace glint::dirsig {
namespace mat_therm_test {

using glint::test::only_error;
using glint::test::TempDir;
using ::testing::HasSubstr;

/// One MATERIAL_ENTRY with id `id` and THERM block `solver`.
std::string entry(int id, const std::string& solver) {
    return "MATERIAL_ENTRY {\n    ID = " + std::to_string(id) + "\n    NAME = M" +
           std::to_string(id) + "\n    TEMP_SOLVER_NAME = Therm\n    TEMP_SOLVER {\n" + solver +
           "    }\n    SURFACE_PROPERTIES { REFLECTANCE_PROP_NAME = SimpleReflectance\n"
           "        REFLECTANCE_PROP { TXT_FILENAME = flat.txt } }\n}\n";
}

std::filesystem::path write_mat(const TempDir& dir, const std::string& text) {
    std::ofstream(dir.path() / "flat.txt") << "0.4 0.2\n20 0.2\n";
    const auto mat = dir.path() / "therm.mat";
    std::ofstream(mat) << text;
    return mat;
}

const std::string kConcrete =
    "        SPECIFIC_HEAT        = 0.1601\n        MASS_DENSITY         = 2.28\n"
    "        THERMAL_CONDUCTIVITY = 15.48\n        SOLAR_ABSORPTION     = 0.73\n"
    "        THERMAL_EMISSIVITY   = 0.94\n        EXPOSED_AREA         = 0.39\n"
    "        THICKNESS            = 1\n";

TEST(MatTherm, KeysAreConvertedToSiAndReadingsSaidOncePerFile) {
    TempDir dir;
    const std::string water =
        "        SPECIFIC_HEAT = 1\n        MASS_DENSITY = 1\n        THERMAL_CONDUCTIVITY = "
        "5.13\n        VISIBLE_EMISSIVITY = 0.45\n        EXPOSED_AREA = -0.5\n"
        "        THICKNESS = 5\n        SPECULARITY = 0.1\n";
    const auto mat = write_mat(dir, entry(1, kConcrete) + entry(2, water) + entry(3, kConcrete));
    Diagnostics diagnostics;
    const auto materials = read_dirsig_materials(mat, {}, diagnostics);
    ASSERT_FALSE(diagnostics.has_errors()) << test::diagnostics_text(diagnostics);
    ASSERT_EQ(materials.size(), 3u);
    ASSERT_TRUE(materials[0].therm);
    const model::ThermProperties& c = *materials[0].therm;
    EXPECT_NEAR(c.specific_heat_j_per_kg_k, 0.1601 * 4186.8, 1e-9);
    EXPECT_NEAR(c.density_kg_per_m3, 2280.0, 1e-9);
    EXPECT_NEAR(c.conductivity_w_per_m_k, 1.8003, 1e-4);  // 15.48 × 0.1163
    EXPECT_EQ(c.solar_absorptance, 0.73);
    EXPECT_EQ(c.thermal_emissivity, 0.94);
    EXPECT_EQ(c.exposed_area, 0.39);
    EXPECT_NEAR(c.thickness_m, 0.01, 1e-15);
    const model::ThermProperties& w = *materials[1].therm;
    EXPECT_NEAR(w.conductivity_w_per_m_k, 0.5966, 1e-4);  // water: 0.60 W/(m K)
    EXPECT_EQ(w.solar_absorptance, 0.45);                 // the older key
    EXPECT_FALSE(w.thermal_emissivity);                   // from the .ems when rendered
    EXPECT_EQ(w.exposed_area, 0.5);                       // the magnitude
    // Warnings, each once however many materials: the units, the negative exposed area,
    // SPECULARITY.
    const std::string text = test::diagnostics_text(diagnostics);
    EXPECT_EQ(diagnostics.warning_count(), 3u) << text;
    EXPECT_THAT(text, HasSubstr("THERM units read as DIRSIG's files use them"));
    EXPECT_THAT(text, HasSubstr("a negative EXPOSED_AREA is read as its magnitude"));
    EXPECT_THAT(text, HasSubstr("SPECULARITY (the surface properties' lobes apply) ignored"));
}

TEST(MatTherm, ZeroThicknessIsAFaceWithoutStorage) {
    TempDir dir;
    const auto mat =
        write_mat(dir, entry(4,
                             "        SPECIFIC_HEAT = 1\n        MASS_DENSITY = 1\n"
                             "        THERMAL_CONDUCTIVITY = 0\n        SOLAR_ABSORPTION = 0.91\n"
                             "        THERMAL_EMISSIVITY = 0.88\n        EXPOSED_AREA = 0.16\n"
                             "        THICKNESS = 0\n"));
    Diagnostics diagnostics;
    const auto materials = read_dirsig_materials(mat, {}, diagnostics);
    ASSERT_FALSE(diagnostics.has_errors()) << test::diagnostics_text(diagnostics);
    EXPECT_EQ(materials[0].therm->thickness_m, 0.0);
    EXPECT_THAT(test::diagnostics_text(diagnostics), HasSubstr("its face stores no heat"));
}

TEST(MatTherm, BadKeysAreErrorsAtTheirLines) {
    const struct {
        std::string solver;
        std::string message;
        int line;
    } cases[] = {
        {"        SPECIFIC_HEAT = 1\n        MASS_DENSITY = 1\n        EXPOSED_AREA = 0.3\n",
         "THERM material \"M1\" needs THERMAL_CONDUCTIVITY", 5},
        {"        SPECIFIC_HEAT = -1\n        MASS_DENSITY = 1\n        THERMAL_CONDUCTIVITY = 1\n"
         "        EXPOSED_AREA = 0.3\n",
         "SPECIFIC_HEAT \"-1\" is not a number >= 0", 6},
        {"        SPECIFIC_HEAT = 1\n        MASS_DENSITY = 1\n        THERMAL_CONDUCTIVITY = 1\n"
         "        EXPOSED_AREA = 1.5\n",
         "EXPOSED_AREA \"1.5\" is not a number in [-1, 1]", 9},
        {"        SPECIFIC_HEAT = 1\n        MASS_DENSITY = 1\n        THERMAL_CONDUCTIVITY = 1\n"
         "        EXPOSED_AREA = 0.3\n        SOLAR_ABSORPTION = 1.2\n",
         "SOLAR_ABSORPTION \"1.2\" is not a number in [0, 1]", 10},
    };
    for (const auto& c : cases) {
        TempDir dir;
        const auto mat = write_mat(dir, entry(1, c.solver));
        Diagnostics diagnostics;
        const auto materials = read_dirsig_materials(mat, {}, diagnostics);
        const Diagnostic error = only_error(diagnostics);
        EXPECT_THAT(error.message, HasSubstr(c.message));
        EXPECT_EQ(error.where.line, c.line) << c.message;
        EXPECT_FALSE(materials.empty() ? false : bool(materials[0].therm)) << c.message;
    }
}

}  // namespace mat_therm_test
}  // namespace glint::dirsig
