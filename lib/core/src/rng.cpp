// SPDX-License-Identifier: Apache-2.0
// Philox4x32-10, the stream keying, and the uniform, normal and Poisson samplers of
// RandomStream. The algorithms and their references are in docs/physics.md.
#include "glint/core/rng.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint {

namespace {

constexpr std::uint32_t kPhiloxM0 = 0xD2511F53u;
constexpr std::uint32_t kPhiloxM1 = 0xCD9E8D57u;
constexpr std::uint32_t kPhiloxW0 = 0x9E3779B9u;  // golden ratio
constexpr std::uint32_t kPhiloxW1 = 0xBB67AE85u;  // sqrt(3) - 1

// Salts that separate the two identity chains and their uses (arbitrary odd constants).
constexpr std::uint64_t kSaltChainKey = 0x6A09E667F3BCC909ull;
constexpr std::uint64_t kSaltChainCounter = 0xBB67AE8584CAA73Bull;
constexpr std::uint64_t kSaltId = 0x3C6EF372FE94F82Bull;
constexpr std::uint64_t kSaltFinal = 0xA54FF53A5F1D36F1ull;

constexpr double kTwoPow52Inv = 1.0 / 4503599627370496.0;  // 2^-52

constexpr double kPoissonInversionLimit = 10.0;
constexpr double kPoissonMaxMean = 1e15;

/// SplitMix64's output function (Steele, Lea, Flood 2014): a 64-bit bijection with full
/// avalanche.
constexpr std::uint64_t mix64(std::uint64_t z) noexcept {
    z += 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

// An identity chain over (seed, ids) in three steps, so that StreamPrefix can stop after
// some ids and go on later: start from the seed, absorb each id in order, finish with the
// total id count. Distinct salts give independent chains.

/// A chain's state before any id.
constexpr std::uint64_t chain_start(std::uint64_t salt, std::uint64_t seed) noexcept {
    return mix64(seed ^ salt);
}

/// A chain's state `h` after absorbing `ids` in order.
constexpr std::uint64_t chain_absorb(std::uint64_t salt, std::uint64_t h,
                                     std::span<const std::uint64_t> ids) noexcept {
    for (std::uint64_t id : ids) h = mix64(h ^ mix64(id ^ kSaltId ^ salt));
    return h;
}

/// A chain's output from its state `h` after `id_count` ids in all.
constexpr std::uint64_t chain_finish(std::uint64_t h, std::uint64_t id_count) noexcept {
    return mix64(h ^ kSaltFinal ^ id_count);
}

/// One ordered chain over (seed, ids).
std::uint64_t identity_chain(std::uint64_t salt, std::uint64_t seed,
                             std::span<const std::uint64_t> ids) noexcept {
    return chain_finish(chain_absorb(salt, chain_start(salt, seed), ids),
                        static_cast<std::uint64_t>(ids.size()));
}

/// The Philox key from the key chain's 64-bit output.
constexpr PhiloxKey philox_key(std::uint64_t key) noexcept {
    return {static_cast<std::uint32_t>(key), static_cast<std::uint32_t>(key >> 32)};
}

inline void mul_hi_lo(std::uint32_t a, std::uint32_t b, std::uint32_t& hi,
                      std::uint32_t& lo) noexcept {
    const std::uint64_t product = static_cast<std::uint64_t>(a) * b;
    hi = static_cast<std::uint32_t>(product >> 32);
    lo = static_cast<std::uint32_t>(product);
}

/// log(k!) for k >= 0: exact products for small k, Stirling's series above (error < 1e-15
/// relative for k >= 30). Written here because std::lgamma writes the global signgam.
double log_factorial(double k) noexcept {
    if (k < 30.0) {
        double product = 1.0;
        for (double i = 2.0; i <= k; i += 1.0) product *= i;
        return std::log(product);
    }
    const double n = k + 1.0;  // log Γ(n)
    const double inv = 1.0 / n;
    const double inv2 = inv * inv;
    return (n - 0.5) * std::log(n) - n + 0.5 * std::log(2.0 * std::numbers::pi) +
           inv * (1.0 / 12.0 - inv2 * (1.0 / 360.0 - inv2 * (1.0 / 1260.0 - inv2 / 1680.0)));
}

}  // namespace

PhiloxCounter philox4x32_10(PhiloxCounter counter, PhiloxKey key) noexcept {
    for (int round = 0; round < 10; ++round) {
        if (round > 0) {
            key[0] += kPhiloxW0;
            key[1] += kPhiloxW1;
        }
        std::uint32_t hi0, lo0, hi1, lo1;
        mul_hi_lo(kPhiloxM0, counter[0], hi0, lo0);
        mul_hi_lo(kPhiloxM1, counter[2], hi1, lo1);
        counter = {hi1 ^ counter[1] ^ key[0], lo1, hi0 ^ counter[3] ^ key[1], lo0};
    }
    return counter;
}

RandomStream::RandomStream(std::uint64_t seed, std::initializer_list<std::uint64_t> stream_ids)
    : RandomStream(seed, std::span<const std::uint64_t>(stream_ids.begin(), stream_ids.size())) {}

RandomStream::RandomStream(std::uint64_t seed, std::span<const std::uint64_t> stream_ids)
    : m_key(philox_key(identity_chain(kSaltChainKey, seed, stream_ids))),
      m_counter_high(identity_chain(kSaltChainCounter, seed, stream_ids)) {}

StreamPrefix::StreamPrefix(std::uint64_t seed,
                           std::initializer_list<std::uint64_t> leading_ids) noexcept
    : StreamPrefix(seed, std::span<const std::uint64_t>(leading_ids.begin(), leading_ids.size())) {}

StreamPrefix::StreamPrefix(std::uint64_t seed, std::span<const std::uint64_t> leading_ids) noexcept
    : m_key_chain(chain_absorb(kSaltChainKey, chain_start(kSaltChainKey, seed), leading_ids)),
      m_counter_chain(
          chain_absorb(kSaltChainCounter, chain_start(kSaltChainCounter, seed), leading_ids)),
      m_id_count(static_cast<std::uint64_t>(leading_ids.size())) {}

StreamPrefix StreamPrefix::extended(std::uint64_t id) const noexcept {
    const std::span<const std::uint64_t> ids(&id, 1);
    StreamPrefix longer = *this;
    longer.m_key_chain = chain_absorb(kSaltChainKey, m_key_chain, ids);
    longer.m_counter_chain = chain_absorb(kSaltChainCounter, m_counter_chain, ids);
    ++longer.m_id_count;
    return longer;
}

RandomStream StreamPrefix::stream(std::initializer_list<std::uint64_t> rest) const noexcept {
    return stream(std::span<const std::uint64_t>(rest.begin(), rest.size()));
}

RandomStream StreamPrefix::stream(std::span<const std::uint64_t> rest) const noexcept {
    const std::uint64_t id_count = m_id_count + static_cast<std::uint64_t>(rest.size());
    return RandomStream(
        philox_key(chain_finish(chain_absorb(kSaltChainKey, m_key_chain, rest), id_count)),
        chain_finish(chain_absorb(kSaltChainCounter, m_counter_chain, rest), id_count));
}

namespace {

/// Philox4x32-10 on `Lanes` counters side by side (c0[j] … c3[j] is lane j's counter, replaced
/// by its output): the rounds of different lanes overlap and vectorize.
template <std::size_t Lanes>
void philox_lanes(std::uint32_t (&c0)[Lanes], std::uint32_t (&c1)[Lanes],
                  std::uint32_t (&c2)[Lanes], std::uint32_t (&c3)[Lanes], PhiloxKey key) noexcept {
    std::uint32_t k0 = key[0];
    std::uint32_t k1 = key[1];
    for (int round = 0; round < 10; ++round) {
        if (round > 0) {
            k0 += kPhiloxW0;
            k1 += kPhiloxW1;
        }
        for (std::size_t j = 0; j < Lanes; ++j) {
            const std::uint64_t p0 = static_cast<std::uint64_t>(kPhiloxM0) * c0[j];
            const std::uint64_t p1 = static_cast<std::uint64_t>(kPhiloxM1) * c2[j];
            const auto n0 = static_cast<std::uint32_t>(p1 >> 32) ^ c1[j] ^ k0;
            const auto n2 = static_cast<std::uint32_t>(p0 >> 32) ^ c3[j] ^ k1;
            c1[j] = static_cast<std::uint32_t>(p1);
            c3[j] = static_cast<std::uint32_t>(p0);
            c0[j] = n0;
            c2[j] = n2;
        }
    }
}

}  // namespace

void RandomStream::refill() {
    // The four blocks of the 16-word group holding word m_position.
    constexpr std::size_t kBlocks = kBufferWords / 4;
    const std::uint64_t first = (m_position / kBufferWords) * kBlocks;
    std::uint32_t c0[kBlocks], c1[kBlocks], c2[kBlocks], c3[kBlocks];
    for (std::size_t j = 0; j < kBlocks; ++j) {
        const std::uint64_t block = first + j;
        c0[j] = static_cast<std::uint32_t>(block);
        c1[j] = static_cast<std::uint32_t>(block >> 32);
        c2[j] = static_cast<std::uint32_t>(m_counter_high);
        c3[j] = static_cast<std::uint32_t>(m_counter_high >> 32);
    }
    philox_lanes(c0, c1, c2, c3, m_key);
    for (std::size_t j = 0; j < kBlocks; ++j) {
        m_buffer[4 * j] = c0[j];
        m_buffer[4 * j + 1] = c1[j];
        m_buffer[4 * j + 2] = c2[j];
        m_buffer[4 * j + 3] = c3[j];
    }
}

void RandomStream::blocks_at(std::span<const std::uint64_t> word_indices,
                             std::span<PhiloxCounter> out) const {
    if (word_indices.size() != out.size()) {
        throw internal_error("RandomStream::blocks_at: " + std::to_string(word_indices.size()) +
                             " positions for " + std::to_string(out.size()) + " blocks");
    }
    constexpr std::size_t kLanes = 16;
    const auto high0 = static_cast<std::uint32_t>(m_counter_high);
    const auto high1 = static_cast<std::uint32_t>(m_counter_high >> 32);
    for (std::size_t begin = 0; begin < out.size(); begin += kLanes) {
        const std::size_t n = std::min(kLanes, out.size() - begin);
        // Lanes side by side so that the rounds of different blocks overlap (and vectorize).
        std::uint32_t c0[kLanes] = {}, c1[kLanes] = {}, c2[kLanes] = {}, c3[kLanes] = {};
        for (std::size_t j = 0; j < n; ++j) {
            const std::uint64_t index = word_indices[begin + j];
            if ((index & 3u) != 0) {
                throw internal_error("RandomStream::blocks_at: word position " +
                                     std::to_string(index) + " is not a multiple of 4");
            }
            const std::uint64_t block = index >> 2;
            c0[j] = static_cast<std::uint32_t>(block);
            c1[j] = static_cast<std::uint32_t>(block >> 32);
            c2[j] = high0;
            c3[j] = high1;
        }
        philox_lanes(c0, c1, c2, c3, m_key);
        for (std::size_t j = 0; j < n; ++j) out[begin + j] = {c0[j], c1[j], c2[j], c3[j]};
    }
}

void RandomStream::skip_to(std::uint64_t word_index) {
    m_position = word_index;
    if ((m_position % kBufferWords) != 0) refill();
    m_has_spare_normal = false;
}

double RandomStream::uniform_open() {
    return (static_cast<double>(next_u64() >> 12) + 0.5) * kTwoPow52Inv;
}

double RandomStream::uniform(double a, double b) {
    if (!std::isfinite(a) || !std::isfinite(b) || !(a <= b)) {
        throw input_error("uniform range [" + format_ten_digits(a) + ", " + format_ten_digits(b) +
                          ") is invalid, expected finite a <= b");
    }
    const double value = a + (b - a) * uniform();
    return value < b ? value : a;  // rounding can reach b when b - a is tiny
}

double RandomStream::normal() {
    if (m_has_spare_normal) {
        m_has_spare_normal = false;
        return m_spare_normal;
    }
    const double radius = std::sqrt(-2.0 * std::log(uniform_open()));
    const double angle = 2.0 * std::numbers::pi * uniform();
    m_spare_normal = radius * std::sin(angle);
    m_has_spare_normal = true;
    return radius * std::cos(angle);
}

double RandomStream::normal(double mean, double sigma) {
    if (!std::isfinite(mean) || !std::isfinite(sigma) || sigma < 0.0) {
        throw input_error("normal distribution with mean " + format_ten_digits(mean) +
                          " and sigma " + format_ten_digits(sigma) +
                          " is invalid, expected finite values and sigma >= 0");
    }
    return mean + sigma * normal();
}

std::uint64_t RandomStream::poisson(double mean) {
    if (!(mean >= 0.0) || !(mean <= kPoissonMaxMean)) {
        throw input_error("Poisson mean " + format_ten_digits(mean) +
                          " is invalid, expected a finite value in [0, 1e15]");
    }
    if (mean == 0.0) return 0;

    if (mean < kPoissonInversionLimit) {
        // Inversion by sequential search: smallest k with CDF(k) > u.
        const double u = uniform();
        double probability = std::exp(-mean);
        double cdf = probability;
        std::uint64_t k = 0;
        // The CDF sums to 1 only up to rounding; the k limit ends the search for u within
        // rounding of 1 (the tail beyond k = 200 is below 1e-150 for means under 10).
        while (u >= cdf && k < 200) {
            ++k;
            probability *= mean / static_cast<double>(k);
            cdf += probability;
        }
        return k;
    }

    // PTRS: W. Hörmann, "The transformed rejection method for generating Poisson random
    // variables", Insurance: Mathematics and Economics 12 (1993) 39–45.
    const double sqrt_mean = std::sqrt(mean);
    const double log_mean = std::log(mean);
    const double b = 0.931 + 2.53 * sqrt_mean;
    const double a = -0.059 + 0.02483 * b;
    const double inv_alpha = 1.1239 + 1.1328 / (b - 3.4);
    const double v_r = 0.9277 - 3.6224 / (b - 2.0);
    const double log_inv_alpha = std::log(inv_alpha);
    for (;;) {
        const double u = uniform() - 0.5;
        const double v = uniform();
        const double us = 0.5 - std::fabs(u);
        const double k = std::floor((2.0 * a / us + b) * u + mean + 0.43);
        if (us >= 0.07 && v <= v_r) return static_cast<std::uint64_t>(k);
        if (k < 0.0 || (us < 0.013 && v > us)) continue;
        if (std::log(v) + log_inv_alpha - std::log(a / (us * us) + b) <=
            -mean + k * log_mean - log_factorial(k)) {
            return static_cast<std::uint64_t>(k);
        }
    }
}

}  // namespace glint
