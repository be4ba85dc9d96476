// SPDX-License-Identifier: Apache-2.0
// Tests of the `.wth` weather history (glint/dirsig/wth_reader.h): DIRSIG's layout (a header
// of rows and step, 13 columns, negatives run into the field before them) read into SI units
// and interpolated; precipitation and cloud types said once per file; every bad row an error
// at its line, the history then empty.
#include "glint/dirsig/wth_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "glint/test/diagnostics.h"

namespace glint::dirsig {
namespace wth_reader_test {

using glint::test::only_error;
using ::testing::HasSubstr;

/// One row as DIRSIG's writer prints it (fixed widths, the time unpadded).
std::string row(double time_h, double air_c, double rh, double dew_c, double wind, double direct,
                double diffuse, double exposure = 1.0, int cloud = 0, double rain = 0.0) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "%.2f%6.2f %8.2f %5.2f%6.2f %7.2f %9.2f %9.2f %5.2f %2d %2d %7.2f %6.2f\n",
                  time_h, air_c, 1000.0, rh, dew_c, wind, direct, diffuse, exposure, cloud, 0, rain,
                  air_c);
    return text;
}

TEST(WthReader, ReadsDirsigsLayoutIntoSiUnits) {
    // A 2-hour history every 0.5 h: a cold night warming, the sun rising at 1.5 h.
    std::string text = "5 0.500000\n";
    text += row(0.0, -15.0, 0.68, -20.0, 5.0, 0.0, 0.0);
    text += row(0.5, -14.0, 0.66, -20.0, 4.0, 0.0, 0.0);
    text += row(1.0, -12.0, 0.60, -20.0, 3.0, 0.0, 0.0);
    text += row(1.5, -10.0, 0.55, -20.0, 2.0, 52.48, 0.14);
    text += row(2.0, 1.5, 0.40, -19.0, 2.0, 80.00, 2.00);
    ASSERT_NE(text.find("0.00-15.00"), std::string::npos);  // run together, as DIRSIG writes
    Diagnostics diagnostics;
    const model::Weather w = parse_wth(text, "day.wth", diagnostics);
    ASSERT_FALSE(diagnostics.has_errors()) << test::diagnostics_text(diagnostics);
    EXPECT_EQ(diagnostics.warning_count(), 0u);
    ASSERT_EQ(w.records.size(), 5u);
    EXPECT_EQ(w.step_h, 0.5);
    const model::WeatherRecord& r = w.records[3];
    EXPECT_EQ(r.line, 5);
    EXPECT_NEAR(r.air_temperature_k, 263.15, 1e-12);
    EXPECT_NEAR(r.dew_point_k, 253.15, 1e-12);
    EXPECT_EQ(r.pressure_hpa, 1000.0);
    EXPECT_EQ(r.relative_humidity, 0.55);
    EXPECT_EQ(r.wind_speed_m_per_s, 2.0);
    EXPECT_NEAR(r.direct_insolation_w_per_m2, 52.48 * 11.63, 1e-9);  // Langley/h
    EXPECT_NEAR(r.diffuse_insolation_w_per_m2, 0.14 * 11.63, 1e-9);
    // Linear between rows, held beyond.
    const model::WeatherRecord mid = w.at(1.75);
    EXPECT_NEAR(mid.air_temperature_k, 273.15 + 0.5 * (-10.0 + 1.5), 1e-12);
    EXPECT_NEAR(mid.direct_insolation_w_per_m2, 0.5 * (52.48 + 80.0) * 11.63, 1e-9);
    EXPECT_NEAR(w.at(-1.0).air_temperature_k, 258.15, 1e-12);
    EXPECT_NEAR(w.at(9.0).air_temperature_k, 274.65, 1e-12);
}

TEST(WthReader, PrecipitationAndCloudsAreSaidOncePerFile) {
    std::string text = "3 0.25\n";
    text += row(0.0, 10.0, 0.9, 8.0, 3.0, 0.0, 10.0, 0.2, 3, 0.1);
    text += row(0.25, 10.0, 0.9, 8.0, 3.0, 0.0, 10.0, 0.2, 3, 0.2);
    text += row(0.5, 10.0, 0.9, 8.0, 3.0, 0.0, 10.0, 0.2, 3, 0.0);
    Diagnostics diagnostics;
    const model::Weather w = parse_wth(text, "rain.wth", diagnostics);
    EXPECT_EQ(w.records.size(), 3u);
    EXPECT_EQ(diagnostics.warning_count(), 2u) << test::diagnostics_text(diagnostics);
    const std::string said = test::diagnostics_text(diagnostics);
    EXPECT_THAT(said, HasSubstr("rain.wth:2: precipitation is not modelled"));
    EXPECT_THAT(said, HasSubstr("rain.wth:2: cloud types are not modelled"));
}

TEST(WthReader, BadRowsAreErrorsAtTheirLines) {
    const std::string good = row(0.0, 10.0, 0.5, 2.0, 3.0, 0.0, 0.0);
    const struct {
        std::string text;
        std::string message;
        int line;
    } cases[] = {
        {"193\n" + good, "expected the header: the number of rows and the hours between them", 1},
        {"2 0.25\n" + good + row(0.5, 10.0, 0.5, 2.0, 3.0, 0.0, 0.0), "time 0.5 h, expected 0.25 h",
         3},
        {"2 0.25\n" + good + "0.25 10.0 1000 0.5 2.0 3.0 0.0 0.0 1.0 0 0 0.0\n",
         "12 values, expected 13", 3},
        {"1 0.25\n" + row(0.0, 10.0, 68.0, 2.0, 3.0, 0.0, 0.0),
         "relative humidity 68 is not a fraction in [0, 1] (a percentage?)", 2},
        {"1 0.25\n" + row(0.0, 10.0, 0.5, 2.0, 3.0, 0.0, 0.0, 1.5),
         "sky exposure 1.5 is not in [0, 1]", 2},
        {"1 0.25\n0.00 1O.0 1000 0.5 2.0 3.0 0.0 0.0 1.0 0 0 0.0 10.0\n",
         "\"1O.0\" is not a number", 2},
        {"3 0.25\n" + good, "the header says 3 rows, the file has 1", 2},
        {"", "no header line", 1},
    };
    for (const auto& c : cases) {
        Diagnostics diagnostics;
        const model::Weather w = parse_wth(c.text, "bad.wth", diagnostics);
        const Diagnostic error = only_error(diagnostics);
        EXPECT_THAT(error.message, HasSubstr(c.message));
        EXPECT_EQ(error.where.file, "bad.wth");
        EXPECT_EQ(error.where.line, c.line) << c.message;
        EXPECT_TRUE(w.records.empty()) << c.message;
    }
}

}  // namespace wth_reader_test
}  // namespace glint::dirsig
