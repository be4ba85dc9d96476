// SPDX-License-Identifier: Apache-2.0
// Tests of `info`: JSON fields, the text report, and several files with a bad one.
#include "glint/app_envi/info.h"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "test_util.h"

namespace glint::app_envi {
namespace info_test {

using InfoTest = testing::TempDirTest;

io::EnviHeader rich_header() {
    io::EnviHeader h;
    h.description = "test cube";
    h.wavelength_units = "Microns";
    h.wavelength = {0.45, 0.55};
    h.fwhm = {0.02, 0.03};
    h.band_names = {"blue", "green"};
    h.data_units = "Watts/(cm2 sr um)";
    h.set_extra("glint seed", "42");
    h.set_extra("glint capture times", "{0.5, 1.5}");
    h.set_extra("map info", "{UTM, 1, 1}");
    return h;
}

TEST_F(InfoTest, JsonFields) {
    const auto file = write_cube(
        "cube.img", 5, 4, 2, io::EnviDataType::float32,
        [](std::size_t, std::size_t, std::size_t) { return 1.0; }, rich_header());
    InfoOptions options;
    options.files = {file};
    options.format = ReportFormat::json;
    std::ostringstream out;
    EXPECT_EQ(report_info(options, m_ctx, out), 0);
    const auto j = nlohmann::json::parse(out.str());
    EXPECT_EQ(j["file"], file.string());
    EXPECT_EQ(j["samples"], 5);
    EXPECT_EQ(j["lines"], 4);
    EXPECT_EQ(j["bands"], 2);
    EXPECT_EQ(j["data_type"], "float32");
    EXPECT_EQ(j["data_type_code"], 4);
    EXPECT_EQ(j["interleave"], "bip");
    EXPECT_EQ(j["header_offset"], 0);
    EXPECT_EQ(j["data_bytes"], 5 * 4 * 2 * 4);
    EXPECT_EQ(j["description"], "test cube");
    EXPECT_EQ(j["wavelength_units"], "Microns");
    EXPECT_EQ(j["data_units"], "Watts/(cm2 sr um)");
    ASSERT_EQ(j["band_info"].size(), 2u);
    EXPECT_EQ(j["band_info"][1]["name"], "green");
    EXPECT_DOUBLE_EQ(j["band_info"][1]["wavelength"].get<double>(), 0.55);
    EXPECT_DOUBLE_EQ(j["band_info"][0]["fwhm"].get<double>(), 0.02);
    EXPECT_EQ(j["glint"]["seed"], "42");
    EXPECT_EQ(j["glint"]["capture_times"], "{0.5, 1.5}");
    EXPECT_EQ(j["extra"]["map info"], "{UTM, 1, 1}");
}

TEST_F(InfoTest, TextReport) {
    const auto file = write_cube(
        "cube.img", 5, 4, 2, io::EnviDataType::uint8,
        [](std::size_t, std::size_t, std::size_t) { return 1.0; }, rich_header());
    InfoOptions options;
    options.files = {file};
    std::ostringstream out;
    EXPECT_EQ(report_info(options, m_ctx, out), 0);
    const std::string text = out.str();
    for (const char* expected :
         {"samples:           5", "lines:             4", "data type:         uint8 (1)",
          "interleave:        bip", "header offset:     0", "green", "0.55", "glint seed = 42",
          "map info = {UTM, 1, 1}", "Watts/(cm2 sr um)"}) {
        EXPECT_NE(text.find(expected), std::string::npos) << expected << "\n" << text;
    }
}

TEST_F(InfoTest, SeveralFilesCarryOnPastABadOne) {
    const auto good = write_cube("good.img", 2, 2, 1, io::EnviDataType::uint8,
                                 [](std::size_t, std::size_t, std::size_t) { return 1.0; });
    std::ofstream(path("bad.img.hdr")) << "ENVI\nsamples = 2\n";
    std::ofstream(path("bad.img")) << "xxxx";
    std::vector<std::string> errors;
    m_ctx.log =
        Log([&](LogLevel, const std::string& m) { errors.push_back(m); }, LogLevel::warning);
    InfoOptions options;
    options.files = {good, path("bad.img"), path("missing.img"), good};
    options.format = ReportFormat::json;
    std::ostringstream out;
    EXPECT_EQ(report_info(options, m_ctx, out), 1);
    const auto j = nlohmann::json::parse(out.str());
    ASSERT_TRUE(j.is_array());
    EXPECT_EQ(j.size(), 2u);
    ASSERT_EQ(errors.size(), 2u);
    EXPECT_NE(errors[0].find("bad.img"), std::string::npos);
    EXPECT_NE(errors[1].find("missing.img"), std::string::npos);
}

}  // namespace info_test
}  // namespace glint::app_envi
