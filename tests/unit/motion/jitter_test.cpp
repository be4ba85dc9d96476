// SPDX-License-Identifier: Apache-2.0
// Tests of jitter synthesis (lib/motion/src/jitter.cpp): PSD interpolation and integrals;
// uncorrelated jitter's mean, σ and independence; the Welch PSD estimate of long synthesised
// series against the input PSD per decade band (flat, 1/f², peaked); variance against ∫S df;
// determinism by seed and stream ids; the periodic wrap; thread independence; the sampling
// rule and its limit; bad inputs; the platform and mount samplers.
#include "glint/motion/jitter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <functional>
#include <numbers>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "glint/core/error.h"
#include "glint/motion/fft.h"

namespace glint::motion {
namespace jitter_test {

model::PsdTable table(std::vector<double> f, std::vector<double> s, std::vector<double> p = {}) {
    model::PsdTable t;
    t.frequency_hz = std::move(f);
    t.psd = std::move(s);
    t.phase_rad = std::move(p);
    t.where = ErrorContext{"jitter.psd", 3, {}};
    return t;
}

JitterModel psd_model(const model::PsdTable& t, double mean = 0.0) {
    JitterModel m;
    m.kind = JitterModel::Kind::psd;
    m.mean = mean;
    m.psd = &t;
    return m;
}

JitterModel normal_model(double mean, double stddev) {
    JitterModel m;
    m.kind = JitterModel::Kind::normal;
    m.mean = mean;
    m.stddev = stddev;
    return m;
}

// ---- PSD interpolation ----------------------------------------------------------------------

TEST(JitterPsd, LogLogInterpolationIsExactForPowerLaws) {
    const auto t = table({0.01, 10.0}, {100.0, 1e-4});  // S = 1e-2 / f²
    for (double f : {0.01, 0.02, 0.5, 1.0, 3.3, 10.0}) {
        EXPECT_NEAR(psd_at(t, f), 1e-2 / (f * f), 1e-12 * 1e-2 / (f * f)) << f;
    }
    EXPECT_EQ(psd_at(t, 0.005), 0.0);
    EXPECT_EQ(psd_at(t, 10.5), 0.0);
    // ∫ 1e-2/f² df from 0.1 to 1 = 1e-2 · 9.
    EXPECT_NEAR(psd_integral(t, 0.1, 1.0), 0.09, 1e-14);
    EXPECT_NEAR(psd_integral(t, 0.0, 100.0), 1e-2 * (100.0 - 0.1), 1e-12);
}

TEST(JitterPsd, LinearWhereAZeroOrZeroFrequencyIsInvolved) {
    const auto t = table({0.0, 2.0, 4.0, 6.0}, {1.0, 3.0, 0.0, 2.0});
    EXPECT_DOUBLE_EQ(psd_at(t, 1.0), 2.0);  // f = 0 row: linear
    EXPECT_DOUBLE_EQ(psd_at(t, 3.0), 1.5);  // zero PSD at one end: linear
    EXPECT_DOUBLE_EQ(psd_at(t, 5.0), 1.0);
    EXPECT_DOUBLE_EQ(psd_integral(t, 0.0, 6.0), 4.0 + 3.0 + 2.0);
    EXPECT_DOUBLE_EQ(psd_integral(t, 1.0, 3.0), 0.5 * (2.0 + 3.0) + 0.5 * (3.0 + 1.5));
}

TEST(JitterPsd, IntegralMatchesNumericalQuadrature) {
    const auto t = table({0.1, 2.8, 3.0, 3.2, 10.0}, {0.01, 0.01, 1.0, 0.01, 0.01});
    const double a = 0.5;
    const double b = 7.0;
    const int steps = 200000;
    double sum = 0.0;
    for (int i = 0; i < steps; ++i) {  // midpoint rule
        sum += psd_at(t, a + (b - a) * (i + 0.5) / steps);
    }
    sum *= (b - a) / steps;
    EXPECT_NEAR(psd_integral(t, a, b), sum, 1e-6 * sum);
}

TEST(JitterPsd, PhaseInterpolation) {
    const auto t = table({1.0, 3.0}, {1.0, 1.0}, {0.0, 1.0});
    EXPECT_DOUBLE_EQ(psd_phase_at(t, 2.0), 0.5);
    EXPECT_DOUBLE_EQ(psd_phase_at(t, 0.5), 0.0);
    EXPECT_DOUBLE_EQ(psd_phase_at(t, 9.0), 1.0);
    EXPECT_DOUBLE_EQ(psd_phase_at(table({1.0, 3.0}, {1.0, 1.0}), 2.0), 0.0);
}

// ---- uncorrelated (normal) jitter -----------------------------------------------------------

TEST(JitterNormal, MeanAndSigmaOver1e5Samples) {
    // k = 5 standard errors: with a fixed seed the test is deterministic; 5 SE would be
    // exceeded by chance with probability 6e-7 per statistic, so a failure means a bias.
    const double mean = 2e-4;
    const double sigma = 5e-5;
    const JitterSeries s(normal_model(mean, sigma), 42, {7, 1, 0}, 0.0, 100.0);
    const int n = 100000;
    double sum = 0.0;
    double sum2 = 0.0;
    double lag = 0.0;
    double previous = 0.0;
    for (int i = 0; i < n; ++i) {
        const double v = s.value_at(i * 1e-3);
        sum += v;
        sum2 += v * v;
        if (i > 0) lag += (v - mean) * (previous - mean);
        previous = v;
    }
    const double m = sum / n;
    const double sd = std::sqrt(sum2 / n - m * m);
    EXPECT_NEAR(m, mean, 5.0 * sigma / std::sqrt(double(n)));
    EXPECT_NEAR(sd, sigma, 5.0 * sigma / std::sqrt(2.0 * n));  // SE(σ̂) ≈ σ/√(2n)
    // Neighbouring samples are independent: lag-1 correlation within 5/√n of 0.
    EXPECT_NEAR(lag / (n - 1) / (sigma * sigma), 0.0, 5.0 / std::sqrt(double(n)));
    EXPECT_EQ(s.stddev(), sigma);
}

TEST(JitterNormal, KeyedByTheTimeQuantisedTo1Ns) {
    const JitterSeries s(normal_model(0.0, 1.0), 1, {3}, 0.0, 1.0);
    EXPECT_EQ(s.value_at(0.25), s.value_at(0.25));
    EXPECT_EQ(s.value_at(0.25), s.value_at(0.25 + 0.4e-9));  // same nanosecond
    EXPECT_NE(s.value_at(0.25), s.value_at(0.25 + 1e-9));
    EXPECT_NE(s.value_at(-0.25), s.value_at(0.25));
    EXPECT_TRUE(std::isfinite(s.value_at(-3.0e7)));  // negative times are keyed too
    EXPECT_TRUE(std::isnan(s.value_at(NAN)));
    EXPECT_TRUE(std::isnan(s.value_at(INFINITY)));
}

TEST(JitterNormal, SeedsAndIdsSelectTheStream) {
    const JitterSeries a(normal_model(0.0, 1.0), 9, {1, 2, 0}, 0.0, 1.0);
    const JitterSeries same(normal_model(0.0, 1.0), 9, {1, 2, 0}, 0.0, 1.0);
    const JitterSeries seed(normal_model(0.0, 1.0), 10, {1, 2, 0}, 0.0, 1.0);
    const JitterSeries axis(normal_model(0.0, 1.0), 9, {1, 2, 1}, 0.0, 1.0);
    int seed_diff = 0;
    int axis_diff = 0;
    for (int i = 0; i < 100; ++i) {
        const double t = i * 0.01;
        EXPECT_EQ(a.value_at(t), same.value_at(t));
        seed_diff += a.value_at(t) != seed.value_at(t);
        axis_diff += a.value_at(t) != axis.value_at(t);
    }
    EXPECT_EQ(seed_diff, 100);
    EXPECT_EQ(axis_diff, 100);
}

TEST(JitterNormal, ZeroSigmaGivesTheMean) {
    const JitterSeries s(normal_model(0.5, 0.0), 1, {}, 0.0, 1.0);
    EXPECT_EQ(s.value_at(0.123), 0.5);
}

// ---- PSD synthesis: Welch estimate against the input PSD -------------------------------------

/// Welch's one-sided PSD estimate: Hann-windowed segments of `length` samples, 50 % overlap,
/// each segment's mean removed, |FFT|² scaled by 2 / (fs Σw²) (1 at DC and Nyquist), averaged.
std::vector<double> welch(const std::vector<double>& x, double fs_hz, std::size_t length) {
    std::vector<double> window(length);
    double window_power = 0.0;
    for (std::size_t i = 0; i < length; ++i) {
        window[i] = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * double(i) / double(length));
        window_power += window[i] * window[i];
    }
    std::vector<double> psd(length / 2 + 1, 0.0);
    std::vector<double> segment(length);
    std::size_t count = 0;
    for (std::size_t start = 0; start + length <= x.size(); start += length / 2) {
        double mean = 0.0;
        for (std::size_t i = 0; i < length; ++i) mean += x[start + i];
        mean /= double(length);
        for (std::size_t i = 0; i < length; ++i) segment[i] = (x[start + i] - mean) * window[i];
        const auto spectrum = fft_real(segment);
        for (std::size_t k = 0; k <= length / 2; ++k) psd[k] += std::norm(spectrum[k]);
        ++count;
    }
    for (std::size_t k = 0; k <= length / 2; ++k) {
        const double one_sided = (k == 0 || k == length / 2) ? 1.0 : 2.0;
        psd[k] *= one_sided / (fs_hz * window_power * double(count));
    }
    return psd;
}

/// ∫ of a Welch estimate over [a, b]: each bin covers [f_k − Δ/2, f_k + Δ/2], weighted by its
/// overlap with the band.
double band_integral(const std::vector<double>& psd, double fs_hz, std::size_t length, double a,
                     double b) {
    const double df = fs_hz / double(length);
    double total = 0.0;
    for (std::size_t k = 0; k < psd.size(); ++k) {
        const double lo = std::max(a, (double(k) - 0.5) * df);
        const double hi = std::min(b, (double(k) + 0.5) * df);
        if (hi > lo) total += psd[k] * (hi - lo);
    }
    return total;
}

struct WelchCase {
    const char* name;
    model::PsdTable psd;
};

/// Synthesises 2^20 samples of `psd` (highest frequency 10 Hz → fs = 100 Hz over 10^4 s)
/// and checks the Welch estimate per decade band, the variance and the mean.
void check_welch(const WelchCase& c) {
    SCOPED_TRACE(c.name);
    const double mean = 1e-3;
    const JitterSeries s(psd_model(c.psd, mean), 2024, {5, 2, 1}, 0.0, 1e4);
    ASSERT_EQ(s.samples().size(), 1u << 20);
    ASSERT_DOUBLE_EQ(s.sample_rate_hz(), 100.0);
    const double fs = s.sample_rate_hz();

    double sum = 0.0;
    for (double v : s.samples()) sum += v;
    const double sample_mean = sum / double(s.samples().size());
    double var = 0.0;
    for (double v : s.samples()) var += (v - sample_mean) * (v - sample_mean);
    var /= double(s.samples().size());
    EXPECT_NEAR(sample_mean, mean, 1e-9 * std::sqrt(var) + 1e-15);  // DC bin is 0
    // Parseval: the series carries exactly the variance put into its bins.
    EXPECT_NEAR(var, s.synthesized_variance(), 1e-9 * var);
    // ... which is ∫S df of the table within a few %.
    const double integral = psd_integral(c.psd, 0.0, 1e9);
    EXPECT_NEAR(var, integral, 0.02 * integral);
    std::printf("[ variance ] %-10s series/∫S df = %.5f\n", c.name, var / integral);
    EXPECT_DOUBLE_EQ(s.psd_variance(), integral);

    const std::size_t length = 4096;
    const auto estimate = welch(s.samples(), fs, length);
    for (const auto& [a, b] : {std::pair{0.1, 1.0}, std::pair{1.0, 10.0}}) {
        const double expected = psd_integral(c.psd, a, b);
        const double measured = band_integral(estimate, fs, length, a, b);
        EXPECT_NEAR(measured / expected, 1.0, 0.10) << "band " << a << "–" << b << " Hz";
        // The accuracy figure of docs/motion.md ("Jitter").
        std::printf("[ welch    ] %-10s %5.1f–%4.1f Hz: measured/input = %.4f\n", c.name, a, b,
                    measured / expected);
    }
}

TEST(JitterPsdSynthesis, WelchMatchesAFlatPsd) {
    check_welch({"flat", table({0.0, 10.0}, {1e-6, 1e-6})});
}

TEST(JitterPsdSynthesis, WelchMatchesAOneOverFSquaredPsd) {
    check_welch({"1/f^2", table({0.01, 10.0}, {100.0, 1e-4})});
}

TEST(JitterPsdSynthesis, WelchMatchesAPsdWithAPeak) {
    check_welch({"peak", table({0.1, 2.8, 3.0, 3.2, 10.0}, {1e-8, 1e-8, 1e-6, 1e-8, 1e-8})});
}

// ---- PSD synthesis: determinism, phases, wrap, threads ---------------------------------------

TEST(JitterPsdSynthesis, IdenticalSeedsGiveIdenticalSeries) {
    const auto t = table({0.5, 20.0}, {1.0, 0.1});
    const JitterSeries a(psd_model(t), 77, {1, 2, 3}, 0.0, 30.0);
    const JitterSeries b(psd_model(t), 77, {1, 2, 3}, 0.0, 30.0);
    const JitterSeries seed(psd_model(t), 78, {1, 2, 3}, 0.0, 30.0);
    const JitterSeries ids(psd_model(t), 77, {1, 2, 4}, 0.0, 30.0);
    EXPECT_EQ(a.samples(), b.samples());
    EXPECT_NE(a.samples(), seed.samples());
    EXPECT_NE(a.samples(), ids.samples());
    EXPECT_EQ(a.value_at(12.345), b.value_at(12.345));
}

TEST(JitterPsdSynthesis, TablePhasesMakeTheSeriesIndependentOfTheSeed) {
    const auto t = table({0.5, 20.0}, {1.0, 0.1}, {0.0, 3.0});
    const JitterSeries a(psd_model(t), 1, {}, 0.0, 30.0);
    const JitterSeries b(psd_model(t), 2, {}, 0.0, 30.0);
    EXPECT_EQ(a.samples(), b.samples());
    // With zero phases every bin is a cosine peaking at t0: x(t0) = Σ A_k.
    const auto zero = table({0.5, 20.0}, {1.0, 0.1}, {0.0, 0.0});
    const JitterSeries z(psd_model(zero), 1, {}, 0.0, 30.0);
    const double df = z.sample_rate_hz() / double(z.samples().size());
    double sum_amplitude = 0.0;
    for (std::size_t k = 1; k < z.samples().size() / 2; ++k) {
        sum_amplitude += std::sqrt(2.0 * psd_at(zero, double(k) * df) * df);
    }
    EXPECT_NEAR(z.samples()[0], sum_amplitude, 1e-9 * sum_amplitude);
}

TEST(JitterPsdSynthesis, SamplingRuleAndPeriodicWrap) {
    const auto t = table({1.0, 20.0}, {1.0, 1.0});
    const JitterSeries s(psd_model(t, 0.25), 3, {}, 100.0, 160.0);
    EXPECT_DOUBLE_EQ(s.sample_rate_hz(), 200.0);      // 10 × 20 Hz
    EXPECT_EQ(s.samples().size(), 16384u);            // next power of two ≥ 60 s × 200 Hz
    EXPECT_DOUBLE_EQ(s.period_s(), 16384.0 / 200.0);  // ≥ the span
    EXPECT_DOUBLE_EQ(s.t0_s(), 100.0);
    EXPECT_NEAR(s.mean(), 0.25, 0.0);
    // value_at passes through the samples and interpolates linearly between them (to the
    // round-off of t · fs times the slope of the series).
    const double dt = 1.0 / s.sample_rate_hz();
    for (std::size_t n : {0u, 1u, 777u, 16383u}) {
        EXPECT_NEAR(s.value_at(100.0 + double(n) * dt), s.samples()[n], 1e-9) << n;
    }
    EXPECT_NEAR(s.value_at(100.0 + 10.5 * dt), 0.5 * (s.samples()[10] + s.samples()[11]), 1e-9);
    // The series repeats with its period, before t0 and after t0 + period.
    for (double x : {0.0, 3.21, 50.0, 81.9}) {
        EXPECT_NEAR(s.value_at(100.0 + x + s.period_s()), s.value_at(100.0 + x), 1e-9) << x;
        EXPECT_NEAR(s.value_at(100.0 + x - 3.0 * s.period_s()), s.value_at(100.0 + x), 1e-9) << x;
    }
    // Between the last sample and the first one of the next period.
    EXPECT_NEAR(s.value_at(100.0 - 0.5 * dt), 0.5 * (s.samples().back() + s.samples()[0]), 1e-9);
    EXPECT_TRUE(std::isnan(s.value_at(NAN)));
}

TEST(JitterPsdSynthesis, LowestFrequencySetsTheMinimumPeriod) {
    // 0.01 Hz content needs a period ≥ 100 s even for a 1 s span.
    const auto t = table({0.01, 1.0}, {1.0, 1.0});
    const JitterSeries s(psd_model(t), 3, {}, 0.0, 1.0);
    EXPECT_DOUBLE_EQ(s.sample_rate_hz(), 10.0);
    EXPECT_GE(s.period_s(), 100.0);
    EXPECT_NEAR(s.synthesized_variance(), s.psd_variance(), 0.02 * s.psd_variance());
}

TEST(JitterPsdSynthesis, LongSpansLowerTheRateThenFail) {
    const auto t = table({1.0, 10.0}, {1.0, 1.0});
    JitterSynthesisOptions options;
    options.max_samples = 1u << 14;
    // 500 s × 100 Hz = 5e4 > 16384: the rate drops to 16384 / 500 s ≥ 2.5 × 10 Hz.
    const JitterSeries s(psd_model(t), 3, {}, 0.0, 500.0, options);
    EXPECT_EQ(s.samples().size(), 16384u);
    EXPECT_DOUBLE_EQ(s.sample_rate_hz(), 16384.0 / 500.0);
    // 1000 s would need 25 Hz × 1000 s > 16384 samples.
    try {
        const JitterSeries f(psd_model(t), 3, {}, 0.0, 1000.0, options);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_EQ(std::string(e.what()),
                  "jitter.psd:3: jitter PSD up to 10 Hz over 1000 s needs 25000 samples at 2.5 "
                  "samples per period of the highest frequency, more than the 16384 allowed; "
                  "shorten the span or lower the highest PSD frequency");
    }
}

TEST(JitterPsdSynthesis, ValuesFromTwoThreadsEqualTheSingleThreadValues) {
    const auto t = table({0.5, 20.0}, {1.0, 0.1});
    const JitterSeries psd(psd_model(t), 5, {1}, 0.0, 20.0);
    const JitterSeries normal(normal_model(0.0, 1.0), 5, {2}, 0.0, 20.0);
    const int n = 20000;
    auto evaluate = [&](std::vector<double>& out) {
        out.resize(2 * n);
        for (int i = 0; i < n; ++i) {
            const double time = i * 1.37e-3;
            out[2 * i] = psd.value_at(time);
            out[2 * i + 1] = normal.value_at(time);
        }
    };
    std::vector<double> single;
    evaluate(single);
    std::vector<double> first;
    std::vector<double> second;
    std::thread a([&] { evaluate(first); });
    std::thread b([&] { evaluate(second); });
    a.join();
    b.join();
    EXPECT_EQ(first, single);
    EXPECT_EQ(second, single);
}

// ---- bad input -------------------------------------------------------------------------------

std::string error_text(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        return e.what();
    }
    return "no error";
}

TEST(JitterErrors, EveryBadInput) {
    JitterModel m = normal_model(0.0, -1.0);
    m.where = ErrorContext{"a.platform", 7, "rotationdeviates"};
    EXPECT_EQ(error_text([&] { JitterSeries(m, 1, {}, 0.0, 1.0); }),
              "a.platform:7: rotationdeviates: jitter standard deviation -1 is invalid, expected "
              "a finite value >= 0");
    m = normal_model(NAN, 1.0);
    EXPECT_EQ(error_text([&] { JitterSeries(m, 1, {}, 0.0, 1.0); }),
              "jitter mean nan is not a finite number");
    m = JitterModel{};
    m.kind = JitterModel::Kind::psd;
    EXPECT_EQ(error_text([&] { JitterSeries(m, 1, {}, 0.0, 1.0); }), "psd jitter has no PSD table");
    const auto bad = table({1.0, 0.5}, {1.0, 1.0});
    EXPECT_EQ(error_text([&] { JitterSeries(psd_model(bad), 1, {}, 0.0, 1.0); }),
              "jitter.psd:3: PSD row 2: frequency 0.5 Hz is not greater than the previous 1 Hz; "
              "frequencies must be strictly increasing");
    const auto negative = table({1.0, 2.0}, {1.0, -1.0});
    EXPECT_EQ(error_text([&] { JitterSeries(psd_model(negative), 1, {}, 0.0, 1.0); }),
              "jitter.psd:3: PSD row 2: psd -1 is negative");
    const auto good = table({1.0, 2.0}, {1.0, 1.0});
    EXPECT_EQ(error_text([&] { JitterSeries(psd_model(good), 1, {}, 2.0, 1.0); }),
              "jitter time span [2, 1] s is invalid, expected finite t0 <= t1");
}

// ---- model adapters and samplers ------------------------------------------------------------

TEST(JitterSamplers, PlatformAxesUseTheirOwnStreams) {
    model::PlatformJitter j;
    for (auto& a : j.location_m) {
        a.kind = model::JitterSpec::Kind::normal;
        a.stddev = 0.1;
    }
    j.orientation_rad[2].kind = model::JitterSpec::Kind::psd;
    j.orientation_rad[2].mean = 1e-3;
    j.orientation_rad[2].psd = table({0.1, 5.0}, {1e-8, 1e-10});
    const PlatformJitterSampler sampler(j, 11, {4}, 0.0, 10.0);
    EXPECT_TRUE(sampler.any());
    EXPECT_FALSE(PlatformJitterSampler().any());
    const auto s = sampler.at(1.5);
    EXPECT_NE(s.location_m.x, s.location_m.y);
    EXPECT_NE(s.location_m.y, s.location_m.z);
    EXPECT_EQ(s.orientation_rad.x, 0.0);
    EXPECT_EQ(s.orientation_rad.y, 0.0);
    EXPECT_NE(s.orientation_rad.z, 0.0);
    // Axis i of location is the stream (seed, ids + {domain, i}).
    const JitterSeries y(normal_model(0.0, 0.1), 11, {4, kJitterDomainPlatformLocation, 1}, 0.0,
                         10.0);
    EXPECT_EQ(s.location_m.y, y.value_at(1.5));
    EXPECT_EQ(sampler.orientation(2).kind(), JitterSeries::Kind::psd);
}

TEST(JitterSamplers, MountUsesItsPsdTable) {
    model::RotationDeviates d;
    d.axes[0].kind = model::JitterSpec::Kind::normal;
    d.axes[0].stddev = 1e-4;
    d.axes[1].kind = model::JitterSpec::Kind::psd;
    d.axes[1].psd_file.text = "across.psd";
    d.axes[1].psd_file.resolved = "/data/across.psd";
    // The table inputs::load reads from the file the axis names (its first row on line 2,
    // after a comment); the sampler takes the table.
    d.axes[1].psd = table({0.5, 50.0}, {1e-8, 1e-10});
    d.axes[1].psd->where = ErrorContext{"across.psd", 2, {}};
    const MountJitterSampler sampler(d, 3, {9}, 0.0, 2.0);
    EXPECT_TRUE(sampler.any());
    EXPECT_DOUBLE_EQ(sampler.axis(1).sample_rate_hz(), 500.0);
    const Vec3 v = sampler.at(0.7);
    EXPECT_EQ(v.x, sampler.axis(0).value_at(0.7));
    EXPECT_EQ(v.y, sampler.axis(1).value_at(0.7));
    EXPECT_EQ(v.z, 0.0);

    // A table that breaks the rules is refused with its location.
    d.axes[1].psd->frequency_hz = {0.5, 0.1};
    EXPECT_EQ(error_text([&] { MountJitterSampler(d, 3, {9}, 0.0, 2.0); }),
              "across.psd:2: PSD row 2: frequency 0.1 Hz is not greater than the previous 0.5 Hz; "
              "frequencies must be strictly increasing");
    // A file named but never read (the loader was bypassed), and no file at all.
    d.axes[1].psd.reset();
    d.axes[1].where = ErrorContext{"a.platform", 41, "mount[M]/rotationdeviates/yrotation"};
    EXPECT_EQ(error_text([&] { MountJitterSampler(d, 3, {9}, 0.0, 2.0); }),
              "a.platform:41: mount[M]/rotationdeviates/yrotation: psd jitter: the PSD file "
              "across.psd was not read (inputs::load reads the PSD files a platform or motion "
              "names)");
    d.axes[1].psd_file = {};
    EXPECT_EQ(error_text([&] { MountJitterSampler(d, 3, {9}, 0.0, 2.0); }),
              "a.platform:41: mount[M]/rotationdeviates/yrotation: psd jitter names no PSD file");
}

}  // namespace jitter_test
}  // namespace glint::motion
