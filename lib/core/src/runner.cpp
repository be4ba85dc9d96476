// SPDX-License-Identifier: Apache-2.0
// The tool runner: common flags, CLI11 parsing, the stderr log sink, progress printing,
// stop signals → cancellation, and the mapping from outcomes to exit statuses.
#include "glint/core/runner.h"

#if defined(__linux__)
#include <sched.h>
#endif
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>
#include <new>
#include <thread>

#include "glint/core/error.h"
#include "glint/core/progress.h"
#include "glint/core/temporary_files.h"
#include "glint/core/text.h"

#ifndef GLINT_VERSION_STRING
#error "GLINT_VERSION_STRING must be defined by the build"
#endif

namespace glint {
namespace {

// The process-wide state a signal handler needs (it can reach nothing else): the running
// tool's cancel flag, for the duration of run_tool only, and the signal that raised it.
std::atomic<bool>* g_interrupt_flag = nullptr;
volatile std::sig_atomic_t g_interrupt_signal = 0;
/// Signal numbers are below this on Linux (_NSIG is 65).
constexpr int kMaxSignal = 65;
/// Which stop signals arrived once already (the next of the same kind ends the process).
volatile std::sig_atomic_t g_signal_seen[kMaxSignal] = {};

/// Signals whose default action ends the process and that a tool turns into a clean stop:
/// the cancel flag is raised, the work stops at its next check, temporary files are removed
/// and the exit status is 128 + the signal's number. (SIGKILL cannot be caught; SIGXFSZ is
/// ignored instead, so that writing past the file-size limit fails with EFBIG and is
/// reported like a full disk.)
constexpr int kStopSignals[] = {SIGINT,  SIGTERM, SIGHUP,  SIGQUIT,   SIGPIPE, SIGALRM,
                                SIGUSR1, SIGUSR2, SIGXCPU, SIGVTALRM, SIGPROF};
constexpr std::size_t kStopSignalCount = std::size(kStopSignals);

extern "C" void on_interrupt(int signal_number) {
    if (g_interrupt_flag != nullptr) g_interrupt_flag->store(true);
    if (g_interrupt_signal == 0) g_interrupt_signal = signal_number;
    // A second interrupt of the same kind ends the process at once — except SIGPIPE, which
    // every further write to the closed pipe raises again — after removing the temporary
    // files the unwinding would have removed (async-signal-safe: unlink only).
    if (signal_number == SIGPIPE || signal_number <= 0 || signal_number >= kMaxSignal) return;
    if (g_signal_seen[signal_number] == 0) {
        g_signal_seen[signal_number] = 1;
        return;
    }
    temporary_files::unlink_all();
    struct sigaction action {};
    action.sa_handler = SIG_DFL;
    sigemptyset(&action.sa_mask);
    sigaction(signal_number, &action, nullptr);
    ::raise(signal_number);  // delivered when the handler returns: the default action
}

/// Routes the stop signals to a cancel flag and ignores SIGXFSZ while alive.
class InterruptGuard {
public:
    explicit InterruptGuard(std::atomic<bool>* flag) {
        g_interrupt_flag = flag;
        g_interrupt_signal = 0;
        for (volatile std::sig_atomic_t& seen : g_signal_seen) seen = 0;
        struct sigaction action {};
        action.sa_handler = on_interrupt;
        sigemptyset(&action.sa_mask);
        for (std::size_t i = 0; i < kStopSignalCount; ++i) {
            sigaction(kStopSignals[i], &action, &m_old[i]);
        }
        struct sigaction ignore {};
        ignore.sa_handler = SIG_IGN;
        sigemptyset(&ignore.sa_mask);
        sigaction(SIGXFSZ, &ignore, &m_old_xfsz);
    }
    ~InterruptGuard() {
        for (std::size_t i = 0; i < kStopSignalCount; ++i) {
            sigaction(kStopSignals[i], &m_old[i], nullptr);
        }
        sigaction(SIGXFSZ, &m_old_xfsz, nullptr);
        g_interrupt_flag = nullptr;
    }
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

    /// The signal that raised the flag, 0 when none did.
    int signal_number() const { return static_cast<int>(g_interrupt_signal); }

private:
    struct sigaction m_old[kStopSignalCount] {};
    struct sigaction m_old_xfsz {};
};

/// Whether stderr is a terminal that understands ANSI escapes (TERM is not "dumb"): the
/// progress line and its clearing need them.
bool ansi_terminal(bool terminal) {
    const char* term = std::getenv("TERM");
    return terminal && (term == nullptr || std::string(term) != "dumb");
}

/// Colour too, unless NO_COLOR is set (https://no-color.org).
bool wants_colour(bool terminal) {
    const char* no_colour = std::getenv("NO_COLOR");
    return ansi_terminal(terminal) && (no_colour == nullptr || *no_colour == '\0');
}

std::string lowercase_first(std::string text) {
    if (!text.empty() && std::isupper(static_cast<unsigned char>(text[0])) &&
        (text.size() < 2 || !std::isupper(static_cast<unsigned char>(text[1])))) {
        text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
    }
    while (!text.empty() && (text.back() == '.' || text.back() == '\n')) text.pop_back();
    return text;
}

/// The latest SOURCE_DATE_EPOCH accepted: 9999-12-31 23:59:59 UTC, the last second a
/// four-digit year (TIFF's "YYYY:MM:DD hh:mm:ss") can write.
constexpr std::int64_t kLatestSourceDateEpoch_s = 253402300799;

/// "SIGHUP" for SIGHUP, and so on for the stop signals.
std::string signal_name(int signal_number) {
    switch (signal_number) {
        case SIGINT:
            return "SIGINT";
        case SIGTERM:
            return "SIGTERM";
        case SIGHUP:
            return "SIGHUP";
        case SIGQUIT:
            return "SIGQUIT";
        case SIGPIPE:
            return "SIGPIPE";
        case SIGALRM:
            return "SIGALRM";
        case SIGUSR1:
            return "SIGUSR1";
        case SIGUSR2:
            return "SIGUSR2";
        case SIGXCPU:
            return "SIGXCPU";
        case SIGVTALRM:
            return "SIGVTALRM";
        case SIGPROF:
            return "SIGPROF";
        default:
            return "signal " + std::to_string(signal_number);
    }
}

int exit_status_for(ErrorCategory category) {
    switch (category) {
        case ErrorCategory::usage:
            return kExitUsage;
        case ErrorCategory::cancelled:
            return kExitInterrupted;
        default:
            return kExitFailure;
    }
}

}  // namespace

const char* version() { return GLINT_VERSION_STRING; }

std::string format_diagnostic(const std::string& program, const std::string& level,
                              const std::string& message, bool colour) {
    return program + ": " + diagnostic_label(level, colour) + " " + printable_message(message);
}

std::string printable_message(const std::string& message) {
    const std::string safe = terminal_safe(message);
    std::string out;
    out.reserve(safe.size());
    for (char c : safe) {
        out += c;
        if (c == '\n') out += "  ";
    }
    return out;
}

std::string diagnostic_label(const std::string& level, bool colour) {
    std::string label = level + ":";
    if (colour) {
        const char* code = level == "error"     ? "\033[1;31m"
                           : level == "warning" ? "\033[1;35m"
                                                : "\033[1m";
        label = code + label + "\033[0m";
    }
    return label;
}

CLI::Validator whole_number(std::uint64_t max) {
    const std::string range = "a whole number from 0 to " + std::to_string(max);
    return CLI::Validator(
        [max, range](std::string& text) -> std::string {
            std::uint64_t value = 0;
            const char* end = text.data() + text.size();
            const auto [ptr, ec] = std::from_chars(text.data(), end, value);
            if (text.empty() || ptr != end || ec != std::errc() || value > max) {
                return quote(text) + " is not " + range;
            }
            return {};
        },
        "", "whole number");
}

CLI::Validator byte_size() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            const std::optional<std::uint64_t> bytes = parse_byte_size(text);
            if (!bytes || *bytes == 0 || *bytes > SIZE_MAX) {
                return quote(text) + " is not a size in bytes above 0 (such as 512M, 1.5G or 8G)";
            }
            return {};
        },
        "", "size");
}

unsigned available_cpus() {
#if defined(__linux__)
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof set, &set) == 0) {
        const int count = CPU_COUNT(&set);
        if (count > 0) return static_cast<unsigned>(count);
    }
#endif
    return std::max(1u, std::thread::hardware_concurrency());
}

void add_common_flags(CLI::App& app, CommonOptions& options, unsigned which) {
    app.add_flag("-v,--verbose", options.verbosity, "More messages on stderr (-v info, -vv debug)");
    app.add_flag("-q,--quiet", options.quiet, "Only errors on stderr; no progress line");
    app.add_option("--progress", options.progress_file,
                   "Append machine-readable progress (key=value lines) to FILE")
        ->type_name("FILE");
    if ((which & kCommonThreads) != 0) {
        app.add_option("--threads", options.threads, "Worker threads (0 = all cores)")
            ->check(whole_number(std::numeric_limits<unsigned>::max()))
            ->type_name("N");
    }
    if ((which & kCommonSeed) != 0) {
        app.add_option("--seed", options.seed,
                       "Seed of every random stream (same seed, same bytes)")
            ->check(whole_number())
            ->type_name("N")
            ->capture_default_str();
    }
    if ((which & kCommonMaxMemory) != 0) {
        app.add_option_function<std::string>(
               "--max-memory",
               [&options](const std::string& text) {
                   options.max_memory_bytes = static_cast<std::size_t>(*parse_byte_size(text));
               },
               "Working memory for line buffers: bytes, or with K, M, G, T (powers of 1024); "
               "wider inputs are refused with what they need (default 4G)")
            ->check(byte_size())
            ->type_name("SIZE");
    }
}

int run_tool(const ToolSpec& spec, int argc, const char* const* argv, const ToolStreams& streams,
             const std::function<void(CLI::App&)>& configure,
             const std::function<int(Context&)>& execute) {
    const std::string program = "glint-" + spec.name;
    std::ostream& err = streams.err;
    const bool colour = wants_colour(streams.err_is_terminal);
    auto report = [&](const std::string& level, const std::string& message) {
        err << format_diagnostic(program, level, message, colour) << '\n';
    };

    CLI::App app{spec.description, program};
    app.set_version_flag("--version", program + " " + version());
    CommonOptions common;
    try {
        add_common_flags(app, common, spec.common_flags);
        configure(app);
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) {
            app.exit(e, streams.out, err);  // --help, --help-all, --version: stdout
            return kExitSuccess;
        }
        // CLI11 checks required arguments before unknown ones, so `--bogus` alone would be
        // reported as a missing input: name what was not understood first.
        std::string message = lowercase_first(e.what());
        if (dynamic_cast<const CLI::RequiredError*>(&e) != nullptr) {
            const std::vector<std::string> extras = app.remaining(true);
            if (!extras.empty()) {
                message = std::string("the following argument") +
                          (extras.size() == 1 ? " was" : "s were") +
                          " not expected: " + join(extras, " ");
            }
        }
        report("error", message + " (see " + program + " --help)");
        return kExitUsage;
    } catch (const Error& e) {
        report("error", e.what());
        return exit_status_for(e.category());
    }

    Context context;
    context.threads = common.threads;
    context.seed = common.seed;
    context.max_memory_bytes = common.max_memory_bytes;
    // The program by its name, not the path it was started from: the provenance in outputs
    // stays the same wherever glint is installed.
    context.arguments.assign(argv, argv + argc);
    if (!context.arguments.empty()) context.arguments.front() = program;
    if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH")) {
        const std::optional<std::int64_t> seconds = parse_int(epoch);
        if (!seconds || *seconds < 0 || *seconds > kLatestSourceDateEpoch_s) {
            report("error", "SOURCE_DATE_EPOCH " + quote(epoch) +
                                " is not a whole number of seconds since 1970 (0 to " +
                                std::to_string(kLatestSourceDateEpoch_s) + ")");
            return kExitUsage;
        }
        context.source_date_epoch_s = seconds;
    }
    const LogLevel threshold = common.quiet            ? LogLevel::error
                               : common.verbosity >= 2 ? LogLevel::debug
                               : common.verbosity == 1 ? LogLevel::info
                                                       : LogLevel::notice;
    const bool terminal_progress = !common.quiet && ansi_terminal(streams.err_is_terminal);
    context.log = Log(
        [&](LogLevel level, const std::string& message) {
            if (terminal_progress) err << "\r\033[K";
            if (level == LogLevel::notice || level == LogLevel::info) {
                err << program << ": " << printable_message(message) << '\n';
            } else {
                report(log_level_name(level), message);
            }
        },
        threshold);

    // More threads than the CPUs this process may use: the thread pool would drop the extra
    // workers with a message of its own; say it once here and use the CPUs there are (the
    // bytes written never depend on the thread count).
    if (const unsigned cpus = available_cpus(); context.threads > cpus) {
        context.log.warning("--threads " + std::to_string(context.threads) +
                            ": this process may run on " + std::to_string(cpus) +
                            (cpus == 1 ? " CPU" : " CPUs") + "; using " + std::to_string(cpus) +
                            (cpus == 1 ? " thread" : " threads"));
        context.threads = cpus;
    }

    std::ofstream progress_file;
    if (!common.progress_file.empty()) {
        progress_file.open(common.progress_file, std::ios::out | std::ios::app);
        if (!progress_file) {
            report("error", common.progress_file + ": cannot open progress file");
            return kExitFailure;
        }
    }
    auto printer = std::make_shared<ProgressPrinter>(
        terminal_progress ? &err : nullptr, progress_file.is_open() ? &progress_file : nullptr);
    if (terminal_progress || progress_file.is_open()) {
        context.progress = Progress([printer](const ProgressUpdate& u) { (*printer)(u); });
    }

    int status = kExitFailure;
    int stop_signal = 0;
    {
        InterruptGuard guard(context.cancel.flag_for_signal_handler());
        const auto stopped_by = [&] { return guard.signal_number(); };
        try {
            status = execute(context);
        } catch (const Error& e) {
            if (terminal_progress) err << "\r\033[K";
            // A closed pipe downstream (`| head`) is not worth a message, as for any tool.
            if (!(e.category() == ErrorCategory::cancelled && stopped_by() == SIGPIPE)) {
                const int signal_number = stopped_by();
                report("error", e.category() == ErrorCategory::cancelled && signal_number != 0
                                    ? e.message() + " (" + signal_name(signal_number) + ")"
                                    : std::string(e.what()));
            }
            status = exit_status_for(e.category());
        } catch (const CLI::Error& e) {
            report("error", lowercase_first(e.what()));
            status = kExitUsage;
        } catch (const std::bad_alloc&) {
            report("error", "out of memory");
            status = kExitFailure;
        } catch (const std::exception& e) {
            report("error", std::string("internal error: ") + e.what());
            status = kExitFailure;
        }
        stop_signal = stopped_by();
    }
    if (context.cancel.cancelled() && status != kExitSuccess) {
        status = stop_signal != 0 ? 128 + stop_signal : kExitInterrupted;
    }
    if (stop_signal == SIGPIPE) return status;  // stdout is gone: nothing to flush or report
    streams.out.flush();
    if (!streams.out) {
        report("error", "cannot write to standard output");
        return kExitFailure;
    }
    return status;
}

}  // namespace glint
