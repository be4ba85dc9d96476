// SPDX-License-Identifier: Apache-2.0
// Tests of run_process() and find_program(): exit statuses, PATH lookup, captured streams,
// no shell interpretation, timeouts and cancellation killing the child's process group.
#include "glint/process/process.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "glint/core/error.h"

namespace glint::process {
namespace process_test {

using namespace std::chrono_literals;

ProcessResult run(std::vector<std::string> argv, OutputMode mode = OutputMode::capture) {
    ProcessOptions options;
    options.argv = std::move(argv);
    options.stdout_mode = mode;
    return run_process(options);
}

TEST(Process, TrueExitsZero) {
    const ProcessResult r = run({"true"});
    EXPECT_TRUE(r.success());
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_EQ(r.signal, 0);
    EXPECT_EQ(r.describe(), "exited with status 0");
}

TEST(Process, FalseExitsOne) {
    const ProcessResult r = run({"false"});
    EXPECT_FALSE(r.success());
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.describe(), "exited with status 1");
}

TEST(Process, ExitStatusIsReported) {
    const ProcessResult r = run({"sh", "-c", "exit 42"});
    EXPECT_EQ(r.exit_code, 42);
}

TEST(Process, MissingProgramThrowsNamingIt) {
    try {
        run({"glint-no-such-program-xyz"});
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::io);
        EXPECT_NE(std::string(e.what()).find("glint-no-such-program-xyz"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("not found on PATH"), std::string::npos);
    }
    EXPECT_THROW(run({"/nonexistent/bin/tool"}), Error);
    EXPECT_THROW(run({}), Error);
}

TEST(Process, FindProgram) {
    const auto sh = find_program("sh");
    ASSERT_TRUE(sh.has_value());
    EXPECT_TRUE(sh->is_absolute());
    EXPECT_FALSE(find_program("sh", "/nonexistent:/also-not").has_value());
    EXPECT_TRUE(find_program("/bin/sh").has_value());
    EXPECT_FALSE(find_program("/etc/passwd").has_value());  // not executable
    EXPECT_FALSE(find_program("").has_value());
}

TEST(Process, CapturesStdoutAndStderrSeparately) {
    const ProcessResult r = run({"sh", "-c", "echo out; echo err >&2"});
    EXPECT_TRUE(r.success());
    EXPECT_EQ(r.stdout_text, "out\n");
    EXPECT_EQ(r.stderr_text, "err\n");
}

TEST(Process, StdoutDiscardedByDefault) {
    const ProcessResult r = run({"echo", "hello"}, OutputMode::discard);
    EXPECT_TRUE(r.success());
    EXPECT_TRUE(r.stdout_text.empty());
}

TEST(Process, NoShellInterpretation) {
    const ProcessResult r = run({"echo", "a;b", "$HOME", "`id`", "*", "|", "c&&d"});
    EXPECT_EQ(r.stdout_text, "a;b $HOME `id` * | c&&d\n");
}

TEST(Process, StdinIsDevNull) {
    const ProcessResult r = run({"cat"});  // would block forever on an inherited terminal
    EXPECT_TRUE(r.success());
    EXPECT_TRUE(r.stdout_text.empty());
}

TEST(Process, StderrCaptureKeepsTheLastBytes) {
    ProcessOptions options;
    options.argv = {"sh", "-c", "head -c 300000 /dev/zero | tr '\\0' x >&2; echo END >&2"};
    options.capture_limit_bytes = 1000;
    const ProcessResult r = run_process(options);
    EXPECT_TRUE(r.success());
    EXPECT_EQ(r.stderr_text.size(), 1000u);
    EXPECT_TRUE(r.stderr_truncated);
    EXPECT_EQ(r.stderr_text.substr(r.stderr_text.size() - 4), "END\n");
}

TEST(Process, EnvironmentAndWorkingDirectory) {
    ProcessOptions options;
    options.argv = {"sh", "-c", "echo \"$GLINT_TEST_VALUE\"; pwd"};
    options.environment = {{"GLINT_TEST_VALUE", "x y"}};
    options.working_directory = "/";
    options.stdout_mode = OutputMode::capture;
    const ProcessResult r = run_process(options);
    EXPECT_EQ(r.stdout_text, "x y\n/\n");
}

TEST(Process, ChildRunsInItsOwnProcessGroup) {
    const ProcessResult r = run({"sh", "-c", "ps -o pgid= -p $$; echo $$"});
    ASSERT_TRUE(r.success()) << r.stderr_text;
    const auto newline = r.stdout_text.find('\n');
    ASSERT_NE(newline, std::string::npos);
    EXPECT_EQ(std::stol(r.stdout_text.substr(0, newline)),
              std::stol(r.stdout_text.substr(newline + 1)));
}

TEST(Process, TimeoutKillsTheGroup) {
    ProcessOptions options;
    // The shell starts a sleep in the background too: killing the group must end both, or
    // the stderr pipe (held by the background sleep) would keep the call waiting.
    options.argv = {"sh", "-c", "sleep 30 & sleep 30"};
    options.timeout = 200ms;
    options.kill_grace = 500ms;
    const auto start = std::chrono::steady_clock::now();
    const ProcessResult r = run_process(options);
    const auto elapsed = std::chrono::steady_clock::now() - start;
    EXPECT_TRUE(r.timed_out);
    EXPECT_FALSE(r.success());
    EXPECT_NE(r.describe().find("timed out"), std::string::npos);
    EXPECT_LT(elapsed, 20s);  // generous: only guards against waiting for the sleep
}

TEST(Process, CancelKillsAndThrows) {
    ProcessOptions options;
    options.argv = {"sleep", "30"};
    CancelToken token;
    options.cancel = token;
    std::thread raiser([token] {
        std::this_thread::sleep_for(100ms);
        token.cancel();
    });
    try {
        run_process(options);
        raiser.join();
        FAIL() << "expected cancellation";
    } catch (const Error& e) {
        raiser.join();
        EXPECT_EQ(e.category(), ErrorCategory::cancelled);
    }
}

TEST(Process, KilledBySignalIsReported) {
    const ProcessResult r = run({"sh", "-c", "kill -TERM $$"});
    EXPECT_FALSE(r.success());
    EXPECT_EQ(r.signal, 15);
    EXPECT_NE(r.describe().find("signal 15"), std::string::npos);
}

TEST(Process, FormatCommandLineQuotes) {
    EXPECT_EQ(format_command_line(std::vector<std::string>{"ffmpeg", "-i", "a b.png", "it's"}),
              "ffmpeg -i 'a b.png' 'it'\\''s'");
}

}  // namespace process_test
}  // namespace glint::process
