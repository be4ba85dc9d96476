// SPDX-License-Identifier: Apache-2.0
// The tool runner: exit statuses, where --help/--version/diagnostics go, common flags,
// log thresholds, progress files and SIGINT.
#include "glint/core/runner.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "glint/core/atomic_file.h"
#include "glint/core/error.h"
#include "glint/core/temporary_files.h"
#include "glint/test/temp_dir.h"

namespace glint {
namespace runner_test {

using ::testing::HasSubstr;
using ::testing::Not;

struct Outcome {
    int status;
    std::string out;
    std::string err;
};

Outcome run(std::vector<std::string> args, const std::function<int(Context&)>& execute,
            unsigned flags = kCommonThreads | kCommonSeed) {
    args.insert(args.begin(), "glint-demo");
    std::vector<const char*> argv;
    for (const auto& a : args) argv.push_back(a.c_str());
    std::string name;
    std::ostringstream out, err;
    const int status = run_tool(
        ToolSpec{"demo", "A demonstration tool", flags}, static_cast<int>(argv.size()), argv.data(),
        ToolStreams{out, err, false},
        [&](CLI::App& app) { app.add_option("--name", name, "A name"); }, execute);
    return Outcome{status, out.str(), err.str()};
}

int succeed(Context&) { return kExitSuccess; }

TEST(Runner, HelpGoesToStdoutAndExitsZero) {
    const Outcome o = run({"--help"}, succeed);
    EXPECT_EQ(o.status, 0);
    EXPECT_THAT(o.out, HasSubstr("glint-demo"));
    EXPECT_THAT(o.out, HasSubstr("--threads"));
    EXPECT_THAT(o.out, HasSubstr("--seed"));
    EXPECT_EQ(o.err, "");
}

TEST(Runner, VersionGoesToStdoutAndExitsZero) {
    const Outcome o = run({"--version"}, succeed);
    EXPECT_EQ(o.status, 0);
    EXPECT_EQ(o.out, std::string("glint-demo ") + version() + "\n");
}

TEST(Runner, RecordsTheCommandLineOnceInTheContext) {
    // argv[0] as started (a path) becomes the program's name, so provenance does not depend
    // on where glint is installed; the arguments stay as typed, quoted where needed.
    std::vector<std::string> arguments;
    std::string line;
    std::vector<std::string> args{"/opt/x/bin/glint-demo", "--name", "a b", "--seed", "7"};
    std::vector<const char*> argv;
    for (const auto& a : args) argv.push_back(a.c_str());
    std::string name;
    std::ostringstream out, err;
    const int status = run_tool(
        ToolSpec{"demo", "A demonstration tool", kCommonSeed}, static_cast<int>(argv.size()),
        argv.data(), ToolStreams{out, err, false},
        [&](CLI::App& app) { app.add_option("--name", name, "A name"); },
        [&](Context& ctx) {
            arguments = ctx.arguments;
            line = ctx.command_line();
            return kExitSuccess;
        });
    EXPECT_EQ(status, 0) << err.str();
    EXPECT_EQ(arguments, (std::vector<std::string>{"glint-demo", "--name", "a b", "--seed", "7"}));
    EXPECT_EQ(line, "glint-demo --name 'a b' --seed 7");
    EXPECT_TRUE(Context{}.arguments.empty());  // a library call made directly records none
    EXPECT_EQ(Context{}.command_line(), "");
}

TEST(Runner, BadFlagIsAUsageErrorOnOneLine) {
    bool ran = false;
    const Outcome o = run({"--bogus"}, [&](Context&) {
        ran = true;
        return 0;
    });
    EXPECT_EQ(o.status, kExitUsage);
    EXPECT_FALSE(ran);
    EXPECT_EQ(o.out, "");
    EXPECT_THAT(o.err, HasSubstr("glint-demo: error: "));
    EXPECT_THAT(o.err, HasSubstr("--bogus"));
    EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1);
}

TEST(Runner, ErrorsMapToExitStatuses) {
    auto thrower = [](Error e) { return [e](Context&) -> int { throw e; }; };
    Outcome o = run({}, thrower(input_error("bad value", ErrorContext{"f.txt", 3, "<x>"})));
    EXPECT_EQ(o.status, kExitFailure);
    EXPECT_EQ(o.err, "glint-demo: error: f.txt:3: <x>: bad value\n");
    EXPECT_EQ(run({}, thrower(usage_error("two outputs"))).status, kExitUsage);
    EXPECT_EQ(run({}, thrower(io_error("disk full", "a.img"))).status, kExitFailure);
    EXPECT_EQ(run({}, thrower(Error(ErrorCategory::cancelled, "interrupted"))).status,
              kExitInterrupted);
    o = run({}, [](Context&) -> int { throw std::logic_error("boom"); });
    EXPECT_EQ(o.status, kExitFailure);
    EXPECT_THAT(o.err, HasSubstr("internal error: boom"));
    EXPECT_EQ(run({}, [](Context&) { return kExitFailure; }).status, kExitFailure);
}

TEST(Runner, MoreThreadsThanCpusAreSaidOnceAndClamped) {
    // The thread pool cannot run more workers than the CPUs the process may use: glint says
    // so in its own words and uses those CPUs (the bytes do not depend on the count).
    const unsigned cpus = available_cpus();
    ASSERT_GE(cpus, 1u);
    Context seen;
    const Outcome o = run({"--threads", std::to_string(cpus + 5)}, [&](Context& c) {
        seen = c;
        return 0;
    });
    EXPECT_EQ(o.status, 0);
    EXPECT_EQ(seen.threads, cpus);
    EXPECT_THAT(o.err, HasSubstr("warning: --threads " + std::to_string(cpus + 5) +
                                 ": this process may run on " + std::to_string(cpus)));
    const Outcome fits = run({"--threads", std::to_string(cpus)}, [&](Context& c) {
        seen = c;
        return 0;
    });
    EXPECT_EQ(seen.threads, cpus);
    EXPECT_THAT(fits.err, Not(HasSubstr("warning")));
}

TEST(Runner, CommonFlagsReachTheContext) {
    Context seen;
    const Outcome o = run({"--seed", "42", "--threads", "3"}, [&](Context& c) {
        seen = c;
        return 0;
    });
    EXPECT_EQ(o.status, 0);
    EXPECT_EQ(seen.seed, 42u);
    EXPECT_EQ(seen.threads, std::min(3u, available_cpus()));
    run({}, [&](Context& c) {
        seen = c;
        return 0;
    });
    EXPECT_EQ(seen.seed, kDefaultSeed);
    EXPECT_EQ(run({"--threads", "-1"}, succeed).status, kExitUsage);
    EXPECT_EQ(run({"--seed", "1"}, succeed, kCommonBasic).status, kExitUsage);
}

TEST(Runner, SeedAndThreadsOutOfRangeAreUsageErrors) {
    // CLI11 alone reads "-1" into an unsigned as 2^64 - 1 and saturates on overflow.
    const std::pair<std::vector<std::string>, std::string> cases[] = {
        {{"--seed", "-1"}, "--seed: \"-1\" is not a whole number from 0 to 18446744073709551615"},
        {{"--seed", "18446744073709551616"},
         "--seed: \"18446744073709551616\" is not a whole number from 0 to "
         "18446744073709551615"},
        {{"--seed", "1e3"}, "--seed: \"1e3\" is not a whole number"},
        {{"--seed", "+5"}, "--seed: \"+5\" is not a whole number"},
        {{"--seed=", ""}, "--seed"},
        {{"--threads=-2"}, "--threads: \"-2\" is not a whole number from 0 to 4294967295"},
        {{"--threads", "4294967296"}, "--threads: \"4294967296\" is not a whole number"},
    };
    for (const auto& [args, message] : cases) {
        bool ran = false;
        const Outcome o = run(args, [&](Context&) {
            ran = true;
            return 0;
        });
        EXPECT_EQ(o.status, kExitUsage) << message;
        EXPECT_THAT(o.err, HasSubstr("glint-demo: error: " + message)) << o.err;
        EXPECT_FALSE(ran) << message;
    }
    Context seen;
    EXPECT_EQ(run({"--seed", "18446744073709551615"},
                  [&](Context& c) {
                      seen = c;
                      return 0;
                  })
                  .status,
              0);
    EXPECT_EQ(seen.seed, 18446744073709551615u);
}

TEST(Runner, VerbosityAndQuietSetTheLogThreshold) {
    auto chatty = [](Context& c) {
        c.log.debug("a debug line");
        c.log.info("an info line");
        c.log.notice("a notice line");
        c.log.warning("a warning line");
        return 0;
    };
    // A notice (the commands a run starts) is shown at normal verbosity, without a label.
    Outcome o = run({}, chatty);
    EXPECT_EQ(o.err, "glint-demo: a notice line\nglint-demo: warning: a warning line\n");
    o = run({"-v"}, chatty);
    EXPECT_EQ(o.err,
              "glint-demo: an info line\nglint-demo: a notice line\nglint-demo: warning: a "
              "warning line\n");
    o = run({"-vv"}, chatty);
    EXPECT_THAT(o.err, HasSubstr("glint-demo: debug: a debug line"));
    o = run({"-q"}, chatty);
    EXPECT_EQ(o.err, "");
}

/// The names of the temporary files (".NAME.tmp-...") in `folder`.
std::vector<std::string> temporary_files_in(const std::filesystem::path& folder) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        const std::string name = entry.path().filename().string();
        if (name.find(".tmp-") != std::string::npos) names.push_back(name);
    }
    return names;
}

TEST(Runner, ASecondSignalEndsTheProcessAfterRemovingItsTemporaryFiles) {
    test::TempDir dir;
    // In a child: an output half written, then SIGINT twice. The first only raises the cancel
    // flag; the second, of the same kind, kills the process — after unlinking the file the
    // unwinding would have removed.
    EXPECT_EXIT(
        {
            run({}, [&](Context&) {
                AtomicFile file(dir / "image.img");
                file.write("half");
                ::raise(SIGINT);
                ::raise(SIGINT);
                return kExitSuccess;  // not reached
            });
            std::_Exit(3);
        },
        ::testing::KilledBySignal(SIGINT), "");
    EXPECT_EQ(temporary_files_in(dir.path()), std::vector<std::string>{});
    EXPECT_FALSE(std::filesystem::exists(dir / "image.img"));
}

TEST(TemporaryFiles, UnlinkAllRemovesWhatIsRegisteredAndNothingElse) {
    test::TempDir dir;
    std::ofstream(dir / "kept.txt") << "x";
    std::ofstream(dir / ".a.tmp-1") << "x";
    std::ofstream(dir / ".b.tmp-2") << "x";
    const int a = temporary_files::add(dir / ".a.tmp-1");
    const int b = temporary_files::add(dir / ".b.tmp-2");
    ASSERT_GE(a, 0);
    ASSERT_GE(b, 0);
    temporary_files::remove(b);  // published: no longer the table's
    temporary_files::unlink_all();
    EXPECT_FALSE(std::filesystem::exists(dir / ".a.tmp-1"));
    EXPECT_TRUE(std::filesystem::exists(dir / ".b.tmp-2"));
    EXPECT_TRUE(std::filesystem::exists(dir / "kept.txt"));
    temporary_files::remove(a);
    // A path longer than the system's limit is not taken (its owner removes it).
    EXPECT_EQ(temporary_files::add(std::filesystem::path(std::string(5000, 'x'))), -1);
}

TEST(Runner, ProgressFileGetsKeyValueLines) {
    test::TempDir dir;
    const std::string file = (dir / "progress.txt").string();
    const Outcome o = run({"--progress", file}, [](Context& c) {
        c.progress.update("lines", 0, 10);
        c.progress.finish("lines", 10);
        return 0;
    });
    EXPECT_EQ(o.status, 0);
    std::ifstream in(file);
    std::string first, second;
    std::getline(in, first);
    std::getline(in, second);
    EXPECT_THAT(first, HasSubstr("label=lines done=0 total=10 percent=0.0"));
    EXPECT_THAT(second, HasSubstr("label=lines done=10 total=10 percent=100.0"));
    EXPECT_THAT(second, HasSubstr("state=finished"));
    EXPECT_EQ(o.err, "");  // stderr is not a terminal here: no progress line
}

/// Sets an environment variable (or unsets it, for nullptr) for its lifetime, then restores it:
/// tests of colour must not depend on the TERM and NO_COLOR they were started with.
class ScopedEnvironment {
public:
    ScopedEnvironment(const char* name, const char* value) : m_name(name) {
        if (const char* old = std::getenv(name)) m_old = old;
        if (value) {
            ::setenv(name, value, 1);
        } else {
            ::unsetenv(name);
        }
    }
    ~ScopedEnvironment() {
        if (m_old) {
            ::setenv(m_name.c_str(), m_old->c_str(), 1);
        } else {
            ::unsetenv(m_name.c_str());
        }
    }
    ScopedEnvironment(const ScopedEnvironment&) = delete;
    ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

private:
    std::string m_name;
    std::optional<std::string> m_old;
};

TEST(Runner, TerminalGetsAProgressLineAndColourUnlessQuiet) {
    const ScopedEnvironment term("TERM", "xterm-256color");
    const ScopedEnvironment no_colour("NO_COLOR", nullptr);
    auto work = [](Context& c) {
        c.progress.update("frames", 1, 2);
        c.progress.finish("frames", 2);
        c.log.warning("careful");
        return 0;
    };
    const char* argv_loud[] = {"glint-demo"};
    std::ostringstream out, err;
    EXPECT_EQ(run_tool(
                  ToolSpec{"demo", "d", kCommonBasic}, 1, argv_loud, ToolStreams{out, err, true},
                  [](CLI::App&) {}, work),
              0);
    EXPECT_THAT(err.str(), HasSubstr("\r\033[Kframes  50.0% (1/2)"));
    EXPECT_THAT(err.str(), HasSubstr("100.0% (2/2)"));
    EXPECT_THAT(err.str(), HasSubstr("\033[1;35mwarning:\033[0m careful"));

    const char* argv_quiet[] = {"glint-demo", "-q"};
    std::ostringstream out_q, err_q;
    EXPECT_EQ(run_tool(
                  ToolSpec{"demo", "d", kCommonBasic}, 2, argv_quiet,
                  ToolStreams{out_q, err_q, true}, [](CLI::App&) {}, work),
              0);
    EXPECT_EQ(err_q.str(), "");
}

TEST(Runner, ADumbTerminalGetsNoEscapesAndNoColorNoColour) {
    auto warn = [](Context& c) {
        c.progress.update("frames", 1, 2);
        c.progress.finish("frames", 2);
        c.log.warning("careful");
        return 0;
    };
    const char* argv[] = {"glint-demo"};
    for (const auto& [term, no_colour] : {std::pair<const char*, const char*>{"dumb", nullptr},
                                          std::pair<const char*, const char*>{"xterm", "1"}}) {
        const ScopedEnvironment set_term("TERM", term);
        const ScopedEnvironment set_no_colour("NO_COLOR", no_colour);
        std::ostringstream out, err;
        EXPECT_EQ(run_tool(
                      ToolSpec{"demo", "d", kCommonBasic}, 1, argv, ToolStreams{out, err, true},
                      [](CLI::App&) {}, warn),
                  0);
        EXPECT_THAT(err.str(), HasSubstr("glint-demo: warning: careful")) << term;
        EXPECT_THAT(err.str(), Not(HasSubstr("\033[1;35m"))) << term;  // no colour either way
        if (std::string(term) == "dumb") {
            EXPECT_EQ(err.str(), "glint-demo: warning: careful\n");  // no progress line
        } else {
            EXPECT_THAT(err.str(), HasSubstr("\r\033[Kframes 100.0% (2/2)"));  // NO_COLOR only
        }
    }
}

TEST(Runner, InterruptCancelsAndExits130) {
    const Outcome o = run({}, [](Context& c) {
        std::raise(SIGINT);
        EXPECT_TRUE(c.cancel.cancelled());
        c.cancel.throw_if_cancelled();
        return 0;
    });
    EXPECT_EQ(o.status, kExitInterrupted);
    EXPECT_THAT(o.err, HasSubstr("glint-demo: error: interrupted"));
}

TEST(Runner, EveryStopSignalCancelsWithItsOwnStatus) {
    // 128 + the signal's number, as a shell reports a process the signal ended; the work
    // stops at its next check, so its temporary files are removed on the way out.
    const std::pair<int, const char*> cases[] = {
        {SIGTERM, "SIGTERM"}, {SIGHUP, "SIGHUP"},   {SIGQUIT, "SIGQUIT"}, {SIGALRM, "SIGALRM"},
        {SIGUSR1, "SIGUSR1"}, {SIGUSR2, "SIGUSR2"}, {SIGXCPU, "SIGXCPU"}, {SIGPROF, "SIGPROF"},
    };
    for (const auto& [signal_number, name] : cases) {
        const int raised = signal_number;
        const Outcome o = run({}, [raised](Context& c) {
            std::raise(raised);
            c.cancel.throw_if_cancelled();
            return 0;
        });
        EXPECT_EQ(o.status, 128 + signal_number) << name;
        EXPECT_EQ(o.err, std::string("glint-demo: error: interrupted (") + name + ")\n");
    }
}

TEST(Runner, ClosedPipeStopsQuietly) {
    // `glint-schedule ... | head`: SIGPIPE on every write, no message, status 141.
    const Outcome o = run({}, [](Context& c) {
        std::raise(SIGPIPE);
        std::raise(SIGPIPE);  // raised again by the next write: still no default action
        c.cancel.throw_if_cancelled();
        return 0;
    });
    EXPECT_EQ(o.status, 128 + SIGPIPE);
    EXPECT_EQ(o.err, "");
}

TEST(Runner, FileSizeLimitIsAWriteErrorNotASignal) {
    // SIGXFSZ is ignored while a tool runs, so writing past `ulimit -f` fails with EFBIG
    // and goes through the usual error path (temporary files removed).
    const Outcome o = run({}, [](Context& c) {
        std::raise(SIGXFSZ);
        EXPECT_FALSE(c.cancel.cancelled());
        return 0;
    });
    EXPECT_EQ(o.status, 0);
}

TEST(ProgressPrinter, RendersTerminalLineAndMachineLines) {
    std::ostringstream terminal, machine;
    ProgressPrinter printer(&terminal, &machine);
    printer(ProgressUpdate{"capture", 1, 4, false});
    printer(ProgressUpdate{"capture", 2, 4, false});  // throttled: within 100 ms
    printer(ProgressUpdate{"capture", 4, 4, true});
    EXPECT_THAT(terminal.str(), HasSubstr("\r\033[Kcapture  25.0% (1/4)"));
    EXPECT_THAT(terminal.str(), HasSubstr("100.0% (4/4)"));
    EXPECT_EQ(terminal.str().back(), '\n');
    const std::string lines = machine.str();
    EXPECT_EQ(std::count(lines.begin(), lines.end(), '\n'), 2);
}

TEST(Diagnostic, ColourOnlyWhenAsked) {
    EXPECT_EQ(format_diagnostic("glint-x", "error", "bad", false), "glint-x: error: bad");
    EXPECT_THAT(format_diagnostic("glint-x", "error", "bad", true), HasSubstr("\033[1;31m"));
}

TEST(Diagnostic, TextFromAFileCannotDrawOnTheTerminalNorPassForGlintsOwnLine) {
    // A <message> or a file name holding an escape sequence, a bidi override and a newline
    // followed by a forged diagnostic.
    EXPECT_EQ(
        format_diagnostic("glint-x", "warning",
                          "a.platform:3: \x1B[2Jdone\xE2\x80\xAE\nglint-x: error: forged", false),
        "glint-x: warning: a.platform:3: \\x1B[2Jdone\\u202E\n  glint-x: error: forged");
    EXPECT_EQ(printable_message("one\ntwo\n"), "one\n  two\n  ");
}

}  // namespace runner_test
}  // namespace glint
