// SPDX-License-Identifier: Apache-2.0
// Tests of the percentile limits (exact order statistics for integer data, within a bin
// width otherwise) and of the value mapping with gamma.
#include "glint/io/stretch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "glint/core/error.h"

namespace glint::io {
namespace stretch_test {

PercentileHistogram histogram_of(const std::vector<double>& values) {
    PercentileHistogram h;
    for (double v : values) h.observe(v);
    h.begin_counting();
    for (double v : values) h.count(v);
    return h;
}

TEST(PercentileHistogram, IntegerDataGiveExactOrderStatistics) {
    std::vector<double> values;
    for (int i = 100; i >= 1; --i) values.push_back(i);  // order does not matter
    const PercentileHistogram h = histogram_of(values);
    EXPECT_EQ(h.finite_count(), 100u);
    // n = 100, q = 0.02: k = floor(0.02 * 99) = 1 → x_1 = 2; m = ceil(0.98 * 99) = 98 → 99.
    const StretchLimits two = h.limits(2.0);
    EXPECT_EQ(two.low, 2.0);
    EXPECT_EQ(two.high, 99.0);
    const StretchLimits none = h.limits(0.0);
    EXPECT_EQ(none.low, 1.0);
    EXPECT_EQ(none.high, 100.0);
    // q = 0.1: k = floor(9.9) = 9 → 10; m = ceil(89.1) = 90 → 91.
    const StretchLimits ten = h.limits(10.0);
    EXPECT_EQ(ten.low, 10.0);
    EXPECT_EQ(ten.high, 91.0);
    for (std::uint64_t k = 0; k < 100; ++k) EXPECT_EQ(h.value_at_rank(k), double(k + 1));
}

TEST(PercentileHistogram, RepeatedValuesAndNonFiniteValues) {
    std::vector<double> values(1000, 5.0);
    values[0] = 0.0;
    values[1] = 10.0;
    values.push_back(std::nan(""));
    values.push_back(INFINITY);
    values.push_back(-INFINITY);
    const PercentileHistogram h = histogram_of(values);
    EXPECT_EQ(h.finite_count(), 1000u);
    EXPECT_EQ(h.limits(1.0).low, 5.0);
    EXPECT_EQ(h.limits(1.0).high, 5.0);
    EXPECT_EQ(h.limits(0.0).low, 0.0);
    EXPECT_EQ(h.limits(0.0).high, 10.0);
}

TEST(PercentileHistogram, ContinuousDataWithinOneBinOfExact) {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> normal(100.0, 15.0);
    std::vector<double> values(200000);
    for (double& v : values) v = normal(rng);
    const PercentileHistogram h = histogram_of(values);
    std::vector<double> sorted = values;
    std::sort(sorted.begin(), sorted.end());
    const double bin = (sorted.back() - sorted.front()) / PercentileHistogram::kBins;
    for (double percent : {0.5, 2.0, 5.0, 25.0}) {
        const double last = static_cast<double>(values.size() - 1);
        const auto k = static_cast<std::size_t>(std::floor(percent / 100 * last));
        const auto m = static_cast<std::size_t>(std::ceil((1 - percent / 100) * last));
        const StretchLimits limits = h.limits(percent);
        EXPECT_NEAR(limits.low, sorted[k], bin) << percent;
        EXPECT_NEAR(limits.high, sorted[m], bin) << percent;
    }
}

TEST(PercentileHistogram, EmptyAndSingle) {
    PercentileHistogram empty;
    empty.begin_counting();
    EXPECT_EQ(empty.finite_count(), 0u);
    EXPECT_EQ(empty.limits(2.0).low, 0.0);
    EXPECT_EQ(empty.limits(2.0).high, 1.0);
    const PercentileHistogram one = histogram_of({3.5});
    EXPECT_EQ(one.limits(2.0).low, 3.5);
    EXPECT_EQ(one.limits(2.0).high, 3.5);
}

TEST(StretchValue, LinearClampGammaFlatNan) {
    const StretchLimits limits{10.0, 20.0};
    EXPECT_DOUBLE_EQ(stretch_value(15.0, limits, 1.0), 0.5);
    EXPECT_DOUBLE_EQ(stretch_value(5.0, limits, 1.0), 0.0);
    EXPECT_DOUBLE_EQ(stretch_value(25.0, limits, 1.0), 1.0);
    EXPECT_DOUBLE_EQ(stretch_value(INFINITY, limits, 1.0), 1.0);
    EXPECT_DOUBLE_EQ(stretch_value(12.5, limits, 2.0), 0.5);  // 0.25^(1/2)
    EXPECT_DOUBLE_EQ(stretch_value(15.0, limits, 2.2), std::pow(0.5, 1 / 2.2));
    EXPECT_DOUBLE_EQ(stretch_value(15.0, StretchLimits{3.0, 3.0}, 1.0), 0.0);
    EXPECT_TRUE(std::isnan(stretch_value(std::nan(""), limits, 1.0)));
}

/// The message of the usage error `request` raises; "" when it passes.
std::string request_error(const StretchRequest& request) {
    try {
        check_stretch_request(request);
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::usage);
        return e.message();
    }
    return "";
}

TEST(StretchRequest, ChecksEveryValueWithTheOptionName) {
    EXPECT_EQ(request_error({}), "");
    EXPECT_EQ(request_error({2.2, 1.0, std::nullopt, std::nullopt}), "");
    EXPECT_EQ(request_error({std::nullopt, std::nullopt, -1.0, 4.0}), "");
    EXPECT_EQ(request_error({0.0, std::nullopt, std::nullopt, std::nullopt}),
              "--gamma must be a positive number, got 0");
    EXPECT_EQ(request_error({INFINITY, std::nullopt, std::nullopt, std::nullopt}),
              "--gamma must be a positive number, got inf");
    EXPECT_EQ(request_error({std::nullopt, 50.0, std::nullopt, std::nullopt}),
              "--percent must be in [0, 50), got 50");
    EXPECT_EQ(request_error({std::nullopt, -0.5, std::nullopt, std::nullopt}),
              "--percent must be in [0, 50), got -0.5");
    EXPECT_EQ(request_error({std::nullopt, std::nullopt, 1.0, std::nullopt}),
              "--min and --max go together");
    EXPECT_EQ(request_error({std::nullopt, std::nullopt, std::nullopt, 1.0}),
              "--min and --max go together");
    EXPECT_EQ(request_error({std::nullopt, std::nullopt, 3.0, 3.0}),
              "--min must be less than --max (got 3 and 3)");
    EXPECT_EQ(request_error({std::nullopt, 2.0, 0.0, 1.0}),
              "give --percent or --min/--max, not both");
}

}  // namespace stretch_test
}  // namespace glint::io
