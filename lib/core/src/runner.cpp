// SPDX-License-Identifier: Apache-2.0
// The tool runner: common flags, CLI11 parsing, the stderr log sink, progress printing,
// SIGINT → cancellation, and the mapping from outcomes to exit statuses.
#include "glint/core/runner.h"

#include <cctype>
#include <charconv>
#include <csignal>
#include <fstream>
#include <limits>
#include <memory>
#include <new>

#include "glint/core/error.h"
#include "glint/core/progress.h"
#include "glint/core/text.h"

#ifndef GLINT_VERSION_STRING
#error "GLINT_VERSION_STRING must be defined by the build"
#endif

namespace glint {
namespace {

// The one piece of process-wide state: a signal handler can reach nothing else. It points at
// the running tool's cancel flag for the duration of run_tool only.
std::atomic<bool>* g_interrupt_flag = nullptr;

extern "C" void on_interrupt(int signal_number) {
    if (g_interrupt_flag != nullptr) g_interrupt_flag->store(true);
    // A second interrupt ends the process at once.
    struct sigaction action {};
    action.sa_handler = SIG_DFL;
    sigemptyset(&action.sa_mask);
    sigaction(signal_number, &action, nullptr);
}

/// Routes SIGINT and SIGTERM to a cancel flag while alive.
class InterruptGuard {
public:
    explicit InterruptGuard(std::atomic<bool>* flag) {
        g_interrupt_flag = flag;
        struct sigaction action {};
        action.sa_handler = on_interrupt;
        sigemptyset(&action.sa_mask);
        sigaction(SIGINT, &action, &m_old_int);
        sigaction(SIGTERM, &action, &m_old_term);
    }
    ~InterruptGuard() {
        sigaction(SIGINT, &m_old_int, nullptr);
        sigaction(SIGTERM, &m_old_term, nullptr);
        g_interrupt_flag = nullptr;
    }
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

private:
    struct sigaction m_old_int {};
    struct sigaction m_old_term {};
};

bool wants_colour(bool terminal) {
    if (!terminal) return false;
    const char* no_colour = std::getenv("NO_COLOR");
    const char* term = std::getenv("TERM");
    return (no_colour == nullptr || *no_colour == '\0') &&
           (term == nullptr || std::string(term) != "dumb");
}

std::string lowercase_first(std::string text) {
    if (!text.empty() && std::isupper(static_cast<unsigned char>(text[0])) &&
        (text.size() < 2 || !std::isupper(static_cast<unsigned char>(text[1])))) {
        text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
    }
    while (!text.empty() && (text.back() == '.' || text.back() == '\n')) text.pop_back();
    return text;
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
    std::string label = level + ":";
    if (colour) {
        const char* code = level == "error"     ? "\033[1;31m"
                           : level == "warning" ? "\033[1;35m"
                                                : "\033[1m";
        label = code + label + "\033[0m";
    }
    return program + ": " + label + " " + message;
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
        report("error", lowercase_first(e.what()) + " (see " + program + " --help)");
        return kExitUsage;
    } catch (const Error& e) {
        report("error", e.what());
        return exit_status_for(e.category());
    }

    Context context;
    context.threads = common.threads;
    context.seed = common.seed;
    // The program by its name, not the path it was started from: the provenance in outputs
    // stays the same wherever glint is installed.
    context.arguments.assign(argv, argv + argc);
    if (!context.arguments.empty()) context.arguments.front() = program;
    const LogLevel threshold = common.quiet            ? LogLevel::error
                               : common.verbosity >= 2 ? LogLevel::debug
                               : common.verbosity == 1 ? LogLevel::info
                                                       : LogLevel::warning;
    const bool terminal_progress = !common.quiet && streams.err_is_terminal;
    context.log = Log(
        [&](LogLevel level, const std::string& message) {
            if (terminal_progress) err << "\r\033[K";
            if (level == LogLevel::info) {
                err << program << ": " << message << '\n';
            } else {
                report(log_level_name(level), message);
            }
        },
        threshold);

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
    {
        InterruptGuard guard(context.cancel.flag_for_signal_handler());
        try {
            status = execute(context);
        } catch (const Error& e) {
            if (terminal_progress) err << "\r\033[K";
            report("error", e.what());
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
    }
    if (context.cancel.cancelled() && status != kExitSuccess) status = kExitInterrupted;
    streams.out.flush();
    if (!streams.out) {
        report("error", "cannot write to standard output");
        return kExitFailure;
    }
    return status;
}

}  // namespace glint
