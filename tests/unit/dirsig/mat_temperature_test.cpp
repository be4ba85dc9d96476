// SPDX-License-Identifier: Apache-2.0
// Tests of a `.mat` entry's temperature map (mat_temperature.cpp): TEMP_SOLVER_NAME = Map
// with a drape or uv projector, an integer image through GAIN and BIAS (said once per file)
// and a floating-point image of °C, and each bad block with its message and place.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "glint/dirsig/scene_reader.h"
#include "glint/test/diagnostics.h"
#include "glint/test/temp_dir.h"

namespace glint::dirsig {
namespace mat_temperature_test {

using glint::test::only_error;
using glint::test::TempDir;
using ::testing::HasSubstr;

void write(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

/// A .mat of one material whose TEMP_SOLVER block is `solver`, beside a 3 x 1 PGM of counts
/// 0, 100, 200 and a flat curve.
std::filesystem::path write_mat(const TempDir& dir, const std::string& solver,
                                const std::string& name = "Map") {
    write(dir.path() / "flat.txt", "0.4 0.2\n20 0.2\n");
    write(dir.path() / "counts.pgm", std::string("P5\n3 1\n255\n") + '\0' + 'd' + '\xc8');
    const auto mat = dir.path() / "hot.mat";
    write(mat, "MATERIAL_ENTRY {\n    ID = 5\n    NAME = Hot\n    TEMP_SOLVER_NAME = " + name +
                   "\n    TEMP_SOLVER {\n" + solver +
                   "    }\n    SURFACE_PROPERTIES { REFLECTANCE_PROP_NAME = SimpleReflectance\n"
                   "        REFLECTANCE_PROP { TXT_FILENAME = flat.txt } }\n}\n");
    return mat;
}

const std::string kDrape =
    "        DRAPE_PROJECTOR {\n            INSERT_POINT = -5, -5, 0\n            GSD = 0.10\n"
    "            ORIGIN = IMAGE\n            FLIPX = TRUE\n            FLIPY = FALSE\n"
    "            EXTENDX = MIRROR\n            EXTENDY = REPEAT\n        }\n";

TEST(MatTemperatureMap, CountsThroughGainAndBias) {
    TempDir dir;
    const auto mat = write_mat(dir,
                               "        IMAGE_FILENAME = counts.pgm\n        GAIN = 0.1\n"
                               "        BIAS = -10\n" +
                                   kDrape);
    Diagnostics diagnostics;
    const auto materials = read_dirsig_materials(mat, {}, diagnostics);
    ASSERT_FALSE(diagnostics.has_errors()) << test::diagnostics_text(diagnostics);
    // One warning: GAIN and BIAS are glint's reading.
    ASSERT_EQ(diagnostics.warning_count(), 1u) << test::diagnostics_text(diagnostics);
    EXPECT_THAT(diagnostics.items()[0].message, HasSubstr("GAIN and BIAS read as degrees Celsius"));
    ASSERT_EQ(materials.size(), 1u);
    const auto& map = materials[0].temperature_map;
    ASSERT_TRUE(map);
    EXPECT_EQ(map->kind, model::MapKind::temperature);
    EXPECT_EQ(map->name, "Hot");
    const model::MapProjector& p = map->projector;
    EXPECT_FALSE(p.uv);
    EXPECT_EQ(p.insert_point_m, (std::array<double, 2>{-5.0, -5.0}));
    EXPECT_EQ(p.gsd_m, (std::array<double, 2>{0.1, 0.1}));
    EXPECT_EQ(p.origin, model::MapOrigin::image);
    EXPECT_TRUE(p.flip_x);
    EXPECT_FALSE(p.flip_y);
    EXPECT_EQ(p.extend_x, model::MapExtend::mirror);
    EXPECT_EQ(p.extend_y, model::MapExtend::repeat);
    // Counts 0, 100, 200 → −10, 0, 10 °C.
    ASSERT_EQ(map->raster->weights.size(), 3u);
    EXPECT_NEAR(map->raster->weights[0], 263.15, 1e-3);
    EXPECT_NEAR(map->raster->weights[1], 273.15, 1e-3);
    EXPECT_NEAR(map->raster->weights[2], 283.15, 1e-3);
}

TEST(MatTemperatureMap, UvProjector) {
    TempDir dir;
    const auto mat =
        write_mat(dir,
                  "        IMAGE_FILENAME = counts.pgm\n        GAIN = 1\n"
                  "        UV_PROJECTOR {\n            FLIPX = FALSE\n            FLIPY = TRUE\n"
                  "        }\n");
    Diagnostics diagnostics;
    const auto materials = read_dirsig_materials(mat, {}, diagnostics);
    ASSERT_FALSE(diagnostics.has_errors()) << test::diagnostics_text(diagnostics);
    ASSERT_TRUE(materials[0].temperature_map);
    EXPECT_TRUE(materials[0].temperature_map->projector.uv);
    EXPECT_TRUE(materials[0].temperature_map->projector.flip_y);
}

struct BadSolver {
    const char* name;
    std::string solver;
    const char* message;
};

class MatTemperatureMapErrors : public ::testing::TestWithParam<BadSolver> {};

TEST_P(MatTemperatureMapErrors, OneErrorAtItsKey) {
    TempDir dir;
    const auto mat = write_mat(dir, GetParam().solver);
    Diagnostics diagnostics;
    const auto materials = read_dirsig_materials(mat, {}, diagnostics);
    const Diagnostic error = only_error(diagnostics);
    EXPECT_THAT(error.message, HasSubstr(GetParam().message)) << GetParam().name;
    EXPECT_EQ(error.where.file, mat.string());
    EXPECT_GT(error.where.line, 0);
}

INSTANTIATE_TEST_SUITE_P(
    MatTemperatureMap, MatTemperatureMapErrors,
    ::testing::Values(
        BadSolver{"counts without gain", "        IMAGE_FILENAME = counts.pgm\n" + kDrape,
                  "holds integer counts: give GAIN and BIAS"},
        BadSolver{"no image", kDrape, "missing IMAGE_FILENAME"},
        BadSolver{"missing image", "        IMAGE_FILENAME = gone.img\n" + kDrape,
                  "temperature map image \"gone.img\" not found"},
        BadSolver{"no projector", "        IMAGE_FILENAME = counts.pgm\n        GAIN = 1\n",
                  "TEMP_SOLVER needs a DRAPE_PROJECTOR or a UV_PROJECTOR"},
        BadSolver{"bad extend",
                  "        IMAGE_FILENAME = counts.pgm\n        GAIN = 1\n"
                  "        DRAPE_PROJECTOR {\n            GSD = 1\n            EXTENDX = WRAP\n"
                  "        }\n",
                  "EXTENDX \"WRAP\" is not NONE, CLAMP, REPEAT or MIRROR"},
        BadSolver{"no gsd",
                  "        IMAGE_FILENAME = counts.pgm\n        GAIN = 1\n"
                  "        DRAPE_PROJECTOR {\n            ORIGIN = IMAGE\n        }\n",
                  "missing GSD"},
        BadSolver{"below absolute zero",
                  "        IMAGE_FILENAME = counts.pgm\n        GAIN = -2\n" + kDrape,
                  "texel (2, 0) is -400 degrees Celsius, below absolute zero"}),
    [](const ::testing::TestParamInfo<BadSolver>& case_info) {
        std::string name = case_info.param.name;
        for (char& c : name) {
            if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
        }
        return name;
    });

}  // namespace mat_temperature_test
}  // namespace glint::dirsig
