// SPDX-License-Identifier: Apache-2.0
// A small in-house fast Fourier transform for jitter synthesis (and the Welch estimates of its
// tests): iterative radix-2 Cooley–Tukey on complex doubles, its inverse, and the real-signal
// pair (N real samples ↔ N/2 + 1 non-negative-frequency bins) computed with one complex
// transform of half the length. Sizes must be powers of two. Conventions:
//   forward  X_k = Σ_n x_n e^(−2πi kn/N)
//   inverse  x_n = (1/N) Σ_k X_k e^(+2πi kn/N)
// so inverse(forward(x)) = x and Σ|x_n|² = (1/N) Σ|X_k|² (Parseval).
#pragma once

#include <complex>
#include <cstddef>
#include <span>
#include <vector>

namespace glint::motion {

/// True when `n` is a power of two (1, 2, 4, …).
constexpr bool is_power_of_two(std::size_t n) noexcept { return n != 0 && (n & (n - 1)) == 0; }

/// The smallest power of two ≥ `n` (1 for n = 0). Throws glint::Error (input) when it does
/// not fit in std::size_t.
std::size_t next_power_of_two(std::size_t n);

/// Forward DFT in place. Throws glint::Error (input) unless the size is a power of two.
void fft(std::span<std::complex<double>> data);

/// Inverse DFT in place, including the 1/N factor. Throws glint::Error (input) unless the size
/// is a power of two.
void inverse_fft(std::span<std::complex<double>> data);

/// Bins 0 … N/2 of the forward DFT of a real signal of length N (a power of two ≥ 2); the
/// other bins are their complex conjugates, X_(N−k) = conj(X_k). Throws glint::Error (input)
/// for another length.
std::vector<std::complex<double>> fft_real(std::span<const double> signal);

/// The real signal of length `n` (a power of two ≥ 2) whose DFT has the non-negative-frequency
/// bins `half_spectrum` (n/2 + 1 of them) and the Hermitian extension X_(n−k) = conj(X_k).
/// The imaginary parts of bins 0 and n/2 are ignored (a real signal has none). Throws
/// glint::Error (input) for another length or a spectrum of the wrong size.
std::vector<double> inverse_fft_real(std::span<const std::complex<double>> half_spectrum,
                                     std::size_t n);

}  // namespace glint::motion
