// SPDX-License-Identifier: Apache-2.0
// The ADC (clipping at both ends, rounding, 12-bit full scale 4095) and the storage of counts
// in narrower types (uint8 keeps the low 8 bits, as the DIRSIG5 BasicPlatform manual says).
#include "glint/detect/adc.h"

#include <gtest/gtest.h>

#include <tuple>

#include "detect_test_support.h"

namespace glint::detect {
namespace adc_test {

TEST(Adc, LinearRoundedAndClippedAtBothEnds) {
    // [1000, 5095] e over 12 bits: 1 DN per electron.
    EXPECT_EQ(adc_count(1000, 1000, 5095, 12), 0);
    EXPECT_EQ(adc_count(999, 1000, 5095, 12), 0);
    EXPECT_EQ(adc_count(-1e9, 1000, 5095, 12), 0);
    EXPECT_EQ(adc_count(1000.49, 1000, 5095, 12), 0);
    EXPECT_EQ(adc_count(1000.5, 1000, 5095, 12), 1);
    EXPECT_EQ(adc_count(3000, 1000, 5095, 12), 2000);
    EXPECT_EQ(adc_count(5095, 1000, 5095, 12), 4095);
    EXPECT_EQ(adc_count(5096, 1000, 5095, 12), 4095);
    EXPECT_EQ(adc_count(1e300, 1000, 5095, 12), 4095);
    EXPECT_EQ(adc_count(std::nan(""), 1000, 5095, 12), 0);
    // The manual's example: 0..100e3 e on 12 bits gives 0..4095.
    EXPECT_EQ(adc_count(100e3, 0, 100e3, 12), 4095);
    EXPECT_EQ(adc_count(50e3, 0, 100e3, 12), 2048);  // 2047.5 rounds up
    EXPECT_EQ(adc_count(1e12, 0, 1, 32), 4294967295.0);
    EXPECT_EQ(adc_count(0.6, 0, 1, 1), 1);
}

TEST(Adc, StorageKeepsTheLowBits) {
    EXPECT_EQ(stored_count(4095, io::EnviDataType::uint8), 255);
    EXPECT_EQ(stored_count(256, io::EnviDataType::uint8), 0);
    EXPECT_EQ(stored_count(300, io::EnviDataType::uint8), 44);
    EXPECT_EQ(stored_count(255, io::EnviDataType::uint8), 255);
    EXPECT_EQ(stored_count(4095, io::EnviDataType::uint16), 4095);
    EXPECT_EQ(stored_count(65535, io::EnviDataType::uint16), 65535);
    EXPECT_EQ(stored_count(65536, io::EnviDataType::uint16), 0);
    EXPECT_EQ(stored_count(4095, io::EnviDataType::int16), 4095);
    EXPECT_EQ(stored_count(40000, io::EnviDataType::int16), 40000 - 65536);
    EXPECT_EQ(stored_count(4294967295.0, io::EnviDataType::uint32), 4294967295.0);
    EXPECT_EQ(stored_count(4294967295.0, io::EnviDataType::int32), -1);
    EXPECT_EQ(stored_count(4294967295.0, io::EnviDataType::float64), 4294967295.0);
    EXPECT_EQ(stored_count(16777217.0, io::EnviDataType::float32), 16777216.0);
    EXPECT_EQ(lossless_count_bits(io::EnviDataType::uint8), 8);
    EXPECT_EQ(lossless_count_bits(io::EnviDataType::uint16), 16);
}

TEST(Adc, TwelveBitCountsInUint16AndUint8) {
    // Bright pixels saturate at 4095 in uint16; in uint8 they keep the low 8 bits (255).
    DetectionSettings s = test::settings(0, 0, 0, 4095, 12);
    s.noise = false;
    for (auto [type, saturated, mid] : {std::tuple{io::EnviDataType::uint16, 4095.0, 1000.0},
                                        std::tuple{io::EnviDataType::uint8, 255.0, 232.0}}) {
        s.data_type = type;
        const DetectionChain chain(s, 3);
        std::vector<double> in{test::fluence_for(1e9), test::fluence_for(1000.0),
                               test::fluence_for(0.0)};
        std::vector<double> out(3);
        chain.process_line({}, in, out);
        EXPECT_EQ(out[0], saturated);
        EXPECT_EQ(out[1], mid);  // 1000 & 0xFF = 232
        EXPECT_EQ(out[2], 0);
    }
}

}  // namespace adc_test
}  // namespace glint::detect
