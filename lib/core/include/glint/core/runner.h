// SPDX-License-Identifier: Apache-2.0
// The tool runner that wraps every glint-<tool> main: builds the CLI11 app with the common
// flags, parses, sets up the Context (stderr log, progress, stop signals → cancel) and maps
// the outcome to the documented exit status:
//   0 success; 1 runtime/data failure; 2 usage error (every CLI11 parse error);
//   128 + N stopped by signal N (130 SIGINT, 143 SIGTERM, 129 SIGHUP, 141 SIGPIPE, ...),
//   temporary files removed. --help and --version print to stdout and exit 0.
// Diagnostics are one line on stderr: "glint-<tool>: error: <message>".
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <ostream>
#include <string>

#include "glint/core/context.h"

namespace glint {

/// Exit statuses of every glint tool.
inline constexpr int kExitSuccess = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;
inline constexpr int kExitInterrupted = 130;

/// Values of the flags every tool shares.
struct CommonOptions {
    int verbosity = 0;                  ///< -v count
    bool quiet = false;                 ///< -q: errors only, no progress
    std::string progress_file;          ///< --progress FILE: key=value progress lines
    unsigned threads = 0;               ///< --threads N (0 = all cores)
    std::uint64_t seed = kDefaultSeed;  ///< --seed N
    std::size_t max_memory_bytes = kDefaultMaxMemoryBytes;  ///< --max-memory SIZE
};

/// Which optional common flags a tool offers (help, version, verbose, quiet and progress are
/// always there).
enum CommonFlag : unsigned {
    kCommonBasic = 0,
    kCommonThreads = 1u << 0,
    kCommonSeed = 1u << 1,
    kCommonMaxMemory = 1u << 2,
};

/// A CLI11 check for options holding unsigned whole numbers: decimal digits only, at most
/// `max`. CLI11 itself reads "-1" into an unsigned as 2^64 - 1 and saturates on overflow;
/// with this check both are usage errors naming the option's range.
CLI::Validator whole_number(std::uint64_t max = UINT64_MAX);

/// A CLI11 check for sizes in bytes (parse_byte_size): above 0 and at most SIZE_MAX, else a
/// usage error naming the value and an example.
CLI::Validator byte_size();

/// The CPUs this process may run on (its affinity mask; the hardware's threads where there
/// is none), at least 1.
unsigned available_cpus();

/// Adds -v/--verbose, -q/--quiet, --progress and, per `which`, --threads, --seed and
/// --max-memory.
void add_common_flags(CLI::App& app, CommonOptions& options, unsigned which);

/// What the runner needs to know about a tool.
struct ToolSpec {
    std::string name;         ///< short name: "envi" gives the program name "glint-envi"
    std::string description;  ///< one line for --help
    unsigned common_flags = kCommonBasic;
};

/// Where a tool's output goes. The library never names stdout or stderr itself: a tool's
/// main hands them in (`{std::cout, std::cerr, isatty(STDERR_FILENO) != 0}`).
struct ToolStreams {
    std::ostream& out;             ///< data and reports (stdout); --help and --version
    std::ostream& err;             ///< diagnostics, logs and the progress line (stderr)
    bool err_is_terminal = false;  ///< redraw a progress line and colour diagnostics
};

/// glint version, e.g. "0.1.0".
const char* version();

/// Runs a tool, writing to `streams`. `configure` adds the tool's options and subcommands to the
/// app; after a successful parse `execute` runs with the context and returns the exit status (0, or
/// 1 when some of several inputs failed). glint::Error and other exceptions thrown by `execute` are
/// reported as one line and mapped to 1, 2 (usage) or 130 (cancelled).
int run_tool(const ToolSpec& spec, int argc, const char* const* argv, const ToolStreams& streams,
             const std::function<void(CLI::App&)>& configure,
             const std::function<int(Context&)>& execute);

/// Formats a diagnostic line "glint-<tool>: <level>: <message>" (colour when `colour`), the
/// message through printable_message.
std::string format_diagnostic(const std::string& program, const std::string& level,
                              const std::string& message, bool colour);

/// "error:", "warning:" (bold and coloured when `colour`).
std::string diagnostic_label(const std::string& level, bool colour);

/// A message as the tools print it on stderr: terminal_safe (glint/core/text.h: no control
/// or bidi character from an input file reaches the terminal) and every line after the
/// first indented by two spaces, so no text a file holds can pass for a line of glint's own.
std::string printable_message(const std::string& message);

}  // namespace glint
