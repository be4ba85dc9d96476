// SPDX-License-Identifier: Apache-2.0
// The Poisson (inversion / PTRS) and ziggurat normal samplers of noise.h.
#include "glint/detect/noise.h"

#include <cmath>
#include <numbers>
#include <string>

#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::detect {
namespace {

using namespace detail;

/// log(k!) for k >= 0: exact products for small k, Stirling's series above (error < 1e-15
/// relative for k >= 30); std::lgamma is avoided because it writes the global signgam.
double log_factorial(double k) noexcept {
    if (k < 30.0) {
        double product = 1.0;
        for (double i = 2.0; i <= k; i += 1.0) product *= i;
        return std::log(product);
    }
    const double n = k + 1.0;
    const double inv = 1.0 / n;
    const double inv2 = inv * inv;
    return (n - 0.5) * std::log(n) - n + 0.5 * std::log(2.0 * std::numbers::pi) +
           inv * (1.0 / 12.0 - inv2 * (1.0 / 360.0 - inv2 * (1.0 / 1260.0 - inv2 / 1680.0)));
}

double uniform53(RandomStream& stream) {
    return static_cast<double>(stream.next_u64() >> 11) * kTwoPow53Inv;
}

double uniform53_open(RandomStream& stream) {
    return (static_cast<double>(stream.next_u64() >> 11) + 0.5) * kTwoPow53Inv;
}

/// The 128-layer ziggurat of f(x) = exp(-x²/2) (unnormalized): r is the start of the tail,
/// v the area of each layer (Marsaglia & Tsang 2000).
ZigguratTable make_ziggurat() {
    ZigguratTable t{};
    constexpr int n = ZigguratTable::kLayers;
    const double f_r = std::exp(-0.5 * t.kR * t.kR);
    t.x[0] = t.kV / f_r;  // the base strip: a rectangle of area v plus the tail
    t.x[1] = t.kR;
    for (int i = 1; i < n - 1; ++i) {
        t.x[i + 1] = std::sqrt(-2.0 * std::log(t.kV / t.x[i] + std::exp(-0.5 * t.x[i] * t.x[i])));
    }
    t.x[n] = 0.0;
    for (int i = 0; i <= n; ++i) t.f[i] = std::exp(-0.5 * t.x[i] * t.x[i]);
    t.f[0] = f_r;
    return t;
}

}  // namespace

namespace detail {

/// W. Hörmann, "The transformed rejection method for generating Poisson random variables",
/// Insurance: Mathematics and Economics 12 (1993) 39–45 (algorithm PTRS).
std::uint64_t ptrs_from(RandomStream& stream, double mean) {
    const PtrsConstants c = ptrs_constants(mean);
    for (;;) {
        const PtrsProposal p = ptrs_proposal(c, mean, stream.next_u64());
        if (p.fast_accept || ptrs_slow_accept(c, mean, p)) return static_cast<std::uint64_t>(p.k);
    }
}

bool ptrs_slow_accept(const PtrsConstants& c, double mean, const PtrsProposal& p) {
    if (p.k < 0.0 || (p.us < 0.013 && p.v > p.us)) return false;
    // Hörmann's test log(v/α) − log(a/us² + b) <= −mean + k log(mean) − log k!, with the
    // left-hand logarithms merged into one.
    const double inv_alpha = 1.1239 + 1.1328 / (c.b - 3.4);
    return std::log(p.v * inv_alpha / (c.a / (p.us * p.us) + c.b)) <=
           -mean + p.k * std::log(mean) - log_factorial(p.k);
}

const ZigguratTable& ziggurat_table() {
    static const ZigguratTable table = make_ziggurat();
    return table;
}

}  // namespace detail

std::uint64_t sample_poisson(RandomStream& stream, double mean) {
    if (!(mean >= 0.0) || !(mean <= kMaxPoissonMean)) {
        throw input_error("Poisson mean " + format_ten_digits(mean) +
                          " is invalid, expected a finite value in [0, 1e15]");
    }
    if (mean == 0.0) return 0;
    if (mean < kPoissonInversionLimit) {
        return static_cast<std::uint64_t>(poisson_inversion(mean, stream.next_u64()));
    }
    return ptrs_from(stream, mean);
}

double sample_standard_normal(RandomStream& stream) {
    const ZigguratTable& t = ziggurat_table();
    for (;;) {
        const std::uint64_t word = stream.next_u64();
        double z = 0.0;
        if (normal_fast(t, word, z)) return z;
        const int layer = static_cast<int>(word & 127u);
        const bool negative = (word & 128u) != 0;
        const double x = static_cast<double>(word >> 11) * kTwoPow53Inv * t.x[layer];
        if (layer == 0) {
            // Tail beyond r (Marsaglia 1964).
            double a = 0.0;
            double b = 0.0;
            do {
                a = -std::log(uniform53_open(stream)) / ZigguratTable::kR;
                b = -std::log(uniform53_open(stream));
            } while (b + b < a * a);
            return negative ? -(ZigguratTable::kR + a) : ZigguratTable::kR + a;
        }
        // Wedge: a uniform height between the layer's bottom f(x[i]) and top f(x[i+1]).
        const double y = t.f[layer] + uniform53(stream) * (t.f[layer + 1] - t.f[layer]);
        if (y < std::exp(-0.5 * x * x)) return negative ? -x : x;
    }
}

}  // namespace glint::detect
