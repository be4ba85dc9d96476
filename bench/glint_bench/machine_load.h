// SPDX-License-Identifier: Apache-2.0
// How much of the machine other processes used while a measurement ran: a benchmark on a
// shared machine measures its neighbours too, so every figure of glint-bench carries the
// share of all cores' time spent outside this process (Linux /proc/stat busy time, steal
// included, minus this process's own CPU time from getrusage).
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>

namespace glint::bench {

/// A snapshot taken at construction; other_load() compares the machine with it.
class LoadProbe {
public:
    LoadProbe();
    /// Fraction (0–1) of all cores' time since construction that other processes (or the
    /// hypervisor, as steal time) took; nullopt when /proc/stat cannot be read or less than
    /// 0.25 s have passed (the kernel counts busy time in 10 ms ticks).
    std::optional<double> other_load() const;

private:
    std::optional<std::uint64_t> m_busy_ticks;
    double m_own_cpu_s = 0.0;
    std::chrono::steady_clock::time_point m_start;
};

}  // namespace glint::bench
