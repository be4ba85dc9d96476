// SPDX-License-Identifier: Apache-2.0
// Diagnostics: every problem kept in order, errors counted, logged at the right level and
// summarised into one glint::Error.
#include "glint/core/diagnostics.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace glint {
namespace diagnostics_test {

using ::testing::HasSubstr;

TEST(Diagnostics, KeepsOrderAndCounts) {
    Diagnostics d;
    EXPECT_FALSE(d.has_errors());
    EXPECT_NO_THROW(d.throw_if_errors());
    d.warning(ErrorContext{"a.platform", 3, "platform/foo"}, "unknown element <foo> ignored");
    d.error(ErrorContext{"a.platform", 7, "platform/x"}, "expected a number, got \"q\"");
    d.add(input_error("bad date", ErrorContext{"a.tasks", 2, "tasklist/reference"}));
    ASSERT_EQ(d.items().size(), 3u);
    EXPECT_EQ(d.error_count(), 2u);
    EXPECT_EQ(d.warning_count(), 1u);
    EXPECT_EQ(d.items()[0].text(), "a.platform:3: platform/foo: unknown element <foo> ignored");
    EXPECT_EQ(d.items()[2].text(), "a.tasks:2: tasklist/reference: bad date");
}

TEST(Diagnostics, ThrowsTheFirstErrorWithACount) {
    Diagnostics d;
    d.warning(ErrorContext{"a", 1, {}}, "just a warning");
    d.error(ErrorContext{"a", 2, "x"}, "first");
    d.error(ErrorContext{"a", 3, "y"}, "second");
    d.error(ErrorContext{"a", 4, "z"}, "third");
    try {
        d.throw_if_errors();
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_STREQ(e.what(), "a:2: x: first (and 2 more errors)");
    }
}

TEST(Diagnostics, LogsAtTheRightLevels) {
    std::vector<std::string> lines;
    Log log(
        [&](LogLevel level, const std::string& m) {
            lines.push_back(std::string(log_level_name(level)) + " " + m);
        },
        LogLevel::warning);
    Diagnostics d;
    d.warning(ErrorContext{"f", 1, {}}, "w");
    d.error(ErrorContext{"f", 2, {}}, "e");
    d.log_to(log);
    EXPECT_EQ(lines, (std::vector<std::string>{"warning f:1: w", "error f:2: e"}));
}

/// The lines log_and_rethrow logs and the message of what it throws.
struct Rethrown {
    std::vector<std::string> lines;
    ErrorCategory category = ErrorCategory::internal;
    std::string what;
};

Rethrown rethrow(const Diagnostics& d, const Error& error) {
    Rethrown out;
    Log log(
        [&](LogLevel level, const std::string& m) {
            out.lines.push_back(std::string(log_level_name(level)) + " " + m);
        },
        LogLevel::warning);
    try {
        d.log_and_rethrow(error, log);
    } catch (const Error& e) {
        out.category = e.category();
        out.what = e.what();
    }
    return out;
}

TEST(Diagnostics, LogAndRethrowPrintsEachProblemOnce) {
    Diagnostics d;
    d.warning(ErrorContext{"f", 1, {}}, "w");
    d.error(ErrorContext{"f", 2, "x"}, "e");
    // The error throw_if_errors raised is one of the logged ones: not printed again.
    Error raised = input_error("placeholder");
    try {
        d.throw_if_errors();
    } catch (const Error& e) {
        raised = e;
    }
    const Rethrown once = rethrow(d, raised);
    EXPECT_EQ(once.lines, (std::vector<std::string>{"warning f:1: w", "error f:2: x: e"}));
    EXPECT_EQ(once.category, ErrorCategory::input);
    EXPECT_EQ(once.what, "nothing written: 1 error in the inputs");

    // Another input error (thrown directly by a later stage) is logged too and counted.
    const Rethrown other = rethrow(d, input_error("late", ErrorContext{"g", 9, {}}));
    EXPECT_EQ(other.lines,
              (std::vector<std::string>{"warning f:1: w", "error f:2: x: e", "error g:9: late"}));
    EXPECT_EQ(other.what, "nothing written: 2 errors in the inputs");
}

TEST(Diagnostics, LogAndRethrowKeepsOtherErrorsAsTheyAre) {
    Diagnostics warnings_only;
    warnings_only.warning(ErrorContext{"f", 1, {}}, "w");
    const Rethrown input = rethrow(warnings_only, input_error("bad", ErrorContext{"f", 3, {}}));
    EXPECT_EQ(input.lines, (std::vector<std::string>{"warning f:1: w"}));
    EXPECT_EQ(input.what, "f:3: bad");

    Diagnostics with_error;
    with_error.error(ErrorContext{"f", 2, {}}, "e");
    const Rethrown io = rethrow(with_error, io_error("disk full", "out.img"));
    EXPECT_EQ(io.category, ErrorCategory::io);
    EXPECT_EQ(io.lines, (std::vector<std::string>{"error f:2: e"}));
}

TEST(Diagnostics, AppendCappedKeepsTwentyPerFileAndCountsTheRest) {
    Diagnostics one_file;
    for (int line = 1; line <= 25; ++line) {
        one_file.error(ErrorContext{"x.ems", line, {}}, "bad row");
    }
    one_file.warning(ErrorContext{"x.ems", 26, {}}, "odd row");
    one_file.warning(ErrorContext{"m.mat", 3, {}}, "unknown key");
    Diagnostics all;
    all.append_capped(one_file);
    ASSERT_EQ(all.items().size(), 22u);  // 20 of x.ems, m.mat's one, the summary
    EXPECT_EQ(all.items()[19].where.line, 20);
    EXPECT_EQ(all.items()[20].text(), "m.mat:3: unknown key");
    EXPECT_EQ(all.items()[21].text(), "x.ems: … and 6 more (5 errors, 1 warning) not shown");
    EXPECT_EQ(all.items()[21].severity, Diagnostic::Severity::error);
    // The counts are of every problem found: the summary line stands for the 6 left off.
    EXPECT_EQ(all.error_count(), 25u);
    EXPECT_EQ(all.warning_count(), 2u);
    // Copied into another list (as the loaders do), the line keeps what it stands for.
    Diagnostics copied;
    for (const Diagnostic& d : all.items()) copied.copy(d);
    EXPECT_EQ(copied.error_count(), 25u);
    EXPECT_EQ(copied.warning_count(), 2u);
    copied.copy(all.items()[21], ErrorContext{"moved.ems", 0, {}});
    EXPECT_EQ(copied.error_count(), 30u);
    EXPECT_EQ(copied.warning_count(), 3u);
    EXPECT_EQ(copied.items().back().text(),
              "moved.ems: … and 6 more (5 errors, 1 warning) not shown");

    Diagnostics warnings_only;
    for (int line = 1; line <= 22; ++line) {
        warnings_only.warning(ErrorContext{"w.mat", line, {}}, "unknown key");
    }
    Diagnostics capped;
    capped.append_capped(warnings_only);
    EXPECT_FALSE(capped.has_errors());
    EXPECT_EQ(capped.items().back().text(), "w.mat: … and 2 more (0 errors, 2 warnings) not shown");
    EXPECT_EQ(capped.warning_count(), 22u);
}

}  // namespace diagnostics_test
}  // namespace glint
