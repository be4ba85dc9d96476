// SPDX-License-Identifier: Apache-2.0
// Unit tests of the `.tasks` reader: a GUI-style file (no prolog, tabs, CDATA), relative and
// absolute start/stop times, and every bad input reported with its message, line and element
// path: malformed XML, bad ISO dates, non-numeric and NaN times, unknown time types, missing
// elements, stop before start, no tasks, unknown elements (warnings).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "glint/core/datetime.h"
#include "glint/dirsig/readers.h"
#include "glint/test/diagnostics.h"
#include "glint/test/temp_dir.h"

namespace glint::dirsig {
namespace tasks_test {

using glint::test::TempDir;
using ::testing::HasSubstr;

const std::filesystem::path kData = std::filesystem::path(GLINT_TEST_DATA_DIR) / "legacy";

/// Writes `text` as `name` in `dir` and reads it as a tasks file.
model::TaskList read_text(const TempDir& dir, const std::string& text, Diagnostics& diagnostics,
                          const std::string& name = "t.tasks") {
    const auto path = dir / name;
    std::ofstream(path) << text;
    return read_tasks(path, ReadOptions{}, diagnostics);
}

/// The only error diagnostic (fails the test unless there is exactly one).
using glint::test::only_error;

constexpr const char* kHeader =
    "<tasklist>\n"
    "  <reference><datetime type=\"absolute\">2020-06-21T12:00:00.0000+00:00</datetime>"
    "</reference>\n";

TEST(TasksReader, ReadsAGuiStyleFile) {
    Diagnostics diagnostics;
    const model::TaskList list = read_tasks(kData / "gui.tasks", ReadOptions{}, diagnostics);
    EXPECT_TRUE(diagnostics.items().empty()) << diagnostics.items().at(0).text();
    EXPECT_EQ(list.file, (kData / "gui.tasks").string());
    EXPECT_EQ(list.reference, parse_iso8601("2009-07-27T19:29:32Z"));
    EXPECT_EQ(list.reference.utc_offset_min, -480);
    ASSERT_EQ(list.tasks.size(), 2u);
    EXPECT_EQ(list.tasks[0].name, "Overpass");
    EXPECT_EQ(list.tasks[0].description, "A single frame, <straight down> & instantaneous");
    EXPECT_EQ(list.tasks[0].start_s, 0.0);
    EXPECT_EQ(list.tasks[0].stop_s, 0.0);
    EXPECT_EQ(list.tasks[0].where.line, 5);
    EXPECT_EQ(list.tasks[0].where.element, "tasklist/task");
    EXPECT_EQ(list.tasks[1].name, "Second pass");
    EXPECT_EQ(list.tasks[1].description, "");
    EXPECT_DOUBLE_EQ(list.tasks[1].start_s, 28.5);  // 19:30:00.5Z - 19:29:32Z
    EXPECT_DOUBLE_EQ(list.tasks[1].stop_s, 30.5);
}

TEST(TasksReader, ReadsTheFormatNotesExample) {
    Diagnostics diagnostics;
    const model::TaskList list = read_tasks(kData / "one_frame.tasks", ReadOptions{}, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors());
    ASSERT_EQ(list.tasks.size(), 1u);
    EXPECT_EQ(list.tasks[0].name, "Pass 1");
    EXPECT_EQ(list.tasks[0].start_s, 1.0);
    EXPECT_EQ(list.tasks[0].stop_s, 3.0);
}

TEST(TasksReader, TimesWithoutATypeAreInferred) {
    TempDir dir;
    Diagnostics diagnostics;
    const model::TaskList list =
        read_text(dir,
                  std::string(kHeader) +
                      "  <task><start><datetime>2.5</datetime></start>"
                      "<stop><datetime>2020-06-21T12:00:10Z</datetime></stop></task>\n"
                      "</tasklist>\n",
                  diagnostics);
    EXPECT_FALSE(diagnostics.has_errors());
    ASSERT_EQ(list.tasks.size(), 1u);
    EXPECT_EQ(list.tasks[0].start_s, 2.5);
    EXPECT_EQ(list.tasks[0].stop_s, 10.0);
}

TEST(TasksReaderErrors, MalformedXml) {
    TempDir dir;
    Diagnostics diagnostics;
    const model::TaskList list =
        read_text(dir, "<tasklist>\n  <task>\n    <start>\n  </task>\n</tasklist>\n", diagnostics);
    const Diagnostic error = only_error(diagnostics);
    EXPECT_EQ(error.where.file, (dir / "t.tasks").string());
    EXPECT_EQ(error.where.line, 3);
    EXPECT_THAT(error.message, HasSubstr("malformed XML: mismatched element"));
    EXPECT_TRUE(list.tasks.empty());
}

TEST(TasksReaderErrors, WrongRootAndMissingFile) {
    TempDir dir;
    Diagnostics diagnostics;
    read_text(dir, "\n<tasks/>\n", diagnostics);
    EXPECT_EQ(only_error(diagnostics).text(),
              (dir / "t.tasks").string() + ":2: expected root element <tasklist>, got <tasks>");

    Diagnostics missing;
    read_tasks(dir / "none.tasks", ReadOptions{}, missing);
    EXPECT_THAT(only_error(missing).text(), HasSubstr("none.tasks: cannot open file"));
}

TEST(TasksReaderErrors, BadIsoDate) {
    TempDir dir;
    Diagnostics diagnostics;
    read_text(dir,
              "<tasklist>\n  <reference>\n    <datetime type=\"absolute\">2020-13-01T00:00:00"
              "</datetime>\n  </reference>\n  <task><start><datetime type=\"relative\">0"
              "</datetime></start><stop><datetime type=\"relative\">1</datetime></stop>"
              "</task>\n</tasklist>\n",
              diagnostics);
    const Diagnostic error = only_error(diagnostics);
    EXPECT_EQ(error.where.line, 3);
    EXPECT_EQ(error.where.element, "tasklist/reference/datetime");
    EXPECT_THAT(error.message, HasSubstr("2020-13-01T00:00:00"));
}

TEST(TasksReaderErrors, NonNumericAndNanRelativeTimes) {
    TempDir dir;
    Diagnostics diagnostics;
    read_text(dir,
              std::string(kHeader) +
                  "  <task>\n    <start><datetime type=\"relative\">soon</datetime></start>\n"
                  "    <stop><datetime type=\"relative\">nan</datetime></stop>\n  </task>\n"
                  "</tasklist>\n",
              diagnostics);
    ASSERT_EQ(diagnostics.error_count(), 2u);
    EXPECT_EQ(diagnostics.items()[0].where.line, 4);
    EXPECT_EQ(diagnostics.items()[0].where.element, "tasklist/task/start/datetime");
    EXPECT_EQ(diagnostics.items()[0].message, "expected a number, got \"soon\"");
    EXPECT_EQ(diagnostics.items()[1].where.line, 5);
    EXPECT_EQ(diagnostics.items()[1].where.element, "tasklist/task/stop/datetime");
    EXPECT_EQ(diagnostics.items()[1].message, "expected a number, got \"nan\"");
}

TEST(TasksReaderErrors, UnknownTimeType) {
    TempDir dir;
    Diagnostics diagnostics;
    read_text(dir,
              std::string(kHeader) +
                  "  <task>\n    <start><datetime type=\"sidereal\">1</datetime></start>\n"
                  "    <stop><datetime type=\"relative\">2</datetime></stop>\n  </task>\n"
                  "</tasklist>\n",
              diagnostics);
    const Diagnostic error = only_error(diagnostics);
    EXPECT_EQ(error.where.line, 4);
    EXPECT_EQ(error.where.element, "tasklist/task/start/datetime@type");
    EXPECT_EQ(error.message, "expected one of relative, absolute, got \"sidereal\"");
}

TEST(TasksReaderErrors, ReferenceMustBeAbsolute) {
    TempDir dir;
    Diagnostics diagnostics;
    read_text(dir,
              "<tasklist>\n  <reference><datetime type=\"relative\">0</datetime></reference>\n"
              "  <task><start><datetime type=\"relative\">0</datetime></start>"
              "<stop><datetime type=\"relative\">0</datetime></stop></task>\n</tasklist>\n",
              diagnostics);
    const Diagnostic error = only_error(diagnostics);
    EXPECT_EQ(error.where.line, 2);
    EXPECT_EQ(error.where.element, "tasklist/reference/datetime@type");
    EXPECT_EQ(error.message, "expected one of absolute, got \"relative\"");
}

TEST(TasksReaderErrors, MissingRequiredElements) {
    TempDir dir;
    Diagnostics diagnostics;
    read_text(dir,
              "<tasklist>\n  <task>\n    <start><datetime type=\"relative\">0</datetime></start>\n"
              "  </task>\n  <task>\n    <start/>\n    <stop><datetime>1</datetime></stop>\n"
              "  </task>\n</tasklist>\n",
              diagnostics);
    ASSERT_EQ(diagnostics.error_count(), 3u);
    EXPECT_EQ(diagnostics.items()[0].text(),
              (dir / "t.tasks").string() + ":1: tasklist: missing required element <reference>");
    EXPECT_EQ(diagnostics.items()[1].where.line, 2);
    EXPECT_EQ(diagnostics.items()[1].where.element, "tasklist/task");
    EXPECT_EQ(diagnostics.items()[1].message, "missing required element <stop>");
    EXPECT_EQ(diagnostics.items()[2].where.line, 6);
    EXPECT_EQ(diagnostics.items()[2].where.element, "tasklist/task/start");
    EXPECT_EQ(diagnostics.items()[2].message, "missing required element <datetime>");
}

TEST(TasksReaderErrors, StopBeforeStart) {
    TempDir dir;
    Diagnostics diagnostics;
    read_text(dir,
              std::string(kHeader) +
                  "  <task>\n    <start><datetime type=\"relative\">3</datetime></start>\n"
                  "    <stop><datetime type=\"absolute\">2020-06-21T12:00:01Z</datetime></stop>\n"
                  "  </task>\n</tasklist>\n",
              diagnostics);
    const Diagnostic error = only_error(diagnostics);
    EXPECT_EQ(error.where.line, 5);
    EXPECT_EQ(error.where.element, "tasklist/task/stop");
    EXPECT_EQ(error.message, "stop time 1 s is before start time 3 s: expected stop >= start");
}

TEST(TasksReaderErrors, NoTasks) {
    TempDir dir;
    Diagnostics diagnostics;
    read_text(dir, std::string(kHeader) + "</tasklist>\n", diagnostics);
    const Diagnostic error = only_error(diagnostics);
    EXPECT_EQ(error.where.line, 1);
    EXPECT_EQ(error.where.element, "tasklist");
    EXPECT_EQ(error.message, "no <task> element: expected at least one task");
}

TEST(TasksReaderErrors, UnknownElementsAreWarnings) {
    TempDir dir;
    Diagnostics diagnostics;
    const model::TaskList list =
        read_text(dir,
                  std::string(kHeader) +
                      "  <comment>x</comment>\n"
                      "  <task>\n    <priority>1</priority>\n"
                      "    <start><datetime type=\"relative\">0</datetime></start>\n"
                      "    <stop><datetime type=\"relative\">1</datetime></stop>\n  </task>\n"
                      "</tasklist>\n",
                  diagnostics);
    EXPECT_FALSE(diagnostics.has_errors());
    ASSERT_EQ(diagnostics.warning_count(), 2u);
    EXPECT_EQ(diagnostics.items()[0].where.line, 3);
    EXPECT_EQ(diagnostics.items()[0].where.element, "tasklist/comment");
    EXPECT_EQ(diagnostics.items()[0].message, "unknown element <comment> ignored");
    EXPECT_EQ(diagnostics.items()[1].where.line, 5);
    EXPECT_EQ(diagnostics.items()[1].message, "unknown element <priority> ignored");
    EXPECT_EQ(list.tasks.size(), 1u);
}

}  // namespace tasks_test
}  // namespace glint::dirsig
