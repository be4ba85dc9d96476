// SPDX-License-Identifier: Apache-2.0
// Tests of the PSD table reader and validator (lib/dirsig/src/psd_reader.cpp): the accepted
// layouts (blanks, commas, comments, CRLF, BOM, phases) and every bad input with its message
// and line, for files and for inline tables.
#include "glint/dirsig/psd_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "glint/test/temp_dir.h"

namespace glint::test {
namespace psd_reader_test {

/// A PSD file read from `text`, with what reading it reported.
struct PsdRead {
    std::string file;
    model::PsdTable table;
    Diagnostics diagnostics;
};

PsdRead read_text(const TempDir& dir, const std::string& text) {
    PsdRead read;
    read.file = (dir / "jitter.psd").string();
    {
        std::ofstream out(read.file, std::ios::binary);
        out << text;
    }
    read.table = dirsig::read_psd_file(read.file, {}, read.diagnostics);
    return read;
}

std::string dump(const Diagnostics& diagnostics) {
    std::string out;
    for (const Diagnostic& d : diagnostics.items()) out += d.text() + "\n";
    return out;
}

/// Asserts exactly one error, at `line` of the file, whose message contains `message`.
void expect_one_error(const PsdRead& read, int line, const std::string& message) {
    ASSERT_EQ(read.diagnostics.error_count(), 1u) << dump(read.diagnostics);
    const Diagnostic& d = read.diagnostics.items().front();
    EXPECT_EQ(d.where.file, read.file);
    EXPECT_EQ(d.where.line, line) << d.text();
    EXPECT_NE(d.message.find(message), std::string::npos) << d.text();
}

// ---- good input -----------------------------------------------------------------------------

TEST(PsdReader, BlankSeparatedRowsWithCommentsAndBlankLines) {
    TempDir dir;
    const auto read = read_text(dir,
                                "# frequency (Hz)  psd (rad^2/Hz)\n"
                                "\n"
                                "0     1e-6\n"
                                "  1.5\t2e-6   # a comment after a row\n"
                                "10 0\n");
    ASSERT_FALSE(read.diagnostics.has_errors()) << dump(read.diagnostics);
    EXPECT_EQ(read.table.frequency_hz, (std::vector<double>{0.0, 1.5, 10.0}));
    EXPECT_EQ(read.table.psd, (std::vector<double>{1e-6, 2e-6, 0.0}));
    EXPECT_TRUE(read.table.phase_rad.empty());
    EXPECT_EQ(read.table.where.file, read.file);
    EXPECT_EQ(read.table.where.line, 3);
}

TEST(PsdReader, CommaSeparatedRowsWithPhasesCrlfAndBom) {
    TempDir dir;
    const auto read = read_text(dir,
                                "\xEF\xBB\xBF"
                                "1, 2, 0.5\r\n2 ,3 ,-1\r\n4,5,3.0\r\n");
    ASSERT_FALSE(read.diagnostics.has_errors()) << dump(read.diagnostics);
    EXPECT_EQ(read.table.frequency_hz, (std::vector<double>{1.0, 2.0, 4.0}));
    EXPECT_EQ(read.table.psd, (std::vector<double>{2.0, 3.0, 5.0}));
    EXPECT_EQ(read.table.phase_rad, (std::vector<double>{0.5, -1.0, 3.0}));
}

TEST(PsdReader, DisplayNameIsUsedInTheTableAndDiagnostics) {
    TempDir dir;
    const std::string path = (dir / "a.psd").string();
    {
        std::ofstream out(path);
        out << "1 1\nx 2\n";
    }
    Diagnostics diagnostics;
    const auto table = dirsig::read_psd_file(path, {}, diagnostics, "$DIR/a.psd");
    EXPECT_EQ(table.where.file, "$DIR/a.psd");
    ASSERT_EQ(diagnostics.error_count(), 1u);
    EXPECT_EQ(diagnostics.items()[0].text(), "$DIR/a.psd:2: frequency 'x' is not a finite number");
}

// ---- bad input: every case names the file and line ------------------------------------------

TEST(PsdReader, NonNumericFrequency) {
    TempDir dir;
    expect_one_error(read_text(dir, "1 1\nabc 2\n3 3\n"), 2,
                     "frequency 'abc' is not a finite number");
}

TEST(PsdReader, NonNumericPsd) {
    TempDir dir;
    expect_one_error(read_text(dir, "1 1\n2 1e-3x\n3 3\n"), 2,
                     "psd '1e-3x' is not a finite number");
}

TEST(PsdReader, NonNumericPhase) {
    TempDir dir;
    expect_one_error(read_text(dir, "1 1 0\n2 1 0\n3 3 pi\n"), 3,
                     "phase 'pi' is not a finite number");
}

TEST(PsdReader, NonFiniteValues) {
    TempDir dir;
    expect_one_error(read_text(dir, "1 1\n2 nan\n3 3\n"), 2, "psd 'nan' is not a finite number");
    expect_one_error(read_text(dir, "1 1\ninf 2\n"), 2, "frequency 'inf' is not a finite number");
    expect_one_error(read_text(dir, "1 1\n2 1e400\n"), 2, "psd '1e400' is not a finite number");
}

TEST(PsdReader, HeaderLineIsNonNumeric) {
    TempDir dir;
    const auto read = read_text(dir, "frequency psd\n1 1\n2 2\n");
    ASSERT_EQ(read.diagnostics.error_count(), 2u) << dump(read.diagnostics);
    EXPECT_EQ(read.diagnostics.items()[0].text(),
              read.file + ":1: frequency 'frequency' is not a finite number");
    EXPECT_EQ(read.diagnostics.items()[1].text(),
              read.file + ":1: psd 'psd' is not a finite number");
}

TEST(PsdReader, NegativeFrequency) {
    TempDir dir;
    expect_one_error(read_text(dir, "-1 1\n2 2\n"), 1, "frequency -1 Hz is negative");
}

TEST(PsdReader, NegativePsd) {
    TempDir dir;
    expect_one_error(read_text(dir, "1 1\n2 -0.5\n3 1\n"), 2, "psd -0.5 is negative");
}

TEST(PsdReader, RepeatedFrequency) {
    TempDir dir;
    expect_one_error(read_text(dir, "1 1\n2 2\n2 3\n"), 3,
                     "frequency 2 Hz is not greater than the previous 2 Hz; frequencies must be "
                     "strictly increasing");
}

TEST(PsdReader, DecreasingFrequency) {
    TempDir dir;
    expect_one_error(read_text(dir, "# head\n1 1\n5 2\n\n3 3\n"), 5,
                     "frequency 3 Hz is not greater than the previous 5 Hz");
}

TEST(PsdReader, DecreasingAfterABadRowComparesWithTheLastGoodFrequency) {
    TempDir dir;
    const auto read = read_text(dir, "1 1\n5 -2\n4 3\n6 1\n");
    ASSERT_EQ(read.diagnostics.error_count(), 2u) << dump(read.diagnostics);
    EXPECT_EQ(read.diagnostics.items()[0].where.line, 2);
    EXPECT_EQ(read.diagnostics.items()[0].message, "psd -2 is negative");
    EXPECT_EQ(read.diagnostics.items()[1].where.line, 3);
    EXPECT_EQ(read.diagnostics.items()[1].message,
              "frequency 4 Hz is not greater than the previous 5 Hz; frequencies must be strictly "
              "increasing");
}

TEST(PsdReader, MixedTwoAndThreeColumns) {
    TempDir dir;
    expect_one_error(read_text(dir, "1 1\n2 2\n3 3 0.1\n"), 3,
                     "row has 3 values but earlier rows have 2; give a phase on every row or on "
                     "none");
    expect_one_error(read_text(dir, "1 1 0\n2 2\n3 3 0.1\n"), 2,
                     "row has 2 values but earlier rows have 3");
}

TEST(PsdReader, WrongValueCount) {
    TempDir dir;
    expect_one_error(read_text(dir, "1 1\n2\n3 3\n"), 2,
                     "row has 1 values, expected 2 or 3 (frequency psd [phase])");
    expect_one_error(read_text(dir, "1 1\n2 2 0 7\n3 3\n"), 2, "row has 4 values, expected 2 or 3");
}

TEST(PsdReader, EmptyFields) {
    TempDir dir;
    for (const char* row : {"2,,3", ",2 3", "2, 3,", "2 , , 3"}) {
        expect_one_error(read_text(dir, std::string("1 1\n") + row + "\n4 4\n"), 2,
                         "empty field: values are separated by blanks or one comma");
    }
}

TEST(PsdReader, FewerThanTwoRows) {
    TempDir dir;
    expect_one_error(read_text(dir, "# only a comment\n\n3 1\n"), 3,
                     "PSD file has only 1 data row; a PSD needs at least 2");
    const auto empty = read_text(dir, "# nothing\n\n");
    ASSERT_EQ(empty.diagnostics.error_count(), 1u);
    EXPECT_EQ(
        empty.diagnostics.items()[0].text(),
        empty.file + ": PSD file has no data rows; a PSD needs at least 2 (frequency psd [phase])");
}

TEST(PsdReader, EveryBadRowIsReported) {
    TempDir dir;
    const auto read = read_text(dir, "1 1\n-2 1\nx 1\n3 -1\n3 1\n");
    ASSERT_EQ(read.diagnostics.error_count(), 4u) << dump(read.diagnostics);
    for (int i = 0; i < 4; ++i) EXPECT_EQ(read.diagnostics.items()[i].where.line, i + 2);
    EXPECT_EQ(read.table.frequency_hz, (std::vector<double>{1.0}));
}

TEST(PsdReader, MissingFileIsAnError) {
    TempDir dir;
    Diagnostics diagnostics;
    const std::string path = (dir / "absent.psd").string();
    dirsig::read_psd_file(path, {}, diagnostics);
    ASSERT_EQ(diagnostics.error_count(), 1u);
    EXPECT_EQ(diagnostics.items()[0].where.file, path);
    EXPECT_NE(diagnostics.items()[0].message.find("cannot open file"), std::string::npos)
        << diagnostics.items()[0].text();
}

// ---- inline tables ---------------------------------------------------------------------------

model::PsdTable inline_table(std::vector<double> f, std::vector<double> s,
                             std::vector<double> phase = {}) {
    model::PsdTable t;
    t.frequency_hz = std::move(f);
    t.psd = std::move(s);
    t.phase_rad = std::move(phase);
    t.where = ErrorContext{"a.motion", 12, "psd"};
    return t;
}

/// The one error of validating `table`, as text.
std::string validate_one(const model::PsdTable& table) {
    Diagnostics diagnostics;
    model::validate_psd_table(table, diagnostics);
    EXPECT_EQ(diagnostics.error_count(), 1u) << dump(diagnostics);
    return diagnostics.items().empty() ? "" : diagnostics.items()[0].text();
}

TEST(PsdValidate, GoodTablesPass) {
    Diagnostics diagnostics;
    model::validate_psd_table(inline_table({0, 1, 10}, {1, 0, 2}), diagnostics);
    model::validate_psd_table(inline_table({0.5, 1}, {1, 1}, {0, -7}), diagnostics);
    EXPECT_FALSE(diagnostics.has_errors()) << dump(diagnostics);
}

TEST(PsdValidate, EveryBadTable) {
    EXPECT_EQ(validate_one(inline_table({1, 2}, {1})),
              "a.motion:12: psd: PSD table has 2 frequencies but 1 PSD values");
    EXPECT_EQ(validate_one(inline_table({1, 2}, {1, 1}, {0})),
              "a.motion:12: psd: PSD table has 2 rows but 1 phases; give a phase on every row or "
              "on none");
    EXPECT_EQ(validate_one(inline_table({1}, {1})),
              "a.motion:12: psd: PSD table has 1 rows; a PSD needs at least 2");
    EXPECT_EQ(validate_one(inline_table({-1, 2}, {1, 1})),
              "a.motion:12: psd: PSD row 1: frequency -1 Hz is negative");
    EXPECT_EQ(validate_one(inline_table({1, 2}, {1, -3})),
              "a.motion:12: psd: PSD row 2: psd -3 is negative");
    EXPECT_EQ(validate_one(inline_table({1, 3, 2}, {1, 1, 1})),
              "a.motion:12: psd: PSD row 3: frequency 2 Hz is not greater than the previous 3 Hz; "
              "frequencies must be strictly increasing");
    EXPECT_EQ(validate_one(inline_table({1, 2}, {1, NAN})),
              "a.motion:12: psd: PSD row 2: psd nan is not a finite number");
    EXPECT_EQ(validate_one(inline_table({1, INFINITY}, {1, 1})),
              "a.motion:12: psd: PSD row 2: frequency inf is not a finite number");
    EXPECT_EQ(validate_one(inline_table({1, 2}, {1, 1}, {0, NAN})),
              "a.motion:12: psd: PSD row 2: phase nan is not a finite number");
}

}  // namespace psd_reader_test
}  // namespace glint::test
