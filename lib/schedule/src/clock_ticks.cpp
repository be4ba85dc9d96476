// SPDX-License-Identifier: Apache-2.0
// Tick ranges of rate clocks (independent and synchronous) and of repeated trigger lists
// inside a task window, computed with integer indices: estimate the index from the window
// end, then step it until the tick time computed exactly as time_s() computes it lies on the
// right side of the end (± kTickTolerance_s). Counting and enumeration therefore agree
// bit for bit.
#include "glint/schedule/clock_ticks.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::schedule {

namespace {

constexpr double kMaxIndex = static_cast<double>(kMaxTicksPerWindow);

std::string seconds(double value) { return format_shortest(value) + " s"; }

void check_rate(double rate_hz, const ErrorContext& where, const std::string& what) {
    if (!std::isfinite(rate_hz) || rate_hz <= 0.0) {
        throw input_error(what + " rate " + format_shortest(rate_hz) +
                              " Hz is not a positive number, expected a rate > 0 Hz",
                          where);
    }
}

void check_offset(double offset_s, const ErrorContext& where, const std::string& what) {
    if (!std::isfinite(offset_s)) {
        throw input_error(
            what + " offset " + format_shortest(offset_s) + " is not a finite number of seconds",
            where);
    }
}

Error too_many_ticks(const ErrorContext& where, double stop_s) {
    return input_error("the clock ticks more than 2^53 times before the task stop " +
                           seconds(stop_s) + ", expected a smaller rate or window",
                       where);
}

}  // namespace

ClockTicks::ClockTicks(const model::Clock& clock,
                       const std::vector<model::MasterClock>& clock_table,
                       std::span<const double> trigger_times_s, double start_s, double stop_s) {
    if (!std::isfinite(start_s) || !std::isfinite(stop_s)) {
        throw input_error(
            "task window [" + seconds(start_s) + ", " + seconds(stop_s) + "] is not finite",
            clock.where);
    }
    if (stop_s < start_s) {
        throw input_error("task stop time " + seconds(stop_s) + " is before its start time " +
                              seconds(start_s) + ": expected stop >= start",
                          clock.where);
    }
    // The clock is checked even for a zero-length window, so a bad clock never goes unseen.
    double offset_s = 0.0;
    double rate_hz = 1.0;
    std::int64_t first_tick = 0;
    std::int64_t stride = 1;
    switch (clock.type) {
        case model::ClockType::independent:
            check_rate(clock.rate_hz, clock.where, "clock");
            check_offset(clock.offset_s, clock.where, "clock");
            offset_s = clock.offset_s;
            rate_hz = clock.rate_hz;
            m_kind = Kind::rate;
            break;
        case model::ClockType::synchronous: {
            const auto master =
                std::find_if(clock_table.begin(), clock_table.end(),
                             [&](const model::MasterClock& m) { return m.name == clock.master; });
            if (master == clock_table.end()) {
                throw input_error("synchronous clock names master \"" + clock.master +
                                      "\", which is not in the <clocktable>",
                                  clock.where);
            }
            check_rate(master->rate_hz, master->where, "master clock \"" + master->name + "\"");
            check_offset(master->offset_s, master->where, "master clock \"" + master->name + "\"");
            if (clock.divider < 1 || clock.offset_count < 0) {
                throw input_error("synchronous clock divider " + std::to_string(clock.divider) +
                                      " and offset " + std::to_string(clock.offset_count) +
                                      ": expected a divider >= 1 and an offset >= 0",
                                  clock.where);
            }
            offset_s = master->offset_s;
            rate_hz = master->rate_hz;
            first_tick = clock.offset_count;
            stride = clock.divider;
            m_kind = Kind::rate;
            break;
        }
        case model::ClockType::external_trigger:
            if (trigger_times_s.empty()) {
                throw input_error("external clock has no trigger times", clock.where);
            }
            for (std::size_t i = 0; i < trigger_times_s.size(); ++i) {
                if (!std::isfinite(trigger_times_s[i]) ||
                    (i > 0 && trigger_times_s[i] <= trigger_times_s[i - 1])) {
                    throw input_error(
                        "external clock trigger times are not finite and strictly increasing",
                        clock.where);
                }
            }
            m_kind = Kind::triggers;
            break;
    }

    if (start_s == stop_s) {  // zero-length task: one capture at that instant
        m_kind = Kind::instant;
        m_offset_s = start_s;
        m_count = 1;
        return;
    }
    const double low_s = start_s - kTickTolerance_s;
    const double high_s = stop_s + kTickTolerance_s;

    if (m_kind == Kind::rate) {
        m_offset_s = offset_s;
        m_rate_hz = rate_hz;
        const auto tick = [&](std::int64_t j) {
            return offset_s + static_cast<double>(j) / rate_hz;
        };
        // Last (master) tick at or before the stop.
        const double high_estimate = std::floor((high_s - offset_s) * rate_hz);
        if (high_estimate > kMaxIndex) throw too_many_ticks(clock.where, stop_s);
        auto last = static_cast<std::int64_t>(std::max(high_estimate, -1.0));
        while (tick(last + 1) <= high_s) ++last;
        while (last >= 0 && tick(last) > high_s) --last;
        if (last < first_tick) return;  // no tick yet at the stop
        // First (master) tick at or after the start, not before the clock's first tick.
        const double low_estimate = std::ceil((low_s - offset_s) * rate_hz);
        auto first =
            static_cast<std::int64_t>(std::clamp(low_estimate, 0.0, static_cast<double>(last)));
        while (first > 0 && tick(first - 1) >= low_s) --first;
        while (first <= last && tick(first) < low_s) ++first;
        first = std::max(first, first_tick);
        if (first > last) return;
        // Ticks of this clock are master ticks first_tick + k · stride, k >= 0.
        const std::int64_t k_first = (first - first_tick + stride - 1) / stride;
        const std::int64_t k_last = (last - first_tick) / stride;
        if (k_last < k_first) return;
        m_first = first_tick + k_first * stride;
        m_stride = stride;
        m_count = static_cast<std::uint64_t>(k_last - k_first + 1);
        return;
    }

    // Trigger list.
    m_triggers = trigger_times_s;
    const std::optional<double> period = trigger_period_s(trigger_times_s);
    if (!period) {  // a single trigger fires once
        const double t = trigger_times_s.front();
        m_count = (t >= low_s && t <= high_s) ? 1 : 0;
        m_first = 0;
        return;
    }
    m_period_s = *period;
    const double n = static_cast<double>(trigger_times_s.size());
    if ((high_s - trigger_times_s.front()) / m_period_s * n > kMaxIndex) {
        throw too_many_ticks(clock.where, stop_s);
    }
    const std::int64_t first = first_trigger_from(low_s, false);
    const std::int64_t end = first_trigger_from(high_s, true);
    m_first = first;
    m_count = end > first ? static_cast<std::uint64_t>(end - first) : 0;
}

std::int64_t ClockTicks::first_trigger_from(double x, bool strict) const {
    const auto after = [&](std::int64_t g) {
        const double t = trigger_time_s(g);
        return strict ? t > x : t >= x;
    };
    if (after(0)) return 0;
    const auto n = static_cast<std::int64_t>(m_triggers.size());
    const double repetitions = std::floor((x - m_triggers.front()) / m_period_s);
    const auto r = static_cast<std::int64_t>(std::max(repetitions, 0.0));
    // Bracket: after(low) is false, after(high) is true.
    std::int64_t low = r * n;
    while (low > 0 && after(low)) low = std::max<std::int64_t>(0, low - n);
    std::int64_t high = (r + 1) * n;
    while (!after(high)) high += n;
    while (high - low > 1) {
        const std::int64_t mid = low + (high - low) / 2;
        if (after(mid)) {
            high = mid;
        } else {
            low = mid;
        }
    }
    return high;
}

std::vector<double> ClockTicks::times_s() const {
    std::vector<double> times;
    times.reserve(m_count);
    for (std::uint64_t i = 0; i < m_count; ++i) times.push_back(time_s(i));
    return times;
}

std::optional<double> trigger_period_s(std::span<const double> times_s) {
    if (times_s.size() < 2) return std::nullopt;
    const double n = static_cast<double>(times_s.size());
    return (times_s.back() - times_s.front()) * n / (n - 1.0);
}

}  // namespace glint::schedule
