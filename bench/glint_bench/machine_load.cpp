// SPDX-License-Identifier: Apache-2.0
// The load probe of glint-bench (machine_load.h).
#include "machine_load.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

namespace glint::bench {
namespace {

/// Shortest measurement whose load is reported.
constexpr double kMinWall_s = 0.25;

struct MachineTicks {
    std::uint64_t busy = 0;  ///< user + nice + system + irq + softirq + steal
    unsigned cores = 0;
};

std::optional<MachineTicks> read_proc_stat() {
    std::ifstream in("/proc/stat");
    if (!in) return std::nullopt;
    MachineTicks ticks;
    bool total = false;
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("cpu ", 0) == 0) {
            std::istringstream fields(line.substr(4));
            std::uint64_t user = 0, nice = 0, system = 0, idle = 0, iowait = 0, irq = 0,
                          softirq = 0, steal = 0;
            fields >> user >> nice >> system >> idle >> iowait >> irq >> softirq >> steal;
            if (!fields) return std::nullopt;
            ticks.busy = user + nice + system + irq + softirq + steal;
            total = true;
        } else if (line.rfind("cpu", 0) == 0) {
            ++ticks.cores;
        }
    }
    if (!total) return std::nullopt;
    return ticks;
}

double own_cpu_seconds() {
    rusage usage{};
    if (getrusage(RUSAGE_SELF, &usage) != 0) return 0.0;
    const auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * t.tv_usec; };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

}  // namespace

LoadProbe::LoadProbe() : m_own_cpu_s(own_cpu_seconds()), m_start(std::chrono::steady_clock::now()) {
    if (const auto ticks = read_proc_stat()) m_busy_ticks = ticks->busy;
}

std::optional<double> LoadProbe::other_load() const {
    const auto ticks = read_proc_stat();
    if (!ticks || !m_busy_ticks) return std::nullopt;
    const double wall_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    const long per_second = sysconf(_SC_CLK_TCK);
    const unsigned cores =
        ticks->cores > 0 ? ticks->cores : std::max(1u, std::thread::hardware_concurrency());
    // Busy time is counted in clock ticks (10 ms): shorter measurements cannot be judged.
    if (!(wall_s >= kMinWall_s) || per_second <= 0) return std::nullopt;
    const double busy_s = double(ticks->busy - *m_busy_ticks) / double(per_second);
    const double other_s = busy_s - (own_cpu_seconds() - m_own_cpu_s);
    return std::clamp(other_s / (wall_s * cores), 0.0, 1.0);
}

}  // namespace glint::bench
