// SPDX-License-Identifier: Apache-2.0
// read_schedule_file (glint/inputs/schedule_file.h), the one reader of glint-schedule JSON:
// what glint-render --schedule selects and what glint-envi merge --expect lists, and the
// shapes it refuses, each with its message.
#include "glint/inputs/schedule_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "glint/core/error.h"
#include "glint/test/temp_dir.h"

namespace glint::inputs {
namespace schedule_file_test {

std::filesystem::path write(const test::TempDir& dir, const std::string& name,
                            const std::string& text) {
    const std::filesystem::path path = dir / name;
    std::ofstream(path) << text;
    return path;
}

constexpr const char* kTwoCaptures = R"({
  "format": "glint-schedule",
  "provenance": {"working_folder": "/runs/a", "command": ["glint-schedule"]},
  "selection": {"shard": {"index": 2, "count": 3, "by": "rows"}},
  "captures": [
    {"index": 4, "files": {"image": "out/frame.img", "truth": ["out/t1.img", "out/t2.img"]},
     "nested": {"index": 99, "image": "not-this.img"}},
    {"index": 7, "files": {"image": "out/frame.img"}}
  ]
})";

TEST(ScheduleFile, ReadsIndicesRowShardAndWorkingFolder) {
    const test::TempDir dir;
    const ScheduleFile file = read_schedule_file(write(dir, "s.json", kTwoCaptures));
    ASSERT_EQ(file.captures.size(), 2u);
    EXPECT_EQ(file.captures[0].index, 4u);
    EXPECT_EQ(file.captures[1].index, 7u);
    EXPECT_TRUE(file.captures[0].image.empty()) << "files are kept only when asked for";
    EXPECT_TRUE(file.captures[0].truth.empty());
    ASSERT_TRUE(file.row_shard);
    EXPECT_EQ(*file.row_shard, (std::pair<std::uint64_t, std::uint64_t>{2, 3}));
    EXPECT_EQ(file.working_folder, "/runs/a");
}

TEST(ScheduleFile, KeepsEachCapturesFilesWhenAsked) {
    const test::TempDir dir;
    const ScheduleFile file = read_schedule_file(write(dir, "s.json", kTwoCaptures), true);
    ASSERT_EQ(file.captures.size(), 2u);
    EXPECT_EQ(file.captures[0].image, "out/frame.img");
    EXPECT_EQ(file.captures[0].truth, (std::vector<std::string>{"out/t1.img", "out/t2.img"}));
    EXPECT_EQ(file.captures[1].image, "out/frame.img");
    EXPECT_TRUE(file.captures[1].truth.empty());
}

TEST(ScheduleFile, AShardByCapturesIsNoRowBand) {
    const test::TempDir dir;
    const ScheduleFile file = read_schedule_file(
        write(dir, "s.json",
              R"({"format": "glint-schedule", "selection": {"shard": {"index": 1, "count": 2,
            "by": "captures"}}, "captures": [{"index": 0}]})"));
    EXPECT_FALSE(file.row_shard);
    EXPECT_FALSE(file.working_folder);
}

void expect_refused(const std::string& text, const std::string& message) {
    const test::TempDir dir;
    const std::filesystem::path path = write(dir, "bad.json", text);
    try {
        (void)read_schedule_file(path, true);
        FAIL() << "expected an error for " << text;
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_NE(e.message().find(message), std::string::npos) << e.message();
        EXPECT_EQ(e.context().file, path.string());
    }
}

TEST(ScheduleFile, RefusesWhatIsNotAGlintSchedule) {
    expect_refused("[1, 2]", "not a glint-schedule file");
    expect_refused("{\"format\": \"glint-schedule\", \"captures\": {}}",
                   "the schedule has no \"captures\" array");
    expect_refused("{\"format\": \"glint-schedule\", \"captures\": [{\"index\": 0}, 3]}",
                   "captures[1] has no non-negative integer \"index\"");
    expect_refused("{\"format\": \"glint-schedule\", \"captures\": []}",
                   "the schedule selects no capture");
    expect_refused("{\"format\": \"glint-schedule\", \"captures\": [", "not JSON");
    expect_refused(
        R"({"format": "glint-schedule", "selection": {"shard": {"by": "columns"}},
            "captures": [{"index": 0}]})",
        "selection.shard.by is \"columns\"");
    expect_refused(
        R"({"format": "glint-schedule", "selection": {"shard": {"index": 3, "count": 2,
            "by": "rows"}}, "captures": [{"index": 0}]})",
        "needs \"index\" K and \"count\" N with 1 <= K <= N");
}

}  // namespace schedule_file_test
}  // namespace glint::inputs
