// SPDX-License-Identifier: Apache-2.0
// Small text helpers shared by every component: number formatting for messages and file
// writers, whole-string number parsing (std::from_chars: no locale, no trailing junk, no
// NaN/infinity, no hex), ASCII case folding for case-insensitive names, list splitting.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

/// The shortest text that reads back as exactly `value` ("0.55", "1e-300", "inf").
std::string format_shortest(double value);

/// `value` for a message: up to 10 significant digits, no trailing zeros ("%.10g": "0.3",
/// "1e-05", "299792458").
std::string format_ten_digits(double value);

/// ASCII white space: space, tab, newline, carriage return, form feed, vertical tab.
bool is_blank(char c) noexcept;

/// `text` with ASCII letters lowered (other bytes unchanged, whatever the locale).
std::string to_lower(std::string_view text);

/// True when `a` and `b` are equal ignoring ASCII case.
bool iequals(std::string_view a, std::string_view b) noexcept;

/// "1 error", "3 errors": the count and the noun, with an "s" unless the count is 1.
std::string plural(std::size_t count, std::string_view noun);

/// The items separated by `separator`, the last two by `last_separator` when one is given:
/// join({"a", "b", "c"}, ", ", " or ") is "a, b or c".
std::string join(std::span<const std::string_view> items, std::string_view separator,
                 std::string_view last_separator = {});
/// The same for strings.
std::string join(std::span<const std::string> items, std::string_view separator,
                 std::string_view last_separator = {});

/// Quotes an argv for a log line (single quotes where needed; an argument holding a control
/// character as bash's $'...' with the control escaped). For display only: nothing glint
/// runs goes through a shell.
std::string format_command_line(std::span<const std::string> argv);

/// `text` safe to print on a terminal, whatever an input file held: C0 and C1 control
/// characters but newline and tab, DEL, the bidirectional controls (U+061C, U+200E, U+200F,
/// U+202A-U+202E, U+2066-U+2069), U+2028 and U+2029 written as \xNN or \uNNNN, and bytes
/// that are not UTF-8 as \xNN. The tool runner passes every message through it.
std::string terminal_safe(std::string_view text);
/// The same with newlines escaped too (\x0A): for text that must stay one line.
std::string terminal_safe_line(std::string_view text);

/// `text` in double quotes for a message: control characters, `"`, `\\` and bytes that are
/// not UTF-8 written as escapes (\n, \", \xFF), and cut after `max_bytes` bytes of input
/// with "..." and the full size, so a 20 MB token is never echoed whole.
std::string quote(std::string_view text, std::size_t max_bytes = 80);

/// Length of the valid UTF-8 sequence starting at `text[at]` (1–4), or 0 when the bytes
/// there are not one (stray continuation, overlong form, surrogate, beyond U+10FFFF, cut).
std::size_t utf8_sequence_length(std::string_view text, std::size_t at) noexcept;

/// True when `text` is entirely valid UTF-8.
bool is_valid_utf8(std::string_view text) noexcept;

/// `text` with each byte that is not part of valid UTF-8 replaced by U+FFFD, so it can go
/// into JSON (which must be UTF-8) whatever bytes a file name or header held.
std::string to_valid_utf8(std::string_view text);

/// `text` without leading and trailing blanks (space, tab, CR, LF, FF, VT).
std::string_view trim(std::string_view text) noexcept;

/// Parses a whole string as a finite double (leading '+' allowed, surrounding blanks
/// trimmed); nullopt otherwise.
std::optional<double> parse_double(std::string_view text);
/// Parses a whole string as a base-10 integer; nullopt otherwise (or on overflow).
std::optional<std::int64_t> parse_int(std::string_view text);
/// Parses a size in bytes: a number (digits, one optional decimal point), optionally followed
/// by K, M, G or T (powers of 1024, any case, optionally with "iB" or "B": "512M", "1.5G",
/// "4GiB", "1073741824"), rounded down to whole bytes; nullopt for anything else or a size of
/// 2^64 bytes or more.
std::optional<std::uint64_t> parse_byte_size(std::string_view text);
/// A size for messages: "160 bytes" below 1 KiB, else three significant digits of KiB, MiB,
/// GiB or TiB ("3.44 MiB", "10.0 GiB").
std::string format_byte_size(double bytes);
/// true/false/1/0/yes/no in any case; nullopt otherwise.
std::optional<bool> parse_bool(std::string_view text);
/// Splits "a, b,c" on commas (or `separator`), trimming each item; empty items dropped.
std::vector<std::string> split_list(std::string_view text, char separator = ',');

/// The lines of `text` (split at '\n', each without its '\n' or a trailing '\r'; no line
/// after a final '\n'). Line k of the result is line k + 1 of the file.
std::vector<std::string_view> split_lines(std::string_view text);

}  // namespace glint
