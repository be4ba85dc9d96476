// SPDX-License-Identifier: Apache-2.0
// The ticks of one focal-plane clock inside one task window, as an indexed sequence: the
// count comes from integer tick ranges (O(1) for rate clocks, O(log n) for a list of n
// triggers), tick i is computed from i (t = offset + j / rate, never accumulated), and
// nothing is allocated. The capture generator keeps one of these per (source, task).
// docs/schedule.md has the definitions (tolerance, synchronous ticks, trigger repeat).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "glint/model/instrument.h"

namespace glint::schedule {

/// A tick closer than this to a task window's start or stop counts as inside it (s).
inline constexpr double kTickTolerance_s = 1e-9;

/// Largest number of ticks one clock may have in one task window (2^53: tick indices stay
/// exact in a double).
inline constexpr std::uint64_t kMaxTicksPerWindow = std::uint64_t{1} << 53;

/// The period with which a list of n >= 2 increasing trigger times repeats:
/// P = (last − first) · n / (n − 1), i.e. the list's span plus its mean spacing, so that
/// 0.0 0.1 0.2 repeats at 0.3 0.4 0.5, 0.6 … (trigger i of repetition r fires at
/// times[i] + r · P). None for a single trigger (it fires once) or an empty list.
std::optional<double> trigger_period_s(std::span<const double> times_s);

/// The ticks of a clock inside the task window [start_s, stop_s] (both ends included within
/// kTickTolerance_s), in increasing time order.
///   - independent: tick j at offset + j / rate, j >= 0 (the offset is the first tick);
///   - synchronous: tick k at master tick j = offset_count + k · divider, k >= 0, master tick
///     j at master offset + j / master rate;
///   - external: trigger g = r · n + i at times[i] + r · period (r >= 0), the period being
///     trigger_period_s(times); a single trigger fires once;
///   - a zero-length window (start == stop) has exactly one tick, at start, whatever the
///     clock.
class ClockTicks {
public:
    /// An empty sequence.
    ClockTicks() = default;
    /// Ticks of `clock` in [start_s, stop_s]. `trigger_times_s` (external clocks) must outlive
    /// this object. Throws glint::Error (input, at the clock) for a rate <= 0 or not finite,
    /// a master missing from `clock_table`, a divider < 1 or offset count < 0, an empty or
    /// unsorted trigger list, stop < start, non-finite window ends, or more than
    /// kMaxTicksPerWindow ticks.
    ClockTicks(const model::Clock& clock, const std::vector<model::MasterClock>& clock_table,
               std::span<const double> trigger_times_s, double start_s, double stop_s);

    /// Number of ticks in the window.
    std::uint64_t size() const noexcept { return m_count; }
    bool empty() const noexcept { return m_count == 0; }
    /// Time of tick `i` (0 <= i < size()), s after the reference time.
    double time_s(std::uint64_t i) const noexcept {
        switch (m_kind) {
            case Kind::rate:
                return m_offset_s +
                       static_cast<double>(m_first + static_cast<std::int64_t>(i) * m_stride) /
                           m_rate_hz;
            case Kind::triggers:
                return trigger_time_s(m_first + static_cast<std::int64_t>(i));
            case Kind::instant:
                break;
        }
        return m_offset_s;
    }
    /// Times of every tick (tests and small windows).
    std::vector<double> times_s() const;

private:
    enum class Kind { rate, triggers, instant };

    /// Time of trigger g of the repeated list.
    double trigger_time_s(std::int64_t g) const noexcept {
        const auto n = static_cast<std::int64_t>(m_triggers.size());
        return m_triggers[static_cast<std::size_t>(g % n)] +
               static_cast<double>(g / n) * m_period_s;
    }
    /// Smallest trigger index whose time is >= x (strict: > x).
    std::int64_t first_trigger_from(double x, bool strict) const;

    Kind m_kind = Kind::instant;
    std::uint64_t m_count = 0;
    /// rate: t = m_offset_s + j / m_rate_hz, j = m_first + i · m_stride; instant: t = m_offset_s.
    double m_offset_s = 0.0;
    double m_rate_hz = 1.0;
    std::int64_t m_first = 0;
    std::int64_t m_stride = 1;
    /// triggers: g = m_first + i; 0 period = a single trigger that never repeats.
    std::span<const double> m_triggers;
    double m_period_s = 0.0;
};

}  // namespace glint::schedule
