// SPDX-License-Identifier: Apache-2.0
// Log level names, CancelToken, and the ProgressPrinter that renders progress for a person
// (one redrawn line) and for a program (key=value lines).
#include <cinttypes>
#include <cstdio>

#include "glint/core/cancel.h"
#include "glint/core/error.h"
#include "glint/core/log.h"
#include "glint/core/progress.h"

namespace glint {

const char* log_level_name(LogLevel level) {
    switch (level) {
        case LogLevel::error:
            return "error";
        case LogLevel::warning:
            return "warning";
        case LogLevel::notice:
            return "notice";
        case LogLevel::info:
            return "info";
        case LogLevel::debug:
            return "debug";
    }
    return "log";
}

void CancelToken::throw_if_cancelled() const {
    if (cancelled()) throw Error(ErrorCategory::cancelled, "interrupted");
}

namespace {

constexpr auto kRedrawInterval = std::chrono::milliseconds(100);

double percent_of(const ProgressUpdate& update) {
    if (update.total == 0) return update.finished ? 100.0 : 0.0;
    return 100.0 * static_cast<double>(update.done) / static_cast<double>(update.total);
}

}  // namespace

ProgressPrinter::ProgressPrinter(std::ostream* terminal, std::ostream* machine)
    : m_terminal(terminal),
      m_machine(machine),
      m_start(std::chrono::steady_clock::now()),
      m_last_draw(m_start - kRedrawInterval),
      m_stage_start(m_start) {}

void ProgressPrinter::operator()(const ProgressUpdate& update) {
    const auto now = std::chrono::steady_clock::now();
    const bool new_stage = update.label != m_last_label;
    if (new_stage) m_stage_start = now;
    if (!update.finished && !new_stage && now - m_last_draw < kRedrawInterval) return;
    m_last_draw = now;
    m_last_label = update.label;
    const double elapsed_s = std::chrono::duration<double>(now - m_start).count();
    const double stage_s = std::chrono::duration<double>(now - m_stage_start).count();
    const double percent = percent_of(update);
    // Rate and remaining time of this stage (label); unknown (−1) before anything is done.
    const double rate =
        stage_s > 0.0 && update.done > 0 ? static_cast<double>(update.done) / stage_s : -1.0;
    const double eta_s = rate > 0.0 && update.total >= update.done
                             ? static_cast<double>(update.total - update.done) / rate
                             : -1.0;
    char text[200];
    if (m_machine != nullptr) {
        std::snprintf(text, sizeof text,
                      " done=%" PRIu64 " total=%" PRIu64
                      " percent=%.1f elapsed_s=%.3f rate_per_s=%.6g eta_s=%.3f state=%s\n",
                      update.done, update.total, percent, elapsed_s, rate, eta_s,
                      update.finished ? "finished" : "running");
        *m_machine << "label=" << update.label << text;
        m_machine->flush();
    }
    if (m_terminal != nullptr) {
        if (rate > 0.0 && !update.finished) {
            std::snprintf(text, sizeof text,
                          " %5.1f%% (%" PRIu64 "/%" PRIu64 ") %.1fs, %.4g/s, ETA %.0fs", percent,
                          update.done, update.total, elapsed_s, rate, eta_s);
        } else {
            std::snprintf(text, sizeof text, " %5.1f%% (%" PRIu64 "/%" PRIu64 ") %.1fs", percent,
                          update.done, update.total, elapsed_s);
        }
        *m_terminal << "\r\033[K" << update.label << text;
        m_line_open = !update.finished;
        if (update.finished) *m_terminal << '\n';
        m_terminal->flush();
    }
}

}  // namespace glint
