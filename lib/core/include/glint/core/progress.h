// SPDX-License-Identifier: Apache-2.0
// Progress reporting. Library code reports through a Progress handle; the ProgressPrinter
// renders updates for a person (a redrawn line, TTY only) and/or for a program (key=value
// lines in a file named by --progress).
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <ostream>
#include <string>

namespace glint {

/// One progress report: `done` of `total` units of the stage `label`.
struct ProgressUpdate {
    std::string label;
    std::uint64_t done = 0;
    std::uint64_t total = 0;
    bool finished = false;
};

/// Handle that library code reports progress through. Default-constructed: reports go nowhere.
class Progress {
public:
    using Sink = std::function<void(const ProgressUpdate&)>;

    Progress() = default;
    explicit Progress(Sink sink) : m_sink(std::move(sink)) {}

    void update(const std::string& label, std::uint64_t done, std::uint64_t total) const {
        if (m_sink) m_sink(ProgressUpdate{label, done, total, false});
    }
    void finish(const std::string& label, std::uint64_t total) const {
        if (m_sink) m_sink(ProgressUpdate{label, total, total, true});
    }

private:
    Sink m_sink;
};

/// Renders progress updates. `terminal` (stderr when it is a TTY and not --quiet) gets one
/// line redrawn in place at most ten times a second (with the stage's rate and ETA once
/// something is done); `machine` (the --progress file) gets `label=... done=... total=...
/// percent=... elapsed_s=... rate_per_s=... eta_s=... state=...` lines (rate and ETA of the
/// current label, −1 while unknown), throttled the same way except that the first and the
/// finishing update of a stage are always written.
class ProgressPrinter {
public:
    ProgressPrinter(std::ostream* terminal, std::ostream* machine);
    void operator()(const ProgressUpdate& update);

private:
    std::ostream* m_terminal;
    std::ostream* m_machine;
    std::chrono::steady_clock::time_point m_start;
    std::chrono::steady_clock::time_point m_last_draw;
    std::chrono::steady_clock::time_point m_stage_start;  ///< when the current label began
    std::string m_last_label;
    bool m_line_open = false;
};

}  // namespace glint
