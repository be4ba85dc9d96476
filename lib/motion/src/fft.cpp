// SPDX-License-Identifier: Apache-2.0
// The radix-2 FFT of glint/motion/fft.h: bit-reversal permutation, then log2(N) butterfly
// stages with twiddles taken from one table of e^(−2πi j/N) computed directly with cos/sin
// (no recurrence, so the error stays near round-off at any size). The real-signal pair packs
// even and odd samples into one complex signal of half the length and splits the result.
#include "glint/motion/fft.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>

#include "glint/core/error.h"

namespace glint::motion {
namespace {

using Complex = std::complex<double>;

void require_power_of_two(std::size_t n, const char* what) {
    if (!is_power_of_two(n)) {
        throw input_error(std::string(what) + " length " + std::to_string(n) +
                          " is not a power of two");
    }
}

/// e^(−2πi j/n) for j = 0 … n/2 − 1 (n ≥ 2). Each quadrant boundary is exact.
std::vector<Complex> twiddle_table(std::size_t n) {
    std::vector<Complex> table(n / 2);
    const double step = 2.0 * std::numbers::pi / static_cast<double>(n);
    for (std::size_t j = 0; j < table.size(); ++j) {
        if (4 * j == n) {
            table[j] = Complex(0.0, -1.0);
        } else {
            const double angle = step * static_cast<double>(j);
            table[j] = Complex(std::cos(angle), -std::sin(angle));
        }
    }
    return table;
}

/// Forward DFT in place of `data` (size m, a power of two) using `table`, the twiddles of a
/// transform of size m · stride (entry j·stride is e^(−2πi j/m)).
void transform(std::span<Complex> data, const std::vector<Complex>& table, std::size_t stride) {
    const std::size_t m = data.size();
    if (m < 2) return;
    // Bit-reversal permutation.
    for (std::size_t i = 1, j = 0; i < m; ++i) {
        std::size_t bit = m >> 1;
        for (; j & bit; bit >>= 1) j ^= bit;
        j ^= bit;
        if (i < j) std::swap(data[i], data[j]);
    }
    // Butterflies: a stage of length `len` combines pairs `half` apart with twiddle
    // e^(−2πi k/len) = table[k · (m/len) · stride].
    for (std::size_t len = 2; len <= m; len <<= 1) {
        const std::size_t half = len >> 1;
        const std::size_t table_step = (m / len) * stride;
        for (std::size_t start = 0; start < m; start += len) {
            for (std::size_t k = 0; k < half; ++k) {
                const Complex w = table[k * table_step];
                const Complex a = data[start + k];
                const Complex b = data[start + k + half] * w;
                data[start + k] = a + b;
                data[start + k + half] = a - b;
            }
        }
    }
}

}  // namespace

std::size_t next_power_of_two(std::size_t n) {
    std::size_t p = 1;
    while (p < n) {
        if (p > std::numeric_limits<std::size_t>::max() / 2) {
            throw input_error("no power of two is at least " + std::to_string(n));
        }
        p <<= 1;
    }
    return p;
}

void fft(std::span<Complex> data) {
    require_power_of_two(data.size(), "FFT");
    if (data.size() < 2) return;
    transform(data, twiddle_table(data.size()), 1);
}

void inverse_fft(std::span<Complex> data) {
    require_power_of_two(data.size(), "inverse FFT");
    if (data.size() < 2) return;
    // inverse(X) = conj(forward(conj(X))) / N
    for (Complex& z : data) z = std::conj(z);
    transform(data, twiddle_table(data.size()), 1);
    const double scale = 1.0 / static_cast<double>(data.size());
    for (Complex& z : data) z = std::conj(z) * scale;
}

std::vector<Complex> fft_real(std::span<const double> signal) {
    const std::size_t n = signal.size();
    if (n < 2) throw input_error("real FFT length " + std::to_string(n) + " is less than 2");
    require_power_of_two(n, "real FFT");
    const std::size_t m = n / 2;
    // z_j = x_2j + i x_2j+1; Z = DFT_m(z).
    std::vector<Complex> z(m);
    for (std::size_t j = 0; j < m; ++j) z[j] = Complex(signal[2 * j], signal[2 * j + 1]);
    const std::vector<Complex> table = twiddle_table(n);
    transform(z, table, 2);
    // E_k = (Z_k + conj Z_(m−k))/2 (DFT of the even samples), O_k = (Z_k − conj Z_(m−k))/2i
    // (of the odd ones); X_k = E_k + e^(−2πi k/n) O_k for k = 0 … m.
    std::vector<Complex> spectrum(m + 1);
    for (std::size_t k = 0; k <= m; ++k) {
        const Complex zk = z[k % m];
        const Complex zc = std::conj(z[(m - k) % m]);
        const Complex even = 0.5 * (zk + zc);
        const Complex odd = Complex(0.0, -0.5) * (zk - zc);
        const Complex w = k < m ? table[k] : Complex(-1.0, 0.0);
        spectrum[k] = even + w * odd;
    }
    return spectrum;
}

std::vector<double> inverse_fft_real(std::span<const Complex> half_spectrum, std::size_t n) {
    if (n < 2)
        throw input_error("real inverse FFT length " + std::to_string(n) + " is less than 2");
    require_power_of_two(n, "real inverse FFT");
    const std::size_t m = n / 2;
    if (half_spectrum.size() != m + 1) {
        throw input_error("real inverse FFT of length " + std::to_string(n) + " needs " +
                          std::to_string(m + 1) + " bins, got " +
                          std::to_string(half_spectrum.size()));
    }
    auto bin = [&](std::size_t k) {
        return (k == 0 || k == m) ? Complex(half_spectrum[k].real(), 0.0) : half_spectrum[k];
    };
    const std::vector<Complex> table = twiddle_table(n);
    // E_k = (X_k + conj X_(m−k))/2, O_k = (X_k − conj X_(m−k)) e^(+2πi k/n)/2 are the DFTs of
    // the even and odd samples; z = IDFT_m(E + i O) holds them as real and imaginary parts.
    std::vector<Complex> z(m);
    for (std::size_t k = 0; k < m; ++k) {
        const Complex xk = bin(k);
        const Complex xc = std::conj(bin(m - k));
        const Complex even = 0.5 * (xk + xc);
        const Complex odd = 0.5 * (xk - xc) * std::conj(table[k]);
        z[k] = even + Complex(0.0, 1.0) * odd;
    }
    // Inverse of size m through the forward transform: conj(DFT(conj Z)) / m.
    for (Complex& v : z) v = std::conj(v);
    transform(z, table, 2);
    const double scale = 1.0 / static_cast<double>(m);
    std::vector<double> signal(n);
    for (std::size_t j = 0; j < m; ++j) {
        signal[2 * j] = z[j].real() * scale;
        signal[2 * j + 1] = -z[j].imag() * scale;
    }
    return signal;
}

}  // namespace glint::motion
