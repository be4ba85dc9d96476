// SPDX-License-Identifier: Apache-2.0
// Logging through an injected sink. Library code logs through a Log it was handed; only the
// tool runner decides that the sink is stderr.
#pragma once

#include <functional>
#include <string>

namespace glint {

/// Severity of a log message, most severe first. `notice` is shown at normal verbosity
/// without a label (what a run does that a user must see: the commands it starts); `info`
/// needs -v, `debug` -vv.
enum class LogLevel { error = 0, warning = 1, notice = 2, info = 3, debug = 4 };

/// Name of a level as printed in diagnostics ("error", "warning", "notice", "info", "debug").
const char* log_level_name(LogLevel level);

/// A cheap-to-copy handle that forwards messages at or above a threshold to a sink.
/// A default-constructed Log discards everything.
class Log {
public:
    using Sink = std::function<void(LogLevel, const std::string&)>;

    Log() = default;
    Log(Sink sink, LogLevel threshold) : m_sink(std::move(sink)), m_threshold(threshold) {}

    bool enabled(LogLevel level) const { return m_sink && level <= m_threshold; }
    void write(LogLevel level, const std::string& message) const {
        if (enabled(level)) m_sink(level, message);
    }
    void error(const std::string& message) const { write(LogLevel::error, message); }
    void warning(const std::string& message) const { write(LogLevel::warning, message); }
    void notice(const std::string& message) const { write(LogLevel::notice, message); }
    void info(const std::string& message) const { write(LogLevel::info, message); }
    void debug(const std::string& message) const { write(LogLevel::debug, message); }

private:
    Sink m_sink;
    LogLevel m_threshold = LogLevel::warning;
};

}  // namespace glint
