// SPDX-License-Identifier: Apache-2.0
// Tests of `stats`: values of known cubes (with NaN and infinities), accuracy far from zero,
// and the JSON report.
#include "glint/app_envi/stats.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "glint/core/error.h"
#include "test_util.h"

namespace glint::app_envi {
namespace stats_test {

using StatsTest = testing::TempDirTest;

TEST_F(StatsTest, KnownCube) {
    // Band 0: x + 10 y over a 4 x 3 grid; band 1: constant 2 with one NaN and one -inf.
    const auto file = write_cube("cube.img", 4, 3, 2, io::EnviDataType::float64,
                                 [](std::size_t x, std::size_t y, std::size_t b) {
                                     if (b == 0) return double(x + 10 * y);
                                     if (x == 1 && y == 1) return std::nan("");
                                     if (x == 2 && y == 0)
                                         return -std::numeric_limits<double>::infinity();
                                     return 2.0;
                                 });
    const StatsReport r = compute_stats(file, m_ctx);
    ASSERT_EQ(r.bands.size(), 2u);
    EXPECT_EQ(r.samples, 4u);
    EXPECT_EQ(r.lines, 3u);
    EXPECT_EQ(r.data_type, "float64");
    const BandStatistics& b0 = r.bands[0];
    EXPECT_EQ(b0.count, 12u);
    EXPECT_EQ(b0.min, 0.0);
    EXPECT_EQ(b0.max, 23.0);
    EXPECT_DOUBLE_EQ(b0.mean, 11.5);
    // Population variance: var(x) + 100 var(y) = 1.25 + 100 * 2/3.
    EXPECT_DOUBLE_EQ(b0.std_dev, std::sqrt(1.25 + 200.0 / 3.0));
    const BandStatistics& b1 = r.bands[1];
    EXPECT_EQ(b1.count, 10u);
    EXPECT_EQ(b1.nan, 1u);
    EXPECT_EQ(b1.infinite, 1u);
    EXPECT_EQ(b1.mean, 2.0);
    EXPECT_EQ(b1.std_dev, 0.0);
}

TEST_F(StatsTest, AccurateFarFromZero) {
    // 1e9 + {0, 1, 2, 3} repeated: mean 1e9 + 1.5, std sqrt(1.25). A naive sum of squares
    // loses every digit here.
    const auto file =
        write_cube("far.img", 400, 50, 1, io::EnviDataType::float64,
                   [](std::size_t x, std::size_t, std::size_t) { return 1e9 + double(x % 4); });
    const StatsReport r = compute_stats(file, m_ctx);
    EXPECT_EQ(r.bands[0].mean, 1e9 + 1.5);
    EXPECT_NEAR(r.bands[0].std_dev, std::sqrt(1.25), 1e-12);
}

TEST_F(StatsTest, BandWithoutFiniteValues) {
    const auto file =
        write_cube("nan.img", 2, 2, 1, io::EnviDataType::float32,
                   [](std::size_t, std::size_t, std::size_t) { return std::nan(""); });
    const StatsReport r = compute_stats(file, m_ctx);
    EXPECT_EQ(r.bands[0].count, 0u);
    EXPECT_EQ(r.bands[0].nan, 4u);
    EXPECT_TRUE(std::isnan(r.bands[0].mean));
    std::ostringstream json;
    write_stats(r, ReportFormat::json, json);
    const auto j = nlohmann::json::parse(json.str());
    EXPECT_TRUE(j["band_stats"][0]["mean"].is_null());
    EXPECT_EQ(j["band_stats"][0]["nan"], 4);
}

TEST_F(StatsTest, JsonAndTextReports) {
    io::EnviHeader header;
    header.band_names = {"red", "green"};
    const auto file = write_cube(
        "rg.img", 3, 2, 2, io::EnviDataType::uint16,
        [](std::size_t x, std::size_t, std::size_t b) { return double(100 * b + x); }, header);
    std::ostringstream json;
    StatsOptions options;
    options.file = file;
    options.format = ReportFormat::json;
    EXPECT_EQ(report_stats(options, m_ctx, json), 0);
    const auto j = nlohmann::json::parse(json.str());
    EXPECT_EQ(j["bands"], 2);
    EXPECT_EQ(j["data_type"], "uint16");
    EXPECT_EQ(j["band_stats"][1]["name"], "green");
    EXPECT_EQ(j["band_stats"][1]["min"], 100.0);
    EXPECT_EQ(j["band_stats"][1]["max"], 102.0);
    EXPECT_EQ(j["band_stats"][1]["mean"], 101.0);
    std::ostringstream text;
    options.format = ReportFormat::text;
    report_stats(options, m_ctx, text);
    EXPECT_NE(text.str().find("green"), std::string::npos);
    EXPECT_NE(text.str().find("uint16"), std::string::npos);
}

TEST_F(StatsTest, DataIgnoreValueIsCountedApart) {
    // float32 with data ignore value -0.1 (matched as float32 stores it): two of six values.
    io::EnviHeader header;
    header.band_names = {"Temperature"};
    header.set_extra("data ignore value", "-0.1");
    const auto file = write_cube(
        "ig.img", 3, 2, 1, io::EnviDataType::float32,
        [](std::size_t x, std::size_t, std::size_t) { return x == 1 ? -0.1 : double(x); }, header);
    const StatsReport r = compute_stats(file, m_ctx);
    ASSERT_TRUE(r.ignore_value);
    EXPECT_EQ(r.bands[0].ignored, 2u);
    EXPECT_EQ(r.bands[0].count, 4u);
    EXPECT_EQ(r.bands[0].min, 0.0);
    EXPECT_EQ(r.bands[0].mean, 1.0);
    std::ostringstream json;
    write_stats(r, ReportFormat::json, json);
    const auto j = nlohmann::json::parse(json.str());
    EXPECT_NEAR(j["data_ignore_value"].get<double>(), -0.1, 1e-7);
    EXPECT_EQ(j["band_stats"][0]["ignored"], 2);
    std::ostringstream text;
    write_stats(r, ReportFormat::text, text);
    EXPECT_NE(text.str().find("data ignore value -0.1"), std::string::npos) << text.str();
    EXPECT_NE(text.str().find("ignored"), std::string::npos) << text.str();

    // NaN as the ignore value: the NaN column; no ignored column in the text.
    header.set_extra("data ignore value", "NaN");
    const auto nan_file = write_cube(
        "nan.img", 2, 1, 1, io::EnviDataType::float64,
        [](std::size_t x, std::size_t, std::size_t) { return x == 0 ? std::nan("") : 5.0; },
        header);
    const StatsReport n = compute_stats(nan_file, m_ctx);
    EXPECT_EQ(n.bands[0].nan, 1u);
    EXPECT_EQ(n.bands[0].ignored, 0u);
    std::ostringstream nan_json;
    write_stats(n, ReportFormat::json, nan_json);
    EXPECT_EQ(nlohmann::json::parse(nan_json.str())["data_ignore_value"], "NaN");
    std::ostringstream nan_text;
    write_stats(n, ReportFormat::text, nan_text);
    EXPECT_NE(nan_text.str().find("data ignore value NaN"), std::string::npos);
    EXPECT_EQ(nan_text.str().find("ignored"), std::string::npos);

    // Not a number: not honoured, with a warning.
    header.set_extra("data ignore value", "none");
    const auto odd = write_cube(
        "odd.img", 1, 1, 1, io::EnviDataType::uint8,
        [](std::size_t, std::size_t, std::size_t) { return 0.0; }, header);
    EXPECT_FALSE(compute_stats(odd, m_ctx).ignore_value);
}

TEST_F(StatsTest, MissingFileNamesIt) {
    try {
        compute_stats(path("missing.img"), m_ctx);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("missing.img"), std::string::npos);
    }
}

}  // namespace stats_test
}  // namespace glint::app_envi
