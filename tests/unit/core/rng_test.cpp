// SPDX-License-Identifier: Apache-2.0
// Tests of glint::RandomStream: Philox4x32-10 known answers, stream keying and
// reproducibility, and statistical checks (moments within k standard errors, chi-square
// goodness of fit) of the uniform, normal and Poisson samplers. Every test uses a fixed
// seed, so each is deterministic; the tolerances are chosen so that a correct sampler
// would fail them with a probability far below 1e-4 for a random seed.
#include "glint/core/rng.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "glint/core/error.h"

namespace glint {
namespace rng_test {

// ---- Helpers ---------------------------------------------------------------------------

struct Moments {
    double mean = 0.0;
    double variance = 0.0;  // unbiased
    double skewness = 0.0;
    double kurtosis = 0.0;  // not excess: 3 for a normal
};

Moments moments(const std::vector<double>& x) {
    const double n = static_cast<double>(x.size());
    double sum = 0.0;
    for (double v : x) sum += v;
    Moments m;
    m.mean = sum / n;
    double m2 = 0.0, m3 = 0.0, m4 = 0.0;
    for (double v : x) {
        const double d = v - m.mean;
        m2 += d * d;
        m3 += d * d * d;
        m4 += d * d * d * d;
    }
    m.variance = m2 / (n - 1.0);
    const double pop_var = m2 / n;
    m.skewness = (m3 / n) / std::pow(pop_var, 1.5);
    m.kurtosis = (m4 / n) / (pop_var * pop_var);
    return m;
}

/// Upper critical value of the chi-square distribution with `df` degrees of freedom at the
/// upper-tail probability whose standard normal quantile is `z`, by the Wilson–Hilferty
/// approximation (accurate to a few percent for df >= 3, plenty for a pass/fail bound).
double chi_square_critical(double df, double z) {
    const double a = 2.0 / (9.0 * df);
    return df * std::pow(1.0 - a + z * std::sqrt(a), 3.0);
}

// z = 3.719 is the 1e-4 upper quantile of the standard normal.
constexpr double kZ1e4 = 3.719;

/// Chi-square statistic of observed counts against expected counts.
double chi_square(const std::vector<double>& observed, const std::vector<double>& expected) {
    double chi2 = 0.0;
    for (std::size_t i = 0; i < observed.size(); ++i) {
        const double d = observed[i] - expected[i];
        chi2 += d * d / expected[i];
    }
    return chi2;
}

/// Poisson pmf by recurrence (fine for the means tested here).
std::vector<double> poisson_pmf(double mean, std::size_t count) {
    std::vector<double> pmf;
    double p = std::exp(-mean);
    for (std::size_t k = 0; k < count; ++k) {
        pmf.push_back(p);
        p *= mean / static_cast<double>(k + 1);
    }
    return pmf;
}

// ---- Philox known answers (Random123 kat_vectors, philox4x32_10) ------------------------

TEST(Philox, KnownAnswerZeros) {
    const PhiloxCounter out = philox4x32_10({0, 0, 0, 0}, {0, 0});
    EXPECT_EQ(out, (PhiloxCounter{0x6627e8d5u, 0xe169c58du, 0xbc57ac4cu, 0x9b00dbd8u}));
}

TEST(Philox, KnownAnswerOnes) {
    const PhiloxCounter out = philox4x32_10({0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu},
                                            {0xffffffffu, 0xffffffffu});
    EXPECT_EQ(out, (PhiloxCounter{0x408f276du, 0x41c83b0eu, 0xa20bc7c6u, 0x6d5451fdu}));
}

TEST(Philox, KnownAnswerPi) {
    const PhiloxCounter out = philox4x32_10({0x243f6a88u, 0x85a308d3u, 0x13198a2eu, 0x03707344u},
                                            {0xa4093822u, 0x299f31d0u});
    EXPECT_EQ(out, (PhiloxCounter{0xd16cfe09u, 0x94fdccebu, 0x5001e420u, 0x24126ea1u}));
}

// ---- Keying and reproducibility --------------------------------------------------------

std::vector<std::uint32_t> draw_words(RandomStream stream, int count) {
    std::vector<std::uint32_t> words;
    for (int i = 0; i < count; ++i) words.push_back(stream.next_u32());
    return words;
}

TEST(RandomStream, SameKeySameSequence) {
    RandomStream a(42, {1, 2, 3});
    RandomStream b(42, {1, 2, 3});
    for (int i = 0; i < 1000; ++i) ASSERT_EQ(a.next_u32(), b.next_u32()) << "word " << i;
    for (int i = 0; i < 1000; ++i) ASSERT_EQ(a.normal(), b.normal()) << "normal " << i;
    for (int i = 0; i < 1000; ++i) ASSERT_EQ(a.poisson(37.5), b.poisson(37.5)) << "poisson " << i;
}

TEST(RandomStream, SpanAndInitializerListAgree) {
    const std::vector<std::uint64_t> ids = {7, 8, 9};
    EXPECT_EQ(draw_words(RandomStream(5, ids), 16), draw_words(RandomStream(5, {7, 8, 9}), 16));
}

TEST(RandomStream, DifferentKeysDiffer) {
    const auto base = draw_words(RandomStream(42, {1, 2, 3}), 8);
    EXPECT_NE(base, draw_words(RandomStream(43, {1, 2, 3}), 8));  // seed
    EXPECT_NE(base, draw_words(RandomStream(42, {1, 2, 4}), 8));  // an id
    EXPECT_NE(base, draw_words(RandomStream(42, {3, 2, 1}), 8));  // id order
    EXPECT_NE(base, draw_words(RandomStream(42, {1, 2}), 8));     // id count
    EXPECT_NE(base, draw_words(RandomStream(42, {1, 2, 3, 0}), 8));
    EXPECT_NE(draw_words(RandomStream(0, {}), 8), draw_words(RandomStream(0, {0}), 8));
}

TEST(RandomStream, RegressionFirstWords) {
    // Pins the keying scheme (salts, chain order, counter layout): changing it changes every
    // rendered image, so it must be a deliberate decision. Update these values only then.
    EXPECT_EQ(draw_words(RandomStream(0, {}), 4),
              (std::vector<std::uint32_t>{0x5b93e0d5u, 0x9fea1f86u, 0x59fb8398u, 0xf3876fdfu}));
}

/// A few well-mixed 64-bit values (SplitMix64) for the prefix tests' seeds and ids.
std::uint64_t test_value(std::uint64_t index) {
    std::uint64_t z = index * 0x9E3779B97F4A7C15ull + 0x2545F4914F6CDD1Dull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

TEST(StreamPrefix, SameStreamsAsDirectAtEverySplit) {
    // Random seeds and 0 to 8 ids (including 0 and all-ones), split at every position: the
    // prefix-made stream and one built by extending the prefix id by id give the same first
    // 64 words as RandomStream(seed, ids).
    std::uint64_t next = 0;
    for (int trial = 0; trial < 40; ++trial) {
        const std::uint64_t seed = trial == 0 ? 0 : test_value(next++);
        for (std::size_t count = 0; count <= 8; ++count) {
            std::vector<std::uint64_t> ids;
            for (std::size_t i = 0; i < count; ++i) {
                const std::uint64_t v = test_value(next++);
                ids.push_back(trial == 1 ? ~std::uint64_t{0} : trial == 2 ? i : v);
            }
            const auto direct = draw_words(RandomStream(seed, ids), 64);
            const std::span<const std::uint64_t> all(ids);
            for (std::size_t split = 0; split <= count; ++split) {
                const StreamPrefix prefix(seed, all.first(split));
                EXPECT_EQ(prefix.id_count(), split);
                ASSERT_EQ(draw_words(prefix.stream(all.subspan(split)), 64), direct)
                    << "seed " << seed << ", " << count << " ids split at " << split;
                StreamPrefix grown(seed, all.first(split));
                for (std::size_t i = split; i < count; ++i) grown = grown.extended(ids[i]);
                EXPECT_EQ(grown.id_count(), count);
                ASSERT_EQ(draw_words(grown.stream({}), 64), direct)
                    << "seed " << seed << ", " << count << " ids extended from " << split;
            }
        }
    }
}

TEST(StreamPrefix, InitializerListOverloadsMatchDirect) {
    const StreamPrefix batch(42, {1, 2, 3});
    EXPECT_EQ(draw_words(batch.stream({4, 5}), 64),
              draw_words(RandomStream(42, {1, 2, 3, 4, 5}), 64));
    EXPECT_EQ(draw_words(batch.stream({4, 5, 6}), 64),
              draw_words(RandomStream(42, {1, 2, 3, 4, 5, 6}), 64));
    EXPECT_EQ(draw_words(batch.stream({}), 64), draw_words(RandomStream(42, {1, 2, 3}), 64));
    EXPECT_EQ(draw_words(StreamPrefix(0, {}).stream({}), 4), draw_words(RandomStream(0, {}), 4));
}

TEST(StreamPrefix, FinalMixTakesTheTotalIdCount) {
    // A prefix of 2 ids plus 1 more is the 3-id stream, not the 2-id one: the final mix takes
    // the total count, not the count of either part.
    const StreamPrefix two(7, {10, 20});
    const auto three_ids = draw_words(two.stream({30}), 16);
    EXPECT_EQ(three_ids, draw_words(RandomStream(7, {10, 20, 30}), 16));
    EXPECT_NE(three_ids, draw_words(RandomStream(7, {10, 20}), 16));
    EXPECT_NE(draw_words(two.stream({}), 16), draw_words(StreamPrefix(7, {10}).stream({}), 16));
    // A trailing 0 id still counts: {10, 20} and {10, 20, 0} differ.
    EXPECT_NE(draw_words(two.stream({}), 16), draw_words(two.stream({0}), 16));
    EXPECT_NE(draw_words(two.stream({}), 16), draw_words(two.extended(0).stream({}), 16));
}

TEST(StreamPrefix, SharedPrefixGivesDistinctStreams) {
    // One prefix, many streams: each keyed by its own rest, the prefix itself unchanged.
    const StreamPrefix batch(2024, {3, 1, 4});
    const auto first = draw_words(batch.stream({0, 0}), 8);
    EXPECT_NE(first, draw_words(batch.stream({0, 1}), 8));
    EXPECT_NE(first, draw_words(batch.stream({1, 0}), 8));
    EXPECT_EQ(first, draw_words(batch.stream({0, 0}), 8));
    EXPECT_EQ(batch.id_count(), 3u);
}

TEST(RandomStream, NextU64CombinesTwoWordsLowFirst) {
    RandomStream a(9, {1});
    RandomStream b(9, {1});
    const std::uint64_t low = b.next_u32();
    const std::uint64_t high = b.next_u32();
    EXPECT_EQ(a.next_u64(), (high << 32) | low);
}

TEST(RandomStream, SkipToMatchesDrawing) {
    RandomStream drawn(11, {4, 5});
    std::vector<std::uint32_t> words;
    for (int i = 0; i < 40; ++i) words.push_back(drawn.next_u32());
    EXPECT_EQ(drawn.position(), 40u);
    for (std::uint64_t start : {0u, 1u, 3u, 4u, 5u, 17u, 36u}) {
        RandomStream skipped(11, {4, 5});
        skipped.next_u32();
        skipped.skip_to(start);
        EXPECT_EQ(skipped.position(), start);
        for (std::uint64_t i = start; i < 40; ++i) ASSERT_EQ(skipped.next_u32(), words[i]);
    }
}

TEST(RandomStream, IndependentStreamsAreUncorrelated) {
    // Adjacent pixel streams: correlation of 1e5 paired uniforms is within 5 standard
    // errors (1/sqrt(n)) of zero.
    RandomStream a(1, {0, 0, 100});
    RandomStream b(1, {0, 0, 101});
    const int n = 100000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) sum += (a.uniform() - 0.5) * (b.uniform() - 0.5);
    const double correlation = (sum / n) * 12.0;
    EXPECT_LT(std::fabs(correlation), 5.0 / std::sqrt(n));
}

// ---- Uniform ---------------------------------------------------------------------------

TEST(RandomStream, UniformRangeAndMoments) {
    RandomStream stream(2024, {1});
    const int n = 200000;
    std::vector<double> x(n);
    for (double& v : x) {
        v = stream.uniform();
        ASSERT_GE(v, 0.0);
        ASSERT_LT(v, 1.0);
    }
    const Moments m = moments(x);
    // Standard errors: mean sqrt(1/12 / n); variance sqrt((mu4 - sigma^4) / n) with
    // mu4 = 1/80 and sigma^4 = 1/144. Five standard errors: a false failure has p < 1e-6.
    EXPECT_NEAR(m.mean, 0.5, 5.0 * std::sqrt(1.0 / 12.0 / n));
    EXPECT_NEAR(m.variance, 1.0 / 12.0, 5.0 * std::sqrt((1.0 / 80.0 - 1.0 / 144.0) / n));
}

TEST(RandomStream, UniformOpenExcludesEnds) {
    RandomStream stream(3, {});
    for (int i = 0; i < 100000; ++i) {
        const double v = stream.uniform_open();
        ASSERT_GT(v, 0.0);
        ASSERT_LT(v, 1.0);
    }
}

TEST(RandomStream, UniformRange) {
    RandomStream stream(4, {});
    for (int i = 0; i < 10000; ++i) {
        const double v = stream.uniform(-3.0, 5.0);
        ASSERT_GE(v, -3.0);
        ASSERT_LT(v, 5.0);
    }
    EXPECT_EQ(stream.uniform(2.0, 2.0), 2.0);
    EXPECT_THROW(stream.uniform(1.0, 0.0), Error);
    EXPECT_THROW(stream.uniform(0.0, INFINITY), Error);
    EXPECT_THROW(stream.uniform(NAN, 1.0), Error);
}

TEST(RandomStream, UniformChiSquare20Bins) {
    RandomStream stream(77, {20});
    const int n = 200000;
    const int bins = 20;
    std::vector<double> observed(bins, 0.0);
    for (int i = 0; i < n; ++i) observed[static_cast<int>(stream.uniform() * bins)] += 1.0;
    const std::vector<double> expected(bins, static_cast<double>(n) / bins);
    EXPECT_LT(chi_square(observed, expected), chi_square_critical(bins - 1, kZ1e4));
}

// ---- Normal ----------------------------------------------------------------------------

TEST(RandomStream, NormalMoments) {
    RandomStream stream(31337, {2});
    const int n = 400000;
    std::vector<double> x(n);
    for (double& v : x) v = stream.normal();
    const Moments m = moments(x);
    // Standard errors for a normal sample: mean 1/sqrt(n), variance sqrt(2/n), skewness
    // sqrt(6/n), kurtosis sqrt(24/n); tolerance 5 of them (p < 1e-6 per check).
    const double rn = std::sqrt(static_cast<double>(n));
    EXPECT_NEAR(m.mean, 0.0, 5.0 / rn);
    EXPECT_NEAR(m.variance, 1.0, 5.0 * std::sqrt(2.0) / rn);
    EXPECT_NEAR(m.skewness, 0.0, 5.0 * std::sqrt(6.0) / rn);
    EXPECT_NEAR(m.kurtosis, 3.0, 5.0 * std::sqrt(24.0) / rn);
}

TEST(RandomStream, NormalChiSquareAgainstCdf) {
    // 20 equiprobable bins of the standard normal, found by inverting erfc numerically.
    RandomStream stream(5, {3});
    const int bins = 20;
    std::vector<double> edges;  // interior edges
    for (int i = 1; i < bins; ++i) {
        const double p = static_cast<double>(i) / bins;
        double lo = -10.0, hi = 10.0;
        for (int it = 0; it < 200; ++it) {
            const double mid = 0.5 * (lo + hi);
            (0.5 * std::erfc(-mid / std::sqrt(2.0)) < p ? lo : hi) = mid;
        }
        edges.push_back(0.5 * (lo + hi));
    }
    const int n = 200000;
    std::vector<double> observed(bins, 0.0);
    for (int i = 0; i < n; ++i) {
        const double v = stream.normal();
        int bin = 0;
        while (bin < bins - 1 && v >= edges[bin]) ++bin;
        observed[bin] += 1.0;
    }
    const std::vector<double> expected(bins, static_cast<double>(n) / bins);
    EXPECT_LT(chi_square(observed, expected), chi_square_critical(bins - 1, kZ1e4));
}

TEST(RandomStream, NormalMeanSigma) {
    RandomStream stream(6, {});
    const int n = 100000;
    std::vector<double> x(n);
    for (double& v : x) v = stream.normal(10.0, 2.0);
    const Moments m = moments(x);
    EXPECT_NEAR(m.mean, 10.0, 5.0 * 2.0 / std::sqrt(n));
    EXPECT_NEAR(m.variance, 4.0, 5.0 * 4.0 * std::sqrt(2.0 / n));
    EXPECT_EQ(stream.normal(3.0, 0.0), 3.0);
    EXPECT_THROW(stream.normal(0.0, -1.0), Error);
    EXPECT_THROW(stream.normal(NAN, 1.0), Error);
}

// ---- Poisson ---------------------------------------------------------------------------

TEST(RandomStream, PoissonZeroMeanIsZero) {
    RandomStream stream(8, {});
    for (int i = 0; i < 100; ++i) EXPECT_EQ(stream.poisson(0.0), 0u);
    EXPECT_EQ(stream.position(), 0u);  // no draws consumed
}

TEST(RandomStream, PoissonRejectsBadMeans) {
    RandomStream stream(8, {});
    EXPECT_THROW(stream.poisson(-1.0), Error);
    EXPECT_THROW(stream.poisson(NAN), Error);
    EXPECT_THROW(stream.poisson(INFINITY), Error);
    EXPECT_THROW(stream.poisson(1e16), Error);
    try {
        stream.poisson(-2.5);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_NE(std::string(e.what()).find("Poisson mean"), std::string::npos) << e.what();
    }
}

class PoissonMoments : public ::testing::TestWithParam<double> {};

TEST_P(PoissonMoments, MeanAndVarianceWithinFiveStandardErrors) {
    const double mean = GetParam();
    RandomStream stream(99, {static_cast<std::uint64_t>(mean * 10.0)});
    const int n = 200000;
    std::vector<double> x(n);
    for (double& v : x) v = static_cast<double>(stream.poisson(mean));
    const Moments m = moments(x);
    // For Poisson(λ): Var = λ, so SE(mean) = sqrt(λ/n); the fourth central moment is
    // λ(1 + 3λ), so SE(sample variance) = sqrt((μ4 − σ⁴)/n) = sqrt((λ + 2λ²)/n). Five
    // standard errors keep the false-failure rate below 1e-6 per check while still catching
    // a bias of ~1% at λ = 30 (PTRS's fixed constants would show up here).
    EXPECT_NEAR(m.mean, mean, 5.0 * std::sqrt(mean / n));
    EXPECT_NEAR(m.variance, mean, 5.0 * std::sqrt((mean + 2.0 * mean * mean) / n));
}

INSTANTIATE_TEST_SUITE_P(Means, PoissonMoments,
                         ::testing::Values(0.5, 3.0, 9.99, 10.0, 30.0, 1000.0, 1e9));

TEST(RandomStream, PoissonHugeMeanCompletes) {
    // PTRS is O(1) per draw: 1000 draws at mean 1e9 finish at once (no timing asserted).
    RandomStream stream(12, {});
    double sum = 0.0;
    for (int i = 0; i < 1000; ++i) sum += static_cast<double>(stream.poisson(1e9));
    // SE of the mean of 1000 draws: sqrt(1e9 / 1000) = 1000.
    EXPECT_NEAR(sum / 1000.0, 1e9, 5.0 * 1000.0);
}

/// Chi-square of Poisson(mean) draws against the pmf, with tail bins pooled so every bin
/// expects at least 5 counts.
void expect_poisson_fits(double mean, std::uint64_t seed) {
    RandomStream stream(seed, {});
    const int n = 200000;
    const std::size_t max_k = static_cast<std::size_t>(mean + 20.0 * std::sqrt(mean) + 20.0);
    std::vector<double> counts(max_k + 1, 0.0);
    for (int i = 0; i < n; ++i) {
        const std::uint64_t k = stream.poisson(mean);
        counts[std::min<std::size_t>(k, max_k)] += 1.0;
    }
    const std::vector<double> pmf = poisson_pmf(mean, max_k + 1);
    // Pool into bins with expectation >= 5: lower tail, body, upper tail (rest of the mass).
    std::vector<double> observed, expected;
    double obs_acc = 0.0, exp_acc = 0.0, exp_total = 0.0;
    for (std::size_t k = 0; k <= max_k; ++k) {
        obs_acc += counts[k];
        exp_acc += pmf[k] * n;
        exp_total += pmf[k] * n;
        if (exp_acc >= 5.0 && (n - exp_total) >= 5.0) {
            observed.push_back(obs_acc);
            expected.push_back(exp_acc);
            obs_acc = exp_acc = 0.0;
        }
    }
    // The remainder (upper tail) gets all mass not yet assigned.
    observed.push_back(obs_acc);
    expected.push_back(n - (exp_total - exp_acc));
    ASSERT_GE(observed.size(), 3u);
    const double df = static_cast<double>(observed.size() - 1);
    EXPECT_LT(chi_square(observed, expected), chi_square_critical(df, kZ1e4))
        << "mean " << mean << ", " << observed.size() << " bins";
}

TEST(RandomStream, PoissonChiSquareSmallMean) { expect_poisson_fits(0.5, 1001); }
TEST(RandomStream, PoissonChiSquareInversionLimit) { expect_poisson_fits(9.5, 1002); }
TEST(RandomStream, PoissonChiSquareMediumMean) { expect_poisson_fits(30.0, 1003); }
TEST(RandomStream, PoissonChiSquareJustAboveLimit) { expect_poisson_fits(10.0, 1004); }

TEST(RandomStream, BlocksAtMatchSkipToAndDraw) {
    const RandomStream stream(42, {7, 8, 9});
    std::vector<std::uint64_t> positions;
    for (std::uint64_t i = 0; i < 37; ++i) positions.push_back((i * 0x9E3779B97F4Aull) << 2);
    positions.push_back(0);
    positions.push_back(std::uint64_t{1} << 40);
    std::vector<PhiloxCounter> blocks(positions.size());
    stream.blocks_at(positions, blocks);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        RandomStream copy = stream;
        copy.skip_to(positions[i]);
        for (int w = 0; w < 4; ++w) ASSERT_EQ(blocks[i][w], copy.next_u32()) << i << " " << w;
    }
    EXPECT_EQ(stream.position(), 0u);
    std::vector<PhiloxCounter> one(1);
    EXPECT_THROW(stream.blocks_at(std::vector<std::uint64_t>{6}, one), Error);
    EXPECT_THROW(stream.blocks_at(std::vector<std::uint64_t>{4, 8}, one), Error);
}

}  // namespace rng_test
}  // namespace glint
