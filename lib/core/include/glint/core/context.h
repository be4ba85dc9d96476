// SPDX-License-Identifier: Apache-2.0
// The per-run context every tool entry point receives: log, progress, cancellation and the
// common options (threads, seed) and the command line. No state lives anywhere else.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/cancel.h"
#include "glint/core/log.h"
#include "glint/core/progress.h"
#include "glint/core/text.h"

namespace glint {

/// Default `--seed` of every tool: fixed, so that two runs without --seed are identical.
inline constexpr std::uint64_t kDefaultSeed = 1;

/// Default `--max-memory` of the tools that read images line by line: what their line
/// buffers and windows of lines may take together.
inline constexpr std::size_t kDefaultMaxMemoryBytes = std::size_t{4} << 30;

/// What a library entry point needs besides its options.
struct Context {
    Log log;
    Progress progress;
    CancelToken cancel;
    unsigned threads = 0;  ///< 0 = all hardware threads
    std::uint64_t seed = kDefaultSeed;
    /// --max-memory: the working memory a line-by-line tool may plan for its buffers; inputs
    /// that would need more are refused with what they need.
    std::size_t max_memory_bytes = kDefaultMaxMemoryBytes;
    /// The command line, program first by its name ("glint-render"), the arguments as typed
    /// (the runner records it once; outputs carry it as provenance). Empty when a library
    /// entry point is called directly.
    std::vector<std::string> arguments;
    /// SOURCE_DATE_EPOCH (seconds since 1970 UTC) when the environment sets it: the one
    /// date-time outputs may record. Unset, outputs record none, so identical runs give
    /// identical bytes.
    std::optional<std::int64_t> source_date_epoch_s;

    /// The arguments as one shell-quoted line (format_command_line), for ENVI headers.
    std::string command_line() const { return format_command_line(arguments); }
};

}  // namespace glint
