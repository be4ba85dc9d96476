// SPDX-License-Identifier: Apache-2.0
// The two random variates of the detector model, drawn from a glint::RandomStream:
// Poisson (shot noise and dark current) and the standard normal (read noise). They are
// written for the detector's budget of one Philox block per pixel on the fast path:
//   - Poisson: mean 0 → 0 without drawing; mean < 10 → inversion by sequential search on a
//     53-bit uniform (two words); larger means → Hörmann's PTRS transformed rejection (1993),
//     whose two uniforms come from the halves of one 64-bit word ((k + ½)·2⁻³² each); the
//     logarithms of its slow path are computed only when that path is taken.
//   - Normal: Marsaglia and Tsang's 128-layer ziggurat (2000) on one 64-bit word per try
//     (7 bits layer, 1 bit sign, 53 bits abscissa), exact tail by Marsaglia's method.
// Both are exact samplers of their distributions (up to the resolution of the uniforms).
#pragma once

#include <cmath>
#include <cstdint>

#include "glint/core/rng.h"

namespace glint::detect {

/// Largest Poisson mean accepted (doubles hold the integer result exactly below it).
inline constexpr double kMaxPoissonMean = 1e15;

/// A Poisson variate with the given mean. Throws glint::Error (input) for a negative, NaN or
/// infinite mean, or one above kMaxPoissonMean.
std::uint64_t sample_poisson(RandomStream& stream, double mean);

/// A standard normal variate (mean 0, standard deviation 1).
double sample_standard_normal(RandomStream& stream);

/// The first step of each sampler on a given 64-bit word, inline, for callers that draw the
/// words of many pixels first and finish the rare undecided ones with the samplers above
/// (DetectionChain). Each function computes exactly what the sampler computes on that word.
namespace detail {

inline constexpr double kTwoPow32Inv = 1.0 / 4294967296.0;        // 2^-32
inline constexpr double kTwoPow53Inv = 1.0 / 9007199254740992.0;  // 2^-53
inline constexpr double kPoissonInversionLimit = 10.0;

/// std::floor without the library call for |x| < 4e18 (the same value).
inline double floor_value(double x) noexcept {
    if (!(std::fabs(x) < 4e18)) return std::floor(x);
    const double t = static_cast<double>(static_cast<std::int64_t>(x));
    return t > x ? t - 1.0 : t;
}

/// PTRS's constants for a mean >= 10.
struct PtrsConstants {
    double b, a, v_r;
};

inline PtrsConstants ptrs_constants(double mean) noexcept {
    const double b = 0.931 + 2.53 * std::sqrt(mean);
    return {b, -0.059 + 0.02483 * b, 0.9277 - 3.6224 / (b - 2.0)};
}

/// One PTRS proposal from a 64-bit word: u and v from its halves, the candidate k, and
/// whether the fast acceptance test takes it.
struct PtrsProposal {
    double u, v, us, k;
    bool fast_accept;
};

/// u, v and us of a word (PTRS's uniforms: (k + ½)·2⁻³² from each half, u centred).
inline double ptrs_u(std::uint64_t word) noexcept {
    return (static_cast<double>(word >> 32) + 0.5) * kTwoPow32Inv - 0.5;
}
inline double ptrs_v(std::uint64_t word) noexcept {
    return (static_cast<double>(word & 0xFFFFFFFFull) + 0.5) * kTwoPow32Inv;
}
/// The candidate before flooring: (2a/us + b) u + mean + 0.43.
inline double ptrs_candidate(const PtrsConstants& c, double mean, double u, double us) noexcept {
    return (2.0 * c.a / us + c.b) * u + mean + 0.43;
}

inline PtrsProposal ptrs_proposal(const PtrsConstants& c, double mean,
                                  std::uint64_t word) noexcept {
    PtrsProposal p;
    p.u = ptrs_u(word);
    p.v = ptrs_v(word);
    p.us = 0.5 - std::fabs(p.u);
    p.k = floor_value(ptrs_candidate(c, mean, p.u, p.us));
    p.fast_accept = p.us >= 0.07 && p.v <= c.v_r;
    return p;
}

/// PTRS's decision on a proposal its fast test did not accept, without drawing: true and the
/// proposal's k accepted by the full test, false when PTRS would draw another proposal.
bool ptrs_slow_accept(const PtrsConstants& c, double mean, const PtrsProposal& p);

/// PTRS (mean >= 10) from the stream's current position: what sample_poisson does after
/// the proposals drawn before that position were rejected.
std::uint64_t ptrs_from(RandomStream& stream, double mean);

/// Poisson by inversion (mean in (0, 10)) from the uniform (word >> 11)·2⁻⁵³.
inline double poisson_inversion(double mean, std::uint64_t word) noexcept {
    const double u = static_cast<double>(word >> 11) * kTwoPow53Inv;
    double probability = std::exp(-mean);
    double cdf = probability;
    double k = 0.0;
    // The tail beyond k = 200 is below 1e-150 for means under 10.
    while (u >= cdf && k < 200.0) {
        k += 1.0;
        probability *= mean / k;
        cdf += probability;
    }
    return k;
}

/// The ziggurat's table (layer edges x and densities f = exp(-x²/2), 128 layers).
struct ZigguratTable {
    static constexpr int kLayers = 128;
    static constexpr double kR = 3.442619855899;
    static constexpr double kV = 9.91256303526217e-3;
    double x[kLayers + 1];
    double f[kLayers + 1];
};
const ZigguratTable& ziggurat_table();

/// The ziggurat's fast path on one 64-bit word: true and `z` when the word's point lies in
/// its layer's rectangle (about 98.8 % of words).
inline bool normal_fast(const ZigguratTable& t, std::uint64_t word, double& z) noexcept {
    const int layer = static_cast<int>(word & 127u);
    const double x = static_cast<double>(word >> 11) * kTwoPow53Inv * t.x[layer];
    if (!(x < t.x[layer + 1])) return false;
    z = (word & 128u) != 0 ? -x : x;
    return true;
}

}  // namespace detail

}  // namespace glint::detect
