// SPDX-License-Identifier: Apache-2.0
// RowBand: --rows parsing and the lines a band or a --by rows shard gives a capture.
#include "glint/schedule/row_band.h"

#include <gtest/gtest.h>

#include <set>
#include <utility>

#include "glint/core/error.h"

namespace glint::schedule {
namespace row_band_test {

using Lines = std::pair<std::uint64_t, std::uint64_t>;

TEST(RowBand, ParsesEveryForm) {
    EXPECT_EQ(parse_row_band("2:5").of(6), Lines(2, 5));
    EXPECT_EQ(parse_row_band("4:").of(6), Lines(4, 6));
    EXPECT_EQ(parse_row_band(":3").of(6), Lines(0, 3));
    EXPECT_EQ(parse_row_band("3").of(6), Lines(3, 4));
    EXPECT_EQ(parse_row_band(":").of(6), Lines(0, 6));
}

TEST(RowBand, ClipsToTheCapture) {
    EXPECT_EQ(parse_row_band("4:100").of(6), Lines(4, 6));
    EXPECT_EQ(parse_row_band("7:9").of(6), Lines(6, 6));  // none of its lines
    EXPECT_EQ(parse_row_band("0:4").of(1), Lines(0, 1));  // a TDI capture's one line
}

TEST(RowBand, RefusesWhatIsNotABand) {
    for (const char* text : {"", "5:2", "3:3", "-1:2", "a:b", "1:2:3", "1.5", " 1:2", "1:+2",
                             "18446744073709551615"}) {
        try {
            (void)parse_row_band(text);
            ADD_FAILURE() << text;
        } catch (const Error& e) {
            EXPECT_EQ(e.category(), ErrorCategory::usage) << text;
            EXPECT_NE(std::string(e.what()).find("--rows: expected A:B"), std::string::npos);
        }
    }
}

TEST(RowBand, ShardsTileEveryCaptureOnce) {
    // Bands of N shards cover 0 … L−1 exactly once, each ⌊L/N⌋ or ⌈L/N⌉ lines.
    for (std::uint64_t lines : {1u, 2u, 6u, 7u, 100u, 4096u}) {
        for (std::uint64_t n : {1u, 2u, 3u, 4u, 7u, 16u}) {
            std::uint64_t next = 0;
            for (std::uint64_t k = 1; k <= n; ++k) {
                RowBand band;
                band.shard = {k, n};
                const auto [a, b] = band.of(lines);
                EXPECT_EQ(a, next) << lines << " " << k << "/" << n;
                EXPECT_LE(b - a, (lines + n - 1) / n);
                EXPECT_GE(b - a, lines / n);
                next = b;
            }
            EXPECT_EQ(next, lines);
        }
    }
}

TEST(RowBand, ShardsOfHugeCapturesDoNotOverflow) {
    RowBand band;
    band.shard = {3, 4};
    const std::uint64_t lines = std::uint64_t{1} << 62;
    EXPECT_EQ(band.of(lines), Lines(lines / 2, lines / 4 * 3));
}

}  // namespace row_band_test
}  // namespace glint::schedule
