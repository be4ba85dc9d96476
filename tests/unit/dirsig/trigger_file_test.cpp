// SPDX-License-Identifier: Apache-2.0
// Trigger files: separators and comments, every bad token reported at file:line, ordering,
// empty and missing files (the repeat period is
// schedule::trigger_period_s, tested with the clock ticks).
#include "glint/dirsig/trigger_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace glint::dirsig {
namespace trigger_file_test {

using ::testing::ElementsAre;

const std::string kData = GLINT_TEST_DATA_DIR "/schedule";

std::vector<std::string> texts(const Diagnostics& diagnostics) {
    std::vector<std::string> result;
    for (const Diagnostic& d : diagnostics.items()) result.push_back(d.text());
    return result;
}

TEST(TriggerFile, BlanksCommasSemicolonsNewlinesAndComments) {
    Diagnostics diagnostics;
    const std::vector<double> times =
        parse_trigger_times("# header\n0.0 0.1,0.2;\t0.3\r\n+0.4 # trailing comment 9\n\n5e-1,\n",
                            "t.txt", diagnostics);
    EXPECT_FALSE(diagnostics.has_errors());
    EXPECT_THAT(times, ElementsAre(0.0, 0.1, 0.2, 0.3, 0.4, 0.5));
}

TEST(TriggerFile, NegativeTimesAreAllowed) {
    Diagnostics diagnostics;
    EXPECT_THAT(parse_trigger_times("-1.5 -0.5 0", "t.txt", diagnostics),
                ElementsAre(-1.5, -0.5, 0.0));
    EXPECT_FALSE(diagnostics.has_errors());
}

TEST(TriggerFile, EveryBadTokenIsReportedWithItsLine) {
    Diagnostics diagnostics;
    const std::vector<double> times =
        parse_trigger_times("0.0\n0.1 abc\n0.1\n0.05 inf\n1e400 0.2 ++1 -\n", "t.txt", diagnostics);
    EXPECT_THAT(times, ElementsAre(0.0, 0.1, 0.2));
    EXPECT_THAT(
        texts(diagnostics),
        ElementsAre(
            "t.txt:2: trigger time \"abc\" is not a finite number, expected seconds after the "
            "reference time",
            "t.txt:3: trigger time 0.1 s is equal to the previous one (0.1 s at line 2), expected "
            "strictly increasing times",
            "t.txt:4: trigger time 0.05 s is before the previous one (0.1 s at line 2), expected "
            "strictly increasing times",
            "t.txt:4: trigger time \"inf\" is not a finite number, expected seconds after the "
            "reference time",
            "t.txt:5: trigger time \"1e400\" is not a finite number, expected seconds after the "
            "reference time",
            "t.txt:5: trigger time \"++1\" is not a finite number, expected seconds after the "
            "reference time",
            "t.txt:5: trigger time \"-\" is not a finite number, expected seconds after the "
            "reference time"));
}

TEST(TriggerFile, EmptyFileIsAnError) {
    Diagnostics diagnostics;
    EXPECT_TRUE(parse_trigger_times("# nothing but a comment\n\n", "t.txt", diagnostics).empty());
    EXPECT_THAT(texts(diagnostics),
                ElementsAre("t.txt: no trigger time in the file, expected at least one time in "
                            "seconds"));
}

TEST(TriggerFile, ReadsAFile) {
    Diagnostics diagnostics;
    EXPECT_THAT(read_trigger_file(kData + "/triggers.txt", {}, diagnostics),
                ElementsAre(0.0, 0.1, 0.2, 0.35, 0.5));
    EXPECT_FALSE(diagnostics.has_errors());
}

TEST(TriggerFile, MissingFileIsAnError) {
    Diagnostics diagnostics;
    EXPECT_TRUE(read_trigger_file(kData + "/no_such_triggers.txt", {}, diagnostics).empty());
    EXPECT_THAT(texts(diagnostics),
                ElementsAre(kData + "/no_such_triggers.txt: cannot open trigger file: No such "
                                    "file or directory"));
}

}  // namespace trigger_file_test
}  // namespace glint::dirsig
