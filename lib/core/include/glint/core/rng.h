// SPDX-License-Identifier: Apache-2.0
// Deterministic counter-based random numbers: the Philox4x32-10 block function (Salmon et al.,
// "Parallel random numbers: as easy as 1, 2, 3", SC 2011) and RandomStream, a stream keyed
// by (seed, stream ids) that gives the same sequence on every platform and thread layout, and
// StreamPrefix, which keys many streams that share their leading ids with less hashing.
// All distributions (uniform, normal, Poisson) are implemented here; std::*_distribution is
// never used because its output differs between standard libraries. See docs/physics.md.
#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>
#include <span>

namespace glint {

/// A Philox4x32 counter: four 32-bit words, word 0 least significant.
using PhiloxCounter = std::array<std::uint32_t, 4>;
/// A Philox4x32 key: two 32-bit words.
using PhiloxKey = std::array<std::uint32_t, 2>;

/// The Philox4x32-10 bijection of Random123: ten rounds keyed by `key` applied to `counter`.
/// Matches the published Random123 known-answer vectors.
PhiloxCounter philox4x32_10(PhiloxCounter counter, PhiloxKey key) noexcept;

/// A reproducible random stream. Its identity is (seed, stream_ids): the ids are mixed with
/// the seed by two SplitMix64 finalizer chains with distinct salts into the 64-bit Philox key
/// and the high 64 bits of the counter (128 bits of identity); the low 64 bits of the counter
/// number the 128-bit blocks drawn. Equal (seed, ids) give equal sequences everywhere;
/// different seeds, ids, id counts or id orders give independent streams.
///
/// Streams that share leading ids (e.g. one per sample of a batch) are keyed more cheaply
/// through StreamPrefix, which gives the same streams.
///
/// Integer and uniform draws are bit-exact on every platform. normal() and poisson() also
/// call log/exp/sqrt/sin/cos, so they are exact wherever the C library's results agree
/// (always for one build; libm versions may differ in the last bit).
///
/// Words are consumed in order; next_u64() consumes two words (the first one is the low
/// half). A stream is not thread-safe; give each thread or work item its own stream.
class RandomStream {
public:
    /// A stream keyed by `seed` and the ordered `stream_ids` (e.g. plugin, task, pixel).
    RandomStream(std::uint64_t seed, std::initializer_list<std::uint64_t> stream_ids);
    /// A stream keyed by `seed` and the ordered `stream_ids`.
    RandomStream(std::uint64_t seed, std::span<const std::uint64_t> stream_ids);

    /// The next 32 random bits. (These three are inline: the path tracer draws a few dozen
    /// numbers per path.)
    std::uint32_t next_u32() {
        if ((m_position % kBufferWords) == 0) refill();
        return m_buffer[m_position++ % kBufferWords];
    }
    /// The next 64 random bits (two words; the first drawn is the low half).
    std::uint64_t next_u64() {
        const std::uint64_t low = next_u32();
        const std::uint64_t high = next_u32();
        return (high << 32) | low;
    }

    /// Uniform on [0, 1) with 53 random bits (multiples of 2⁻⁵³); consumes two words.
    double uniform() { return static_cast<double>(next_u64() >> 11) * 0x1p-53; }
    /// Uniform on the open interval (0, 1): (k + 0.5)·2⁻⁵², never 0 or 1; consumes two words.
    double uniform_open();
    /// Uniform on [a, b); throws glint::Error (input) unless a and b are finite and a <= b.
    double uniform(double a, double b);

    /// A standard normal variate (Box–Muller; the second value of each pair is kept for the
    /// next call).
    double normal();
    /// A normal variate with the given mean and standard deviation; throws glint::Error
    /// (input) unless both are finite and sigma >= 0.
    double normal(double mean, double sigma);

    /// A Poisson variate with the given mean. Mean 0 gives 0 without drawing; means below 10
    /// use inversion by sequential search; larger means use Hörmann's PTRS transformed
    /// rejection (1993), O(1) whatever the mean. Throws glint::Error (input) for a negative,
    /// NaN or infinite mean, or one above 1e15 (where doubles stop holding the integer
    /// result exactly).
    std::uint64_t poisson(double mean);

    /// Repositions the stream as if exactly `word_index` 32-bit words had been drawn since
    /// construction; forgets any kept normal variate.
    void skip_to(std::uint64_t word_index);
    /// How many 32-bit words have been drawn (or skipped to).
    std::uint64_t position() const noexcept { return m_position; }

    /// The four words the stream gives from each word position `word_indices[i]` (a multiple
    /// of 4: the start of a 128-bit block), in draw order, into `out[i]`: what skip_to(index)
    /// then four next_u32() would return. The stream itself is not moved. Many blocks are
    /// computed together (interleaved Philox rounds), several times faster than one by one.
    /// Throws glint::Error (internal) for a position that is not a multiple of 4 or spans of
    /// different sizes.
    void blocks_at(std::span<const std::uint64_t> word_indices, std::span<PhiloxCounter> out) const;

private:
    friend class StreamPrefix;

    /// A stream with an already mixed identity (what StreamPrefix computes).
    RandomStream(PhiloxKey key, std::uint64_t counter_high) noexcept
        : m_key(key), m_counter_high(counter_high) {}

    void refill();

    PhiloxKey m_key{};
    std::uint64_t m_counter_high = 0;  ///< counter words 2 and 3: part of the stream identity
    std::uint64_t m_position = 0;      ///< words consumed; block = m_position / 4
    /// Words drawn at a time: four blocks computed side by side (their rounds overlap).
    static constexpr std::size_t kBufferWords = 16;
    /// Words (m_position - 1) / 16 × 16 onwards: blocks 4 (m_position - 1) / 16 … + 3.
    std::array<std::uint32_t, kBufferWords> m_buffer{};
    bool m_has_spare_normal = false;
    double m_spare_normal = 0.0;
};

/// The identity chains of RandomStream run over (seed, leading ids), kept so that many
/// streams sharing those ids can be keyed by hashing only the ids that differ (e.g.
/// {plugin, task, capture} once per batch, then {problem, sample} per stream). The streams
/// are identical, bit for bit, to the ones the RandomStream constructor gives:
/// StreamPrefix(seed, {a, b}).stream({c, d}) is RandomStream(seed, {a, b, c, d}), and
/// StreamPrefix(seed, {a}).extended(b).stream({}) is RandomStream(seed, {a, b}).
/// A small value (three words); copy it freely between threads.
class StreamPrefix {
public:
    /// The chains over `seed` and the ordered `leading_ids`.
    StreamPrefix(std::uint64_t seed, std::initializer_list<std::uint64_t> leading_ids) noexcept;
    /// The chains over `seed` and the ordered `leading_ids`.
    StreamPrefix(std::uint64_t seed, std::span<const std::uint64_t> leading_ids) noexcept;

    /// This prefix with `id` appended to its ids.
    StreamPrefix extended(std::uint64_t id) const noexcept;

    /// The stream keyed by the seed and the prefix's ids followed by the ordered `rest`.
    RandomStream stream(std::initializer_list<std::uint64_t> rest) const noexcept;
    /// The stream keyed by the seed and the prefix's ids followed by the ordered `rest`.
    RandomStream stream(std::span<const std::uint64_t> rest) const noexcept;

    /// How many ids the prefix holds.
    std::uint64_t id_count() const noexcept { return m_id_count; }

private:
    std::uint64_t m_key_chain = 0;      ///< the key chain's state after the ids so far
    std::uint64_t m_counter_chain = 0;  ///< the counter chain's state after the ids so far
    std::uint64_t m_id_count = 0;       ///< ids so far; the final mix takes the total count
};

}  // namespace glint
