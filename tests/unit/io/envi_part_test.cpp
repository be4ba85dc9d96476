// SPDX-License-Identifier: Apache-2.0
// The index runs of the part keys: written compactly, read back exactly, junk refused.
#include "glint/io/envi_part.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace glint::io {
namespace envi_part_test {

using Indices = std::vector<std::uint64_t>;

TEST(IndexRuns, WritesRunsAndLoneIndices) {
    EXPECT_EQ(format_index_runs({0, 1, 2, 3, 7, 9, 10}), "{0:4, 7, 9:11}");
    EXPECT_EQ(format_index_runs({5}), "{5}");
    EXPECT_EQ(format_index_runs({}), "{}");
}

TEST(IndexRuns, ReadsWhatItWrites) {
    for (const Indices& v : {Indices{}, Indices{0}, Indices{0, 1, 2, 3, 7, 9, 10},
                             Indices{4, 6, 8, 9, 100, 101, 102, 1000000}}) {
        EXPECT_EQ(parse_index_runs(format_index_runs(v)), v);
    }
}

TEST(IndexRuns, RefusesJunkAndDisorder) {
    for (const char* text : {"{a}", "{3:3}", "{4:2}", "{1, 1}", "{5, 2}", "{0:4, 3}", "{1:}",
                             "{-1}", "{0:99999999999}"}) {
        EXPECT_FALSE(parse_index_runs(text)) << text;
    }
}

TEST(IndexRuns, CountsWithoutListing) {
    EXPECT_EQ(count_index_runs("{0:4, 7, 9:11}"), 7u);
    EXPECT_EQ(count_index_runs("{}"), 0u);
    // A few bytes naming 2^32 and 2^64 - 1 indices: counted, never listed.
    EXPECT_EQ(count_index_runs("{0:4294967296}"), 4294967296u);
    EXPECT_EQ(count_index_runs("{0:18446744073709551615}"), 18446744073709551615u);
    EXPECT_FALSE(parse_index_runs("{0:4294967297}"));
    EXPECT_FALSE(count_index_runs("{0:18446744073709551615, 18446744073709551615:}"));
    EXPECT_FALSE(count_index_runs("{5, 2}"));
}

}  // namespace envi_part_test
}  // namespace glint::io
