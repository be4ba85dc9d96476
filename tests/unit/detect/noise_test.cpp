// SPDX-License-Identifier: Apache-2.0
// The detector's samplers: Poisson (inversion below a mean of 10, PTRS above) and the
// ziggurat normal, checked by chi-square against their distributions and by their moments.
#include "glint/detect/noise.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <vector>

#include "glint/core/error.h"

namespace glint::detect {
namespace noise_test {

double poisson_pmf(double mean, std::uint64_t k) {
    return std::exp(-mean + static_cast<double>(k) * std::log(mean) -
                    std::lgamma(static_cast<double>(k) + 1.0));
}

/// Chi-square statistic of Poisson draws against the pmf, over bins with expectation >= 20
/// (the tails pooled); returns (statistic, degrees of freedom).
std::pair<double, int> poisson_chi_square(double mean, int n) {
    RandomStream stream(99, {static_cast<std::uint64_t>(mean * 1000)});
    std::map<std::uint64_t, int> counts;
    for (int i = 0; i < n; ++i) ++counts[sample_poisson(stream, mean)];
    // Bins from the pmf: consecutive k until the expectation reaches 20.
    const auto lo = static_cast<std::uint64_t>(std::max(0.0, mean - 8 * std::sqrt(mean) - 10));
    const auto hi = static_cast<std::uint64_t>(mean + 8 * std::sqrt(mean) + 10);
    double chi2 = 0;
    int bins = 0;
    double expected = 0;
    double observed = 0;
    for (std::uint64_t k = 0; k <= hi; ++k) {
        expected += n * poisson_pmf(mean, k);
        observed += counts.count(k) ? counts[k] : 0;
        if (k < lo) continue;
        if (expected >= 20 || k == hi) {
            chi2 += (observed - expected) * (observed - expected) / expected;
            ++bins;
            expected = 0;
            observed = 0;
        }
    }
    return {chi2, bins - 1};
}

TEST(Noise, PoissonMatchesItsDistribution) {
    for (double mean : {0.3, 3.0, 9.99, 10.0, 37.5, 1000.0, 123456.0}) {
        const auto [chi2, dof] = poisson_chi_square(mean, 200000);
        // Mean + 5 standard deviations of a chi-square variable (fails ~1e-6 of the time by
        // chance; the streams are fixed, so the test is deterministic).
        EXPECT_LT(chi2, dof + 5 * std::sqrt(2.0 * dof)) << "mean " << mean << ", dof " << dof;
    }
}

TEST(Noise, PoissonMomentsAtLargeMeans) {
    for (double mean : {1e6, 1e9}) {
        RandomStream stream(5, {1});
        const int n = 100000;
        double sum = 0, sum2 = 0;
        for (int i = 0; i < n; ++i) {
            const double k = static_cast<double>(sample_poisson(stream, mean));
            sum += k;
            sum2 += k * k;
        }
        const double m = sum / n;
        const double var = sum2 / n - m * m;
        EXPECT_NEAR(m, mean, 5 * std::sqrt(mean / n));
        EXPECT_NEAR(var / mean, 1.0, 0.03);
    }
}

TEST(Noise, PoissonEdgeCases) {
    RandomStream stream(1, {2});
    EXPECT_EQ(sample_poisson(stream, 0.0), 0u);
    EXPECT_EQ(stream.position(), 0u) << "mean 0 draws nothing";
    EXPECT_THROW(sample_poisson(stream, -1.0), Error);
    EXPECT_THROW(sample_poisson(stream, std::nan("")), Error);
    EXPECT_THROW(sample_poisson(stream, 2e15), Error);
}

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::numbers::sqrt2); }

TEST(Noise, ZigguratNormalMatchesTheGaussian) {
    RandomStream stream(7, {3});
    const int n = 1000000;
    // 64 equal-probability bins cut at the Gaussian's quantiles, plus tail checks.
    std::vector<double> edges;
    const int bins = 64;
    for (int i = 1; i < bins; ++i) {
        double lo = -10, hi = 10;  // bisection for the i/bins quantile
        for (int it = 0; it < 100; ++it) {
            const double mid = 0.5 * (lo + hi);
            (normal_cdf(mid) < static_cast<double>(i) / bins ? lo : hi) = mid;
        }
        edges.push_back(0.5 * (lo + hi));
    }
    std::vector<int> counts(bins, 0);
    double sum = 0, sum2 = 0, sum4 = 0;
    int beyond_3_5 = 0;
    for (int i = 0; i < n; ++i) {
        const double x = sample_standard_normal(stream);
        sum += x;
        sum2 += x * x;
        sum4 += x * x * x * x;
        if (std::fabs(x) > 3.5) ++beyond_3_5;
        counts[std::upper_bound(edges.begin(), edges.end(), x) - edges.begin()]++;
    }
    const double expected = static_cast<double>(n) / bins;
    double chi2 = 0;
    for (int c : counts) chi2 += (c - expected) * (c - expected) / expected;
    EXPECT_LT(chi2, (bins - 1) + 5 * std::sqrt(2.0 * (bins - 1)));
    EXPECT_NEAR(sum / n, 0.0, 5.0 / std::sqrt(n));
    EXPECT_NEAR(sum2 / n, 1.0, 5.0 * std::sqrt(2.0 / n));
    EXPECT_NEAR(sum4 / n, 3.0, 5.0 * std::sqrt(96.0 / n));
    // The tail beyond the ziggurat's r = 3.44 is sampled: P(|x| > 3.5) = 4.65e-4.
    const double tail = 2 * (1 - normal_cdf(3.5)) * n;
    EXPECT_NEAR(beyond_3_5, tail, 5 * std::sqrt(tail));
}

}  // namespace noise_test
}  // namespace glint::detect
