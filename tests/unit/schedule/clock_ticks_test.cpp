// SPDX-License-Identifier: Apache-2.0
// Clock ticks in a task window: independent clocks with offsets, ticks on the window ends
// (and within the 1e-9 s tolerance), zero-length windows, synchronous clocks through a
// master's divider and offset count, repeated trigger lists, counts equal to brute-force
// enumeration, the 3.6e8-tick window, and bad clocks.
#include "glint/schedule/clock_ticks.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "glint/core/error.h"
#include "glint/schedule/schedule.h"

namespace glint::schedule {
namespace clock_ticks_test {

using ::testing::DoubleNear;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

model::Clock independent(double rate_hz, double offset_s = 0.0) {
    model::Clock clock;
    clock.type = model::ClockType::independent;
    clock.rate_hz = rate_hz;
    clock.offset_s = offset_s;
    return clock;
}

model::Clock synchronous(const std::string& master, std::int64_t divider,
                         std::int64_t offset_count) {
    model::Clock clock;
    clock.type = model::ClockType::synchronous;
    clock.master = master;
    clock.divider = divider;
    clock.offset_count = offset_count;
    return clock;
}

model::Clock external() {
    model::Clock clock;
    clock.type = model::ClockType::external_trigger;
    return clock;
}

const std::vector<model::MasterClock> kTable{{"Master", 100.0, 0.01, {}}, {"Slow", 1.0, 0.0, {}}};
const std::vector<double> kNone;

std::vector<double> ticks(const model::Clock& clock, double start_s, double stop_s,
                          const std::vector<double>& triggers = kNone) {
    return clock_ticks(clock, kTable, triggers, start_s, stop_s);
}

std::string error_of(const model::Clock& clock, double start_s, double stop_s,
                     const std::vector<double>& triggers = kNone) {
    try {
        ClockTicks(clock, kTable, triggers, start_s, stop_s);
    } catch (const Error& error) {
        return error.message();
    }
    return "no error";
}

TEST(ClockTicks, IndependentWithOffset) {
    EXPECT_THAT(ticks(independent(10.0, 0.05), 0.0, 0.5),
                ElementsAre(0.05, DoubleNear(0.15, 1e-15), 0.25, DoubleNear(0.35, 1e-15),
                            DoubleNear(0.45, 1e-15)));
    // Ticks are offset + j / rate, computed from j (never accumulated).
    const std::vector<double> times = ticks(independent(10.0, 0.05), 100.0, 101.0);
    ASSERT_EQ(times.size(), 10u);
    for (std::size_t i = 0; i < times.size(); ++i) {
        EXPECT_EQ(times[i], 0.05 + static_cast<double>(1000 + i) / 10.0);
    }
}

TEST(ClockTicks, TicksOnTheWindowEndsAreIncluded) {
    EXPECT_THAT(ticks(independent(4.0), 0.0, 1.0), ElementsAre(0.0, 0.25, 0.5, 0.75, 1.0));
    EXPECT_THAT(ticks(independent(4.0), 0.25, 0.75), ElementsAre(0.25, 0.5, 0.75));
    // Within the tolerance of an end counts; beyond it does not.
    EXPECT_THAT(ticks(independent(4.0), 0.25 + 0.5e-9, 0.75 - 0.5e-9),
                ElementsAre(0.25, 0.5, 0.75));
    EXPECT_THAT(ticks(independent(4.0), 0.25 + 2e-9, 0.75 - 2e-9), ElementsAre(0.5));
    // 0.1 + 0.2 != 0.3 in binary: a stop written as 0.3 still catches tick 3 of 10 Hz.
    EXPECT_EQ(ticks(independent(10.0), 0.0, 0.1 + 0.2).size(), 4u);
    EXPECT_EQ(ticks(independent(10.0), 0.0, 0.3).size(), 4u);
}

TEST(ClockTicks, TheOffsetIsTheFirstTick) {
    EXPECT_THAT(ticks(independent(1.0, 2.0), -5.0, 3.5), ElementsAre(2.0, 3.0));
    EXPECT_THAT(ticks(independent(1.0, 2.0), -5.0, 1.0), IsEmpty());
    EXPECT_THAT(ticks(independent(1.0, -2.0), -5.0, 0.0), ElementsAre(-2.0, -1.0, 0.0));
}

TEST(ClockTicks, ZeroLengthWindowIsOneCaptureAtThatInstant) {
    EXPECT_THAT(ticks(independent(10.0, 0.05), 2.0, 2.0), ElementsAre(2.0));
    EXPECT_THAT(ticks(synchronous("Master", 4, 2), 0.5, 0.5), ElementsAre(0.5));
    EXPECT_THAT(ticks(external(), 7.0, 7.0, {0.0, 0.1}), ElementsAre(7.0));
    // Before the clock's first tick too.
    EXPECT_THAT(ticks(independent(1.0, 5.0), 1.0, 1.0), ElementsAre(1.0));
}

TEST(ClockTicks, WindowBetweenTicksIsEmpty) {
    EXPECT_THAT(ticks(independent(1.0), 0.2, 0.8), IsEmpty());
    EXPECT_EQ(ClockTicks(independent(1.0), kTable, kNone, 0.2, 0.8).size(), 0u);
}

TEST(ClockTicks, SynchronousDividerAndOffsetCount) {
    // Master: 100 Hz from 0.01 s. Tick k of the clock is master tick 2 + 4k.
    const std::vector<double> times = ticks(synchronous("Master", 4, 2), 0.0, 0.2);
    ASSERT_EQ(times.size(), 5u);
    for (std::size_t k = 0; k < times.size(); ++k) {
        EXPECT_EQ(times[k], 0.01 + static_cast<double>(2 + 4 * k) / 100.0);
    }
    EXPECT_THAT(times, ElementsAre(DoubleNear(0.03, 1e-15), DoubleNear(0.07, 1e-15),
                                   DoubleNear(0.11, 1e-15), DoubleNear(0.15, 1e-15),
                                   DoubleNear(0.19, 1e-15)));
    // A window starting between slave ticks starts at the next slave tick.
    EXPECT_THAT(ticks(synchronous("Master", 4, 2), 0.08, 0.16),
                ElementsAre(DoubleNear(0.11, 1e-15), DoubleNear(0.15, 1e-15)));
    EXPECT_EQ(ticks(synchronous("Master", 1, 0), 0.0, 0.2).size(), 20u);
    EXPECT_THAT(ticks(synchronous("Slow", 1, 0), 0.0, 2.0), ElementsAre(0.0, 1.0, 2.0));
    EXPECT_THAT(ticks(synchronous("Slow", 2, 3), 0.0, 10.0), ElementsAre(3.0, 5.0, 7.0, 9.0));
}

TEST(ClockTicks, TriggerListRepeatsWithSpanPlusMeanSpacing) {
    const std::vector<double> list{0.0, 0.1, 0.2};
    const std::vector<double> times = ticks(external(), 0.0, 1.0, list);
    ASSERT_EQ(times.size(), 11u);
    for (std::size_t i = 0; i < times.size(); ++i) {
        EXPECT_NEAR(times[i], 0.1 * static_cast<double>(i), 1e-12) << i;
    }
    const std::vector<double> five{0.0, 0.1, 0.2, 0.35, 0.5};
    EXPECT_THAT(
        ticks(external(), 0.6, 1.3, five),
        ElementsAre(DoubleNear(0.625, 1e-12), DoubleNear(0.725, 1e-12), DoubleNear(0.825, 1e-12),
                    DoubleNear(0.975, 1e-12), DoubleNear(1.125, 1e-12), DoubleNear(1.25, 1e-12)));
    // Nothing before the first trigger of the list.
    const std::vector<double> late{5.0, 6.0};
    EXPECT_THAT(ticks(external(), 0.0, 8.5, late), ElementsAre(5.0, 6.0, 7.0, 8.0));
}

TEST(ClockTicks, SingleTriggerFiresOnce) {
    const std::vector<double> one{0.5};
    EXPECT_THAT(ticks(external(), 0.0, 10.0, one), ElementsAre(0.5));
    EXPECT_THAT(ticks(external(), 0.6, 10.0, one), IsEmpty());
}

/// Brute force: every tick index whose time (computed as ClockTicks does) is in the window.
std::vector<double> brute_force_rate(double offset_s, double rate_hz, std::int64_t first,
                                     std::int64_t stride, double start_s, double stop_s) {
    std::vector<double> times;
    for (std::int64_t j = first; j < 100000; j += stride) {
        const double t = offset_s + static_cast<double>(j) / rate_hz;
        if (t >= start_s - kTickTolerance_s && t <= stop_s + kTickTolerance_s) times.push_back(t);
    }
    return times;
}

TEST(ClockTicks, CountsEqualBruteForceEnumeration) {
    const std::vector<double> list{0.013, 0.1, 0.37, 0.4};
    const double period = 0.4 - 0.013 + (0.4 - 0.013) / 3.0;
    for (int a = 0; a < 40; ++a) {
        for (int b = a; b < 40; b += 3) {
            const double start = a * 0.173 - 1.0;
            const double stop = b * 0.173 - 1.0 + (b % 2 ? 0.0 : 0.05);
            if (stop == start) continue;
            EXPECT_EQ(ticks(independent(7.0, 0.3), start, stop),
                      brute_force_rate(0.3, 7.0, 0, 1, start, stop));
            EXPECT_EQ(ticks(synchronous("Master", 3, 5), start, stop),
                      brute_force_rate(0.01, 100.0, 5, 3, start, stop));
            std::vector<double> expected;
            for (int r = 0; r < 40; ++r) {
                for (double t : list) {
                    const double time = t + r * period;
                    if (time >= start - kTickTolerance_s && time <= stop + kTickTolerance_s) {
                        expected.push_back(time);
                    }
                }
            }
            const std::vector<double> got = ticks(external(), start, stop, list);
            ASSERT_EQ(got.size(), expected.size()) << start << " " << stop;
            for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], expected[i], 1e-12);
        }
    }
}

TEST(ClockTicks, TenHoursAtTenKilohertzIsCountedNotEnumerated) {
    const ClockTicks line(independent(10000.0), kTable, kNone, 0.0, 36000.0);
    EXPECT_EQ(line.size(), 360000001u);
    EXPECT_EQ(line.time_s(0), 0.0);
    EXPECT_EQ(line.time_s(360000000), 36000.0);
    EXPECT_EQ(line.time_s(123456789), 12345.6789);
    const std::vector<double> list{0.0, 1e-4, 2e-4};
    const ClockTicks triggers(external(), kTable, list, 0.0, 36000.0);
    EXPECT_EQ(triggers.size(), 360000001u);
}

TEST(ClockTicks, BadClocksAreErrors) {
    EXPECT_EQ(error_of(independent(0.0), 0.0, 1.0),
              "clock rate 0 Hz is not a positive number, expected a rate > 0 Hz");
    EXPECT_EQ(error_of(independent(-5.0), 0.0, 0.0),
              "clock rate -5 Hz is not a positive number, expected a rate > 0 Hz");
    EXPECT_EQ(error_of(synchronous("Nope", 1, 0), 0.0, 1.0),
              "synchronous clock names master \"Nope\", which is not in the <clocktable>");
    EXPECT_EQ(error_of(synchronous("Master", 0, 0), 0.0, 1.0),
              "synchronous clock divider 0 and offset 0: expected a divider >= 1 and an offset "
              ">= 0");
    EXPECT_EQ(error_of(external(), 0.0, 1.0), "external clock has no trigger times");
    EXPECT_EQ(error_of(external(), 0.0, 1.0, {0.2, 0.1}),
              "external clock trigger times are not finite and strictly increasing");
    EXPECT_EQ(error_of(independent(1.0), 3.0, 1.0),
              "task stop time 1 s is before its start time 3 s: expected stop >= start");
    EXPECT_THAT(error_of(independent(1e12), 0.0, 1e6), HasSubstr("more than 2^53 times"));
}

TEST(TriggerPeriod, IsSpanPlusMeanSpacing) {
    const std::vector<double> three{0.0, 0.1, 0.2};
    EXPECT_NEAR(*trigger_period_s(three), 0.3, 1e-15);
    const std::vector<double> five{0.0, 0.1, 0.2, 0.35, 0.5};
    EXPECT_NEAR(*trigger_period_s(five), 0.625, 1e-15);
    const std::vector<double> offset{10.0, 12.0};
    EXPECT_DOUBLE_EQ(*trigger_period_s(offset), 4.0);
    EXPECT_FALSE(trigger_period_s(std::vector<double>{1.0}).has_value());
    EXPECT_FALSE(trigger_period_s(std::vector<double>{}).has_value());
}

}  // namespace clock_ticks_test
}  // namespace glint::schedule
