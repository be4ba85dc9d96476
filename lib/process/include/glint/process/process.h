// SPDX-License-Identifier: Apache-2.0
// Running external programs safely: an argv vector (never a shell), stdin from /dev/null,
// the child in its own process group (so that a timeout or a cancelled run can kill it and
// everything it started), bounded capture of its stderr and, optionally, its stdout.
// Every external program glint runs (ffmpeg, processing tasks) goes through run_process().
#pragma once

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "glint/core/cancel.h"
#include "glint/core/text.h"

namespace glint::process {

/// What happens to the child's stdout.
enum class OutputMode {
    discard,  ///< /dev/null (the default: a tool's stdout carries only its own data)
    capture,  ///< kept in ProcessResult::stdout_text (bounded, like stderr)
    inherit,  ///< the parent's stdout
};

/// How to run a program.
struct ProcessOptions {
    /// argv[0] is the program: a path when it contains '/', else looked up on PATH.
    std::vector<std::string> argv;
    /// Working directory of the child; empty = the parent's.
    std::filesystem::path working_directory;
    /// Environment variables set (or replaced) in the child's copy of the environment.
    std::vector<std::pair<std::string, std::string>> environment;
    /// Wall-clock limit; when it passes the process group gets SIGTERM, then SIGKILL after
    /// `kill_grace`, and the result says `timed_out`.
    std::optional<std::chrono::milliseconds> timeout;
    std::chrono::milliseconds kill_grace{2000};
    /// Polled while the child runs; once raised the group is killed and run_process throws
    /// glint::Error(cancelled).
    std::optional<CancelToken> cancel;
    OutputMode stdout_mode = OutputMode::discard;
    /// Captured streams keep at most this many bytes: the last ones (the end of a
    /// program's stderr is where its error message is).
    std::size_t capture_limit_bytes = 64 * 1024;
};

/// How a program ended.
struct ProcessResult {
    int exit_code = -1;  ///< exit status when the program exited, else -1
    int signal = 0;      ///< the signal that killed it, else 0
    bool timed_out = false;
    double timeout_s = 0;     ///< the time limit it ran under (0 = none)
    std::string stdout_text;  ///< captured stdout (OutputMode::capture)
    std::string stderr_text;  ///< captured stderr (the last capture_limit_bytes bytes)
    bool stdout_truncated = false;
    bool stderr_truncated = false;

    /// True when the program exited with status 0 within its time limit.
    bool success() const { return !timed_out && signal == 0 && exit_code == 0; }
    /// "exited with status 1", "killed by signal 9 (Killed)", "timed out after 2.5 s", ...
    std::string describe() const;
};

/// Runs a program to completion. Throws glint::Error (io) when the program cannot be found
/// or started, (usage) for an empty argv, (cancelled) when the token is raised meanwhile.
/// A non-zero exit status is not an error here: check ProcessResult::success().
ProcessResult run_process(const ProcessOptions& options);

/// The executable `name` resolves to: `name` itself when it contains '/' (if executable),
/// else the first executable regular file `<dir>/<name>` for the directories of `path_env`
/// (the PATH variable when null). Empty PATH entries mean the current directory.
std::optional<std::filesystem::path> find_program(std::string_view name,
                                                  const char* path_env = nullptr);

}  // namespace glint::process
