// SPDX-License-Identifier: Apache-2.0
// glint-schedule's filters and shards: parsing --captures and --shard, the shard rule on
// synthetic problem counts (every capture in exactly one shard, shards contiguous, each
// within one capture's problem count of total/N), and the filters resolved against a
// loaded schedule (unknown focal plane or task: a message listing what there is).
#include "glint/app_schedule/selection.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "glint/core/error.h"
#include "glint/test/schedules.h"

namespace glint::app_schedule {
namespace selection_test {

namespace fs = std::filesystem;

const fs::path kData = fs::path(GLINT_TEST_DATA_DIR) / "schedule_tool";

TEST(ParseCaptureRange, AcceptsSliceForms) {
    const CaptureRange both = parse_capture_range("3:7");
    EXPECT_EQ(both.first, 3u);
    ASSERT_TRUE(both.end);
    EXPECT_EQ(*both.end, 7u);
    EXPECT_TRUE(both.contains(3));
    EXPECT_TRUE(both.contains(6));
    EXPECT_FALSE(both.contains(7));
    EXPECT_FALSE(both.contains(2));

    const CaptureRange open_end = parse_capture_range("5:");
    EXPECT_EQ(open_end.first, 5u);
    EXPECT_FALSE(open_end.end);
    EXPECT_TRUE(open_end.contains(1'000'000'000));

    const CaptureRange open_start = parse_capture_range(":2");
    EXPECT_EQ(open_start.first, 0u);
    EXPECT_TRUE(open_start.contains(0));
    EXPECT_FALSE(open_start.contains(2));

    const CaptureRange single = parse_capture_range("9");
    EXPECT_TRUE(single.contains(9));
    EXPECT_FALSE(single.contains(10));
    EXPECT_FALSE(single.contains(8));
}

TEST(ParseCaptureRange, RejectsJunkWithTheFlagName) {
    for (const char* text : {"", ":", "a:b", "-1:3", "5:5", "7:3", "1:2:3", " 1:2", "1.5"}) {
        try {
            parse_capture_range(text);
            ADD_FAILURE() << "accepted \"" << text << "\"";
        } catch (const Error& e) {
            EXPECT_EQ(e.category(), ErrorCategory::usage) << text;
            EXPECT_NE(e.message().find("--captures"), std::string::npos) << e.message();
        }
    }
}

TEST(ParseShard, AcceptsKOfN) {
    const ShardSpec shard = parse_shard("2/5");
    EXPECT_EQ(shard.index, 2u);
    EXPECT_EQ(shard.count, 5u);
    EXPECT_EQ(parse_shard("1/1").count, 1u);
}

TEST(ParseShard, RejectsOutOfRange) {
    for (const char* text : {"0/3", "4/3", "1/0", "3", "/3", "1/", "a/b", "-1/2", "1/2/3"}) {
        try {
            parse_shard(text);
            ADD_FAILURE() << "accepted \"" << text << "\"";
        } catch (const Error& e) {
            EXPECT_EQ(e.category(), ErrorCategory::usage) << text;
            EXPECT_NE(e.message().find("--shard"), std::string::npos) << e.message();
        }
    }
}

/// Splits `weights` into `n` shards; returns the shard of each capture.
std::vector<std::uint64_t> split(const std::vector<std::uint64_t>& weights, std::uint64_t n) {
    SelectionTotals totals;
    for (std::uint64_t w : weights) {
        ++totals.captures;
        totals.problems += w;
    }
    ShardSplitter splitter(totals, n);
    std::vector<std::uint64_t> shards;
    for (std::uint64_t w : weights) shards.push_back(splitter.shard_of(w));
    return shards;
}

/// Checks the documented properties of a split.
void expect_balanced(const std::vector<std::uint64_t>& weights, std::uint64_t n) {
    const std::vector<std::uint64_t> shards = split(weights, n);
    std::uint64_t total = 0;
    std::uint64_t largest = 0;
    for (std::uint64_t w : weights) {
        total += w;
        largest = std::max(largest, w);
    }
    std::vector<std::uint64_t> sums(n + 1, 0);
    for (std::size_t i = 0; i < weights.size(); ++i) {
        ASSERT_GE(shards[i], 1u);
        ASSERT_LE(shards[i], n);
        if (i > 0) {
            ASSERT_GE(shards[i], shards[i - 1]) << "shards are contiguous runs";
        }
        sums[shards[i]] += weights[i];
    }
    const double ideal = static_cast<double>(total) / static_cast<double>(n);
    for (std::uint64_t k = 1; k <= n; ++k) {
        EXPECT_LE(std::abs(static_cast<double>(sums[k]) - ideal), static_cast<double>(largest))
            << "shard " << k << " of " << n;
    }
}

TEST(ShardSplitter, EqualWeightsSplitEvenly) {
    const std::vector<std::uint64_t> weights(12, 100);
    const std::vector<std::uint64_t> shards = split(weights, 3);
    EXPECT_EQ(shards, (std::vector<std::uint64_t>{1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3}));
    expect_balanced(weights, 3);
}

TEST(ShardSplitter, MixedWeightsStayWithinOneCapture) {
    // A pattern like a framing camera (192 px) beside a line scanner (1024 px) and a small
    // rolling focal plane (32 px), for many shard counts.
    std::vector<std::uint64_t> weights;
    for (int i = 0; i < 300; ++i) weights.push_back(i % 3 == 0 ? 192 : (i % 3 == 1 ? 32 : 1024));
    for (std::uint64_t n : {1u, 2u, 3u, 4u, 7u, 16u, 299u, 300u, 1000u}) {
        SCOPED_TRACE(n);
        expect_balanced(weights, n);
    }
}

TEST(ShardSplitter, OneHugeCaptureTakesItsOwnShard) {
    const std::vector<std::uint64_t> weights{1, 1, 1000, 1, 1};
    const std::vector<std::uint64_t> shards = split(weights, 3);
    EXPECT_EQ(shards[2], 2u);
    expect_balanced(weights, 3);
}

TEST(ShardSplitter, ZeroProblemsFallBackToCaptureCounts) {
    const std::vector<std::uint64_t> weights(6, 0);
    EXPECT_EQ(split(weights, 2), (std::vector<std::uint64_t>{1, 1, 1, 2, 2, 2}));
}

TEST(ShardSplitter, HugeTotalsDoNotOverflow) {
    // 3.6e8 captures of 2^31 problems each: N · 2C exceeds 64 bits.
    SelectionTotals totals{360'000'000, 360'000'000ull * (1ull << 31)};
    ShardSplitter splitter(totals, 1000);
    // Skip ahead by feeding big captures: the shard index must never decrease.
    std::uint64_t last = 1;
    for (int i = 0; i < 1000; ++i) {
        const std::uint64_t shard = splitter.shard_of(360'000ull * (1ull << 31));
        EXPECT_GE(shard, last);
        EXPECT_LE(shard, 1000u);
        last = shard;
    }
    EXPECT_EQ(last, 1000u);
}

class SelectionTest : public ::testing::Test {
protected:
    SelectionTest() : m_schedule(test::load_schedule(kData / "small.jsim", {}, m_diag)) {}

    Diagnostics m_diag;
    schedule::Schedule m_schedule;
};

TEST_F(SelectionTest, FocalPlaneByNameOrInstrumentSlashName) {
    Filters filters;
    filters.focal_plane = "RGB";
    const Selection by_name(m_schedule, filters);
    filters.focal_plane = "Cam/RGB";
    const Selection by_path(m_schedule, filters);
    std::size_t selected = 0;
    for (std::size_t s = 0; s < m_schedule.sources().size(); ++s) {
        const bool rgb = m_schedule.sources()[s].focal_plane->name == "RGB";
        EXPECT_EQ(by_name.source_selected(s), rgb);
        EXPECT_EQ(by_path.source_selected(s), rgb);
        selected += rgb ? 1 : 0;
    }
    EXPECT_EQ(selected, 2u);  // one per BasicPlatform entry
}

TEST_F(SelectionTest, UnknownFocalPlaneListsTheNames) {
    Filters filters;
    filters.focal_plane = "SWIR";
    try {
        const Selection selection(m_schedule, filters);
        FAIL() << "accepted an unknown focal plane";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_NE(e.message().find("\"SWIR\""), std::string::npos) << e.message();
        EXPECT_NE(e.message().find("Cam/NIR, Cam/RGB, Line/Pan"), std::string::npos) << e.message();
    }
}

TEST_F(SelectionTest, TaskOutOfRangeSaysWhichExist) {
    Filters filters;
    filters.task = 2;
    try {
        const Selection selection(m_schedule, filters);
        FAIL() << "accepted task 2";
    } catch (const Error& e) {
        EXPECT_NE(e.message().find("no task 2 (task indices run from 0 to 1)"), std::string::npos)
            << e.message();
    }
}

TEST_F(SelectionTest, AnalyticTotalsEqualEnumeratedTotals) {
    for (const std::optional<std::size_t> task :
         {std::optional<std::size_t>{}, std::optional<std::size_t>{0},
          std::optional<std::size_t>{1}}) {
        for (const char* focal_plane : {"", "RGB", "Line/Pan"}) {
            Filters analytic;
            analytic.task = task;
            if (*focal_plane != '\0') analytic.focal_plane = focal_plane;
            Filters enumerated = analytic;
            enumerated.captures = CaptureRange{0, std::nullopt};
            const SelectionTotals a =
                selection_totals(m_schedule, Selection(m_schedule, analytic), CancelToken{});
            const SelectionTotals b =
                selection_totals(m_schedule, Selection(m_schedule, enumerated), CancelToken{});
            EXPECT_EQ(a.captures, b.captures) << focal_plane;
            EXPECT_EQ(a.problems, b.problems) << focal_plane;
            EXPECT_GT(a.captures, 0u);
        }
    }
    const SelectionTotals all =
        selection_totals(m_schedule, Selection(m_schedule, Filters{}), CancelToken{});
    EXPECT_EQ(all.captures, m_schedule.total_captures());
    EXPECT_EQ(all.problems, m_schedule.total_problems());
}

}  // namespace selection_test
}  // namespace glint::app_schedule
