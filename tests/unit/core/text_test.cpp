// SPDX-License-Identifier: Apache-2.0
// Tests of the helpers in glint/core/text.h: quote, the UTF-8 checks, byte sizes, lines, the
// ten-digit number format and blanks.
#include "glint/core/text.h"

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

namespace glint::test {
namespace text_test {

TEST(Quote, PlainTextIsQuotedAsIs) {
    EXPECT_EQ(quote("frame"), "\"frame\"");
    EXPECT_EQ(quote(""), "\"\"");
    EXPECT_EQ(quote("caf\xC3\xA9 \xE2\x82\xAC"), "\"caf\xC3\xA9 \xE2\x82\xAC\"");  // UTF-8 kept
}

TEST(Quote, EscapesWhatATerminalWouldMisread) {
    EXPECT_EQ(quote("a\"b\\c"), "\"a\\\"b\\\\c\"");
    EXPECT_EQ(quote("a\nb\tc\r"), "\"a\\nb\\tc\\r\"");
    EXPECT_EQ(quote(std::string("x\0y", 3)), "\"x\\x00y\"");
    EXPECT_EQ(quote("\x1B[31m"), "\"\\x1B[31m\"");
    EXPECT_EQ(quote("Latin-1 \xE9t\xE9"), "\"Latin-1 \\xE9t\\xE9\"");  // not UTF-8
    EXPECT_EQ(quote("\xFF\xFE"), "\"\\xFF\\xFE\"");
}

TEST(Quote, EscapesBidiAndC1Controls) {
    // U+202E RIGHT-TO-LEFT OVERRIDE ("Trojan Source") and U+0085 NEXT LINE, as UTF-8.
    EXPECT_EQ(quote("a\xE2\x80\xAE"
                    "gpj.exe"),
              "\"a\\u202Egpj.exe\"");
    EXPECT_EQ(quote("a\xC2\x85"
                    "b"),
              "\"a\\u0085b\"");
}

TEST(TerminalSafe, EscapesWhatATerminalActsOn) {
    EXPECT_EQ(terminal_safe("plain caf\xC3\xA9\tand\nlines"), "plain caf\xC3\xA9\tand\nlines");
    EXPECT_EQ(terminal_safe("\x1B]0;title\x07\x1B[2J"), "\\x1B]0;title\\x07\\x1B[2J");
    EXPECT_EQ(terminal_safe("x\ry"), "x\\x0Dy");  // a carriage return would redraw the line
    EXPECT_EQ(terminal_safe("\x7F\xC2\x9B"), "\\x7F\\u009B");  // DEL, the C1 CSI
    for (const char* bidi :
         {"\xD8\x9C", "\xE2\x80\x8E", "\xE2\x80\x8F", "\xE2\x80\xAA", "\xE2\x80\xAE",
          "\xE2\x81\xA6", "\xE2\x81\xA9", "\xE2\x80\xA8", "\xE2\x80\xA9"}) {
        const std::string shown = terminal_safe(bidi);
        EXPECT_EQ(shown.substr(0, 2), "\\u") << shown;
    }
    EXPECT_EQ(terminal_safe("Latin-1 \xE9"), "Latin-1 \\xE9");
    EXPECT_EQ(terminal_safe_line("a\nb\tc"), "a\\x0Ab\tc");
}

TEST(FormatCommandLine, ShowsWhatRunsAsBashWouldReadIt) {
    const std::vector<std::string> plain{"/usr/bin/ffmpeg", "-y", "-i", "a%04d.png"};
    EXPECT_EQ(format_command_line(plain), "/usr/bin/ffmpeg -y -i a%04d.png");
    const std::vector<std::string> quoted{"x", "a b", "it's", "$(y)"};
    EXPECT_EQ(format_command_line(quoted), "x 'a b' 'it'\\''s' '$(y)'");
    const std::vector<std::string> controls{"x", "a\nb", "\x1B[2J'\\", "r\xE2\x80\xAEl"};
    EXPECT_EQ(format_command_line(controls), "x $'a\\x0Ab' $'\\x1B[2J\\'\\\\' $'r\\u202El'");
}

TEST(Quote, LongTextIsCutWithItsSize) {
    const std::string token(20'000'000, 'x');  // the 20 MB OBJ token of a fuzzed input
    const std::string shown = quote(token);
    EXPECT_EQ(shown, "\"" + std::string(80, 'x') + "\"... (20000000 bytes)");
    EXPECT_EQ(quote("abcdef", 3), "\"abc\"... (6 bytes)");
    EXPECT_EQ(quote("abc", 3), "\"abc\"");
}

TEST(Utf8, SequenceLengths) {
    EXPECT_EQ(utf8_sequence_length("a", 0), 1u);
    EXPECT_EQ(utf8_sequence_length("\xC3\xA9", 0), 2u);
    EXPECT_EQ(utf8_sequence_length("\xE2\x82\xAC", 0), 3u);
    EXPECT_EQ(utf8_sequence_length("\xF0\x9F\x98\x80", 0), 4u);
    EXPECT_EQ(utf8_sequence_length("\xA9", 0), 0u);              // stray continuation
    EXPECT_EQ(utf8_sequence_length("\xC0\xAF", 0), 0u);          // overlong '/'
    EXPECT_EQ(utf8_sequence_length("\xE0\x80\xAF", 0), 0u);      // overlong '/'
    EXPECT_EQ(utf8_sequence_length("\xED\xA0\x80", 0), 0u);      // surrogate U+D800
    EXPECT_EQ(utf8_sequence_length("\xF4\x90\x80\x80", 0), 0u);  // beyond U+10FFFF
    EXPECT_EQ(utf8_sequence_length("\xE2\x82", 0), 0u);          // cut short
    EXPECT_EQ(utf8_sequence_length("a", 1), 0u);                 // past the end
}

TEST(Utf8, ValidityAndReplacement) {
    EXPECT_TRUE(is_valid_utf8(""));
    EXPECT_TRUE(is_valid_utf8("plain caf\xC3\xA9"));
    EXPECT_FALSE(is_valid_utf8("caf\xE9"));
    EXPECT_FALSE(is_valid_utf8("\xFF"));
    EXPECT_EQ(to_valid_utf8("caf\xE9.img"), "caf\xEF\xBF\xBD.img");
    EXPECT_EQ(to_valid_utf8("\xFF\xFE"), "\xEF\xBF\xBD\xEF\xBF\xBD");
    EXPECT_EQ(to_valid_utf8("ok \xE2\x82\xAC"), "ok \xE2\x82\xAC");
    EXPECT_TRUE(is_valid_utf8(to_valid_utf8("\xC0\xAF\xED\xA0\x80\xF8")));
}

TEST(ByteSize, ParsesBytesAndBinarySuffixes) {
    EXPECT_EQ(parse_byte_size("1073741824"), std::uint64_t{1} << 30);
    EXPECT_EQ(parse_byte_size("512M"), std::uint64_t{512} << 20);
    EXPECT_EQ(parse_byte_size("4GiB"), std::uint64_t{4} << 30);
    EXPECT_EQ(parse_byte_size(" 2 kb "), std::uint64_t{2048});
    EXPECT_EQ(parse_byte_size("1.5G"), std::uint64_t{3} << 29);
    EXPECT_EQ(parse_byte_size("0.5K"), std::uint64_t{512});
    EXPECT_EQ(parse_byte_size("100B"), std::uint64_t{100});
    EXPECT_EQ(parse_byte_size("16777215T"), std::uint64_t{16777215} << 40);
    EXPECT_EQ(parse_byte_size("0"), std::uint64_t{0});  // callers refuse 0 themselves
    for (const char* bad : {"", "G", "-1", "+1", "12X", "1..5G", ".5G", "1.5.G", "1 G B",
                            "16777216T", "18446744073709551616", "1e3", "nanG"}) {
        EXPECT_FALSE(parse_byte_size(bad).has_value()) << bad;
    }
}

TEST(ByteSize, FormatsThreeSignificantDigits) {
    EXPECT_EQ(format_byte_size(0), "0 bytes");
    EXPECT_EQ(format_byte_size(1023), "1023 bytes");
    EXPECT_EQ(format_byte_size(1024), "1.00 KiB");
    EXPECT_EQ(format_byte_size(34304), "33.5 KiB");
    EXPECT_EQ(format_byte_size(256.0 * 1024 * 1024), "256 MiB");
    EXPECT_EQ(format_byte_size(8e9), "7.45 GiB");
    EXPECT_EQ(format_byte_size(3.0 * 0x1p50), "3072 TiB");
}

TEST(FormatTenDigits, DropsFloatNoiseAndTrailingZeros) {
    EXPECT_EQ(format_ten_digits(0.1 + 0.2),
              "0.3");  // the shortest round trip is 0.30000000000000004
    EXPECT_EQ(format_ten_digits(0.04), "0.04");
    EXPECT_EQ(format_ten_digits(1e-9), "1e-09");
    EXPECT_EQ(format_ten_digits(299792458.0), "299792458");
    EXPECT_EQ(format_ten_digits(-2.5), "-2.5");
    EXPECT_EQ(format_ten_digits(12345678901.0), "1.23456789e+10");  // 11 digits: rounded to 10
}

TEST(IsBlank, AsciiWhiteSpaceOnly) {
    for (const char c : std::string_view(" \t\n\r\f\v")) EXPECT_TRUE(is_blank(c)) << int(c);
    for (const char c : std::string_view("a0_,\x00\xA0")) EXPECT_FALSE(is_blank(c)) << int(c);
    EXPECT_EQ(trim(" \t a b \r\n"), "a b");
}

TEST(SplitLines, LinesWithoutTheirEndings) {
    using V = std::vector<std::string_view>;
    EXPECT_EQ(split_lines(""), V{});
    EXPECT_EQ(split_lines("a"), V{"a"});
    EXPECT_EQ(split_lines("a\n"), V{"a"});
    EXPECT_EQ(split_lines("a\r\n\nb\r\nc"), (V{"a", "", "b", "c"}));
    EXPECT_EQ(split_lines("\n\n"), (V{"", ""}));
}

}  // namespace text_test
}  // namespace glint::test
