// SPDX-License-Identifier: Apache-2.0
// Tests of the in-house FFT (lib/motion/src/fft.cpp): forward transforms against a naive DFT
// in long double, round trips, the real-signal pair against the complex transform, Parseval,
// and the size checks.
#include "glint/motion/fft.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <vector>

#include "glint/core/error.h"
#include "glint/core/rng.h"

namespace glint::motion {
namespace fft_test {

using Complex = std::complex<double>;

std::vector<Complex> random_signal(std::size_t n, std::uint64_t seed) {
    RandomStream rng(seed, {n});
    std::vector<Complex> x(n);
    for (Complex& v : x) v = Complex(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
    return x;
}

/// X_k = Σ x_n e^(−2πi kn/N) in long double, with the angle reduced exactly (kn mod N).
std::vector<Complex> naive_dft(const std::vector<Complex>& x) {
    const std::size_t n = x.size();
    std::vector<long double> c(n);
    std::vector<long double> s(n);
    for (std::size_t j = 0; j < n; ++j) {
        const long double angle = -2.0L * std::numbers::pi_v<long double> *
                                  static_cast<long double>(j) / static_cast<long double>(n);
        c[j] = std::cos(angle);
        s[j] = std::sin(angle);
    }
    std::vector<Complex> out(n);
    for (std::size_t k = 0; k < n; ++k) {
        long double re = 0.0L;
        long double im = 0.0L;
        for (std::size_t j = 0; j < n; ++j) {
            const std::size_t r = (k * j) % n;
            re += x[j].real() * c[r] - x[j].imag() * s[r];
            im += x[j].real() * s[r] + x[j].imag() * c[r];
        }
        out[k] = Complex(static_cast<double>(re), static_cast<double>(im));
    }
    return out;
}

double max_abs_diff(const std::vector<Complex>& a, const std::vector<Complex>& b) {
    double worst = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
    return worst;
}

TEST(Fft, PowerOfTwoHelpers) {
    EXPECT_TRUE(is_power_of_two(1));
    EXPECT_TRUE(is_power_of_two(4096));
    EXPECT_FALSE(is_power_of_two(0));
    EXPECT_FALSE(is_power_of_two(12));
    EXPECT_EQ(next_power_of_two(0), 1u);
    EXPECT_EQ(next_power_of_two(1), 1u);
    EXPECT_EQ(next_power_of_two(5), 8u);
    EXPECT_EQ(next_power_of_two(1024), 1024u);
    EXPECT_EQ(next_power_of_two(1025), 2048u);
}

TEST(Fft, MatchesNaiveDftForEverySizeUpTo1024) {
    for (std::size_t n = 1; n <= 1024; n *= 2) {
        const auto x = random_signal(n, 1);
        auto fast = x;
        fft(fast);
        // Round-off of a radix-2 FFT grows like log2(N); the values are O(√N).
        const double error = max_abs_diff(fast, naive_dft(x));
        EXPECT_LT(error, 1e-13 * std::sqrt(double(n)) * 11) << n;
        if (n == 1024) std::printf("[ fft      ] N = 1024: max |FFT − DFT| = %.2e\n", error);
    }
}

TEST(Fft, KnownTransforms) {
    // An impulse transforms to ones; a single cosine to two bins of N/2.
    std::vector<Complex> impulse(8);
    impulse[0] = 1.0;
    fft(impulse);
    for (const Complex& v : impulse) EXPECT_EQ(v, Complex(1.0, 0.0));
    const std::size_t n = 64;
    std::vector<Complex> cosine(n);
    for (std::size_t j = 0; j < n; ++j) {
        cosine[j] = std::cos(2.0 * std::numbers::pi * 5.0 * double(j) / double(n));
    }
    fft(cosine);
    for (std::size_t k = 0; k < n; ++k) {
        const double expected = (k == 5 || k == n - 5) ? n / 2.0 : 0.0;
        EXPECT_NEAR(cosine[k].real(), expected, 1e-12) << k;
        EXPECT_NEAR(cosine[k].imag(), 0.0, 1e-12) << k;
    }
}

TEST(Fft, RoundTripAndParseval) {
    for (std::size_t n : {2u, 16u, 4096u, 1u << 16}) {
        const auto x = random_signal(n, 2);
        auto y = x;
        fft(y);
        double energy_time = 0.0;
        double energy_freq = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            energy_time += std::norm(x[i]);
            energy_freq += std::norm(y[i]);
        }
        EXPECT_NEAR(energy_freq / double(n), energy_time, 1e-12 * energy_time) << n;
        inverse_fft(y);
        EXPECT_LT(max_abs_diff(x, y), 1e-14 * std::log2(double(n) + 1) * 4) << n;
    }
}

TEST(Fft, RealPairMatchesTheComplexTransform) {
    for (std::size_t n = 2; n <= 8192; n *= 2) {
        const auto c = random_signal(n, 3);
        std::vector<double> x(n);
        std::vector<Complex> xc(n);
        for (std::size_t i = 0; i < n; ++i) {
            x[i] = c[i].real();
            xc[i] = x[i];
        }
        fft(xc);
        const auto half = fft_real(x);
        ASSERT_EQ(half.size(), n / 2 + 1);
        for (std::size_t k = 0; k <= n / 2; ++k) {
            EXPECT_LT(std::abs(half[k] - xc[k]), 1e-12 * std::sqrt(double(n))) << n << " " << k;
        }
        const auto back = inverse_fft_real(half, n);
        ASSERT_EQ(back.size(), n);
        for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(back[i], x[i], 1e-13) << n << " " << i;
    }
}

TEST(Fft, RealInverseIsTheHermitianExtension) {
    // Random half spectrum; the complex inverse of its Hermitian extension must be real and
    // equal to inverse_fft_real. The imaginary parts of bins 0 and N/2 are ignored.
    const std::size_t n = 256;
    const auto r = random_signal(n / 2 + 1, 4);
    std::vector<Complex> full(n);
    for (std::size_t k = 0; k <= n / 2; ++k) {
        const Complex v = (k == 0 || k == n / 2) ? Complex(r[k].real(), 0.0) : r[k];
        full[k] = v;
        if (k != 0 && k != n / 2) full[n - k] = std::conj(v);
    }
    inverse_fft(full);
    const auto real = inverse_fft_real(r, n);
    for (std::size_t i = 0; i < n; ++i) {
        EXPECT_NEAR(full[i].imag(), 0.0, 1e-15);
        EXPECT_NEAR(real[i], full[i].real(), 1e-15);
    }
}

TEST(Fft, BadSizesAreInputErrors) {
    std::vector<Complex> twelve(12);
    EXPECT_THROW(fft(twelve), Error);
    EXPECT_THROW(inverse_fft(twelve), Error);
    try {
        fft(twelve);
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_EQ(e.message(), "FFT length 12 is not a power of two");
    }
    std::vector<double> one(1);
    EXPECT_THROW(fft_real(one), Error);
    std::vector<double> six(6);
    EXPECT_THROW(fft_real(six), Error);
    std::vector<Complex> bins(5);
    EXPECT_THROW(inverse_fft_real(bins, 16), Error);  // 16 needs 9 bins
    EXPECT_NO_THROW(inverse_fft_real(bins, 8));
    std::vector<Complex> empty;
    EXPECT_THROW(fft(empty), Error);  // 0 is not a power of two
}

}  // namespace fft_test
}  // namespace glint::motion
