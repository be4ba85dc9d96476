// SPDX-License-Identifier: Apache-2.0
// glint-detect's option values: every spelling accepted (names, codes, any case) and each bad
// one refused with a usage error naming the option and its choices.
#include <gtest/gtest.h>

#include <string>

#include "glint/app_detect/detect_tool.h"
#include "glint/core/error.h"

namespace glint::app_detect {
namespace options_test {

/// The usage error's message, or "" when `f` does not throw one.
template <typename F>
std::string usage_message(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.category() == ErrorCategory::usage ? e.message() : "not a usage error";
    }
    return "";
}

TEST(DetectOptions, DataTypeByNameOrCode) {
    EXPECT_EQ(parse_data_type("uint16"), io::EnviDataType::uint16);
    EXPECT_EQ(parse_data_type("UINT16"), io::EnviDataType::uint16);
    EXPECT_EQ(parse_data_type("12"), io::EnviDataType::uint16);
    EXPECT_EQ(parse_data_type("float64"), io::EnviDataType::float64);
    EXPECT_EQ(parse_data_type("1"), io::EnviDataType::uint8);
    EXPECT_NE(usage_message([] { parse_data_type("complex64"); }), "");  // counts are real
    EXPECT_NE(usage_message([] { parse_data_type("6"); }), "");
    EXPECT_EQ(usage_message([] { parse_data_type("int8"); }),
              "--data-type: unknown ENVI data type 'int8' (uint8, int16, uint16, int32, uint32, "
              "int64, uint64, float32, float64 or their codes 1, 2, 12, 3, 13, 14, 15, 4, 5)");
}

TEST(DetectOptions, MosaicPhaseAndTdiMode) {
    EXPECT_EQ(parse_mosaic("Bayer"), detect::MosaicChoice::bayer);
    EXPECT_EQ(parse_mosaic("truesense"), detect::MosaicChoice::truesense);
    EXPECT_EQ(parse_mosaic("NONE"), detect::MosaicChoice::none);
    EXPECT_EQ(usage_message([] { parse_mosaic("xtrans"); }),
              "--mosaic: expected bayer, truesense or none, got 'xtrans'");
    EXPECT_EQ(parse_bayer_phase("gbrg"), detect::BayerPhase::gbrg);
    EXPECT_EQ(usage_message([] { parse_bayer_phase("rgbg"); }),
              "--bayer-phase: expected rggb, grbg, gbrg or bggr, got 'rgbg'");
    EXPECT_EQ(parse_tdi_mode("Digital"), detect::TdiMode::digital);
    EXPECT_EQ(parse_tdi_mode("charge"), detect::TdiMode::charge);
    EXPECT_EQ(usage_message([] { parse_tdi_mode("analog"); }),
              "--tdi-mode: expected charge or digital, got 'analog'");
}

}  // namespace options_test
}  // namespace glint::app_detect
