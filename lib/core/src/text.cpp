// SPDX-License-Identifier: Apache-2.0
// Small text helpers shared by every component (glint/core/text.h).
#include "glint/core/text.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <system_error>

namespace glint {
namespace {

constexpr char ascii_lower(char c) noexcept {
    return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
}

/// Trims blanks and drops one leading '+'; nullopt for an empty result or a second sign.
std::optional<std::string_view> strip_sign(std::string_view text) {
    text = trim(text);
    if (!text.empty() && text.front() == '+') {
        text.remove_prefix(1);
        if (!text.empty() && (text.front() == '+' || text.front() == '-')) return std::nullopt;
    }
    if (text.empty()) return std::nullopt;
    return text;
}

}  // namespace

bool is_blank(char c) noexcept {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

std::string_view trim(std::string_view text) noexcept {
    while (!text.empty() && is_blank(text.front())) text.remove_prefix(1);
    while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
    return text;
}

std::string format_ten_digits(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", value);
    return text;
}

std::string format_shortest(double value) {
    char buffer[64];  // the longest shortest-form double is 24 characters
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

namespace {

template <typename Item>
std::string join_items(std::span<const Item> items, std::string_view separator,
                       std::string_view last_separator) {
    std::string text;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (i > 0) {
            const bool last = i + 1 == items.size() && !last_separator.empty();
            text += last ? last_separator : separator;
        }
        text += items[i];
    }
    return text;
}

}  // namespace

std::string join(std::span<const std::string_view> items, std::string_view separator,
                 std::string_view last_separator) {
    return join_items(items, separator, last_separator);
}

std::string join(std::span<const std::string> items, std::string_view separator,
                 std::string_view last_separator) {
    return join_items(items, separator, last_separator);
}

namespace {

/// The code point of the valid UTF-8 sequence of `length` bytes at `text[at]`.
char32_t decode_utf8(std::string_view text, std::size_t at, std::size_t length) noexcept {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[at + k]); };
    switch (length) {
        case 1:
            return byte(0);
        case 2:
            return ((byte(0) & 0x1Fu) << 6) | (byte(1) & 0x3Fu);
        case 3:
            return ((byte(0) & 0x0Fu) << 12) | ((byte(1) & 0x3Fu) << 6) | (byte(2) & 0x3Fu);
        default:
            return ((byte(0) & 0x07u) << 18) | ((byte(1) & 0x3Fu) << 12) |
                   ((byte(2) & 0x3Fu) << 6) | (byte(3) & 0x3Fu);
    }
}

/// True for the code points a terminal acts on or that reorder what it shows: C0 and C1
/// controls and DEL (escape sequences), the bidirectional controls (U+061C, U+200E, U+200F,
/// U+202A-U+202E, U+2066-U+2069: "Trojan Source") and the line and paragraph separators.
bool is_terminal_control(char32_t c) noexcept {
    return c < 0x20 || (c >= 0x7F && c <= 0x9F) || c == 0x061C || c == 0x200E || c == 0x200F ||
           (c >= 0x202A && c <= 0x202E) || (c >= 0x2066 && c <= 0x2069) || c == 0x2028 ||
           c == 0x2029;
}

/// Appends the escape of a byte that is not UTF-8 (\xNN) or of a code point (\xNN below
/// U+0080, \uNNNN above: both as bash's $'...' reads them).
void append_escape(std::string& out, char32_t c, bool as_byte) {
    char escape[12];
    if (as_byte || c < 0x80) {
        std::snprintf(escape, sizeof escape, "\\x%02X", static_cast<unsigned>(c));
    } else {
        std::snprintf(escape, sizeof escape, "\\u%04X", static_cast<unsigned>(c));
    }
    out += escape;
}

/// `text` with what a terminal would act on escaped (`keep` lists the controls kept).
std::string escape_controls(std::string_view text, std::string_view keep) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t length = utf8_sequence_length(text, i);
        if (length == 0) {  // not UTF-8: the byte itself
            append_escape(out, static_cast<unsigned char>(text[i]), true);
            ++i;
            continue;
        }
        const char32_t c = decode_utf8(text, i, length);
        if (is_terminal_control(c) && !(length == 1 && keep.find(text[i]) != keep.npos)) {
            append_escape(out, c, false);
        } else {
            out.append(text.substr(i, length));
        }
        i += length;
    }
    return out;
}

/// `text` for bash's $'...': controls escaped as above, `\\` and `'` backslashed.
std::string escape_controls_for_bash(std::string_view text) {
    std::string out;
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t length = utf8_sequence_length(text, i);
        if (length == 0) {
            append_escape(out, static_cast<unsigned char>(text[i]), true);
            ++i;
            continue;
        }
        const char32_t c = decode_utf8(text, i, length);
        if (is_terminal_control(c) && c != '\t') {
            append_escape(out, c, false);
        } else {
            if (c == '\\' || c == '\'') out += '\\';
            out.append(text.substr(i, length));
        }
        i += length;
    }
    return out;
}

}  // namespace

std::string terminal_safe(std::string_view text) { return escape_controls(text, "\n\t"); }

std::string terminal_safe_line(std::string_view text) { return escape_controls(text, "\t"); }

std::string format_command_line(std::span<const std::string> argv) {
    std::string line;
    for (const auto& arg : argv) {
        if (!line.empty()) line += ' ';
        const bool plain = !arg.empty() && arg.find_first_not_of(
                                               "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuv"
                                               "wxyz0123456789_./=:,+%@-") == std::string::npos;
        if (plain) {
            line += arg;
            continue;
        }
        // Controls (a newline, an escape sequence, a bidi override) are written the way bash
        // reads them back, $'\n', so the line shows what runs and cannot redraw the terminal.
        if (escape_controls(arg, "\t") != arg) {
            line += "$'" + escape_controls_for_bash(arg) + "'";
            continue;
        }
        line += '\'';
        for (char c : arg) line += c == '\'' ? std::string("'\\''") : std::string(1, c);
        line += '\'';
    }
    return line;
}

std::string to_lower(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = ascii_lower(c);
    return out;
}

bool iequals(std::string_view a, std::string_view b) noexcept {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (ascii_lower(a[i]) != ascii_lower(b[i])) return false;
    }
    return true;
}

std::optional<double> parse_double(std::string_view text) {
    const std::optional<std::string_view> body = strip_sign(text);
    if (!body) return std::nullopt;
    double value = 0.0;
    const char* end = body->data() + body->size();
    const auto [ptr, ec] = std::from_chars(body->data(), end, value, std::chars_format::general);
    if (ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
    return value;
}

std::optional<std::int64_t> parse_int(std::string_view text) {
    const std::optional<std::string_view> body = strip_sign(text);
    if (!body) return std::nullopt;
    std::int64_t value = 0;
    const char* end = body->data() + body->size();
    const auto [ptr, ec] = std::from_chars(body->data(), end, value, 10);
    if (ec != std::errc() || ptr != end) return std::nullopt;
    return value;
}

std::optional<std::uint64_t> parse_byte_size(std::string_view text) {
    const std::string_view value = trim(text);
    std::size_t end = 0;
    while (end < value.size() && ((value[end] >= '0' && value[end] <= '9') || value[end] == '.')) {
        ++end;
    }
    if (end == 0 || value[0] == '.' || value.substr(0, end).find('.') != value.rfind('.', end)) {
        return std::nullopt;
    }
    double count = 0;
    const auto [ptr, ec] = std::from_chars(value.data(), value.data() + end, count);
    if (ec != std::errc() || ptr != value.data() + end) return std::nullopt;
    std::string unit = to_lower(trim(value.substr(end)));
    if (unit.size() == 3 && unit.ends_with("ib")) unit.resize(1);
    if (unit.size() == 2 && unit.back() == 'b') unit.resize(1);
    double scale = 1.0;
    if (unit == "k") {
        scale = 0x1p10;
    } else if (unit == "m") {
        scale = 0x1p20;
    } else if (unit == "g") {
        scale = 0x1p30;
    } else if (unit == "t") {
        scale = 0x1p40;
    } else if (!unit.empty() && unit != "b") {
        return std::nullopt;
    }
    const double bytes = std::floor(count * scale);
    if (!(bytes < 0x1p64)) return std::nullopt;
    return static_cast<std::uint64_t>(bytes);
}

std::string format_byte_size(double bytes) {
    if (bytes < 1024.0) return std::to_string(static_cast<long long>(bytes)) + " bytes";
    static const char* const kUnits[] = {"KiB", "MiB", "GiB", "TiB"};
    double value = bytes / 1024.0;
    std::size_t unit = 0;
    while (value >= 1024.0 && unit + 1 < std::size(kUnits)) {
        value /= 1024.0;
        ++unit;
    }
    char text[32];
    std::snprintf(text, sizeof text,
                  value < 10    ? "%.2f %s"
                  : value < 100 ? "%.1f %s"
                                : "%.0f %s",
                  value, kUnits[unit]);
    return text;
}

std::optional<bool> parse_bool(std::string_view text) {
    const std::string_view value = trim(text);
    for (std::string_view yes : {"true", "1", "yes"}) {
        if (iequals(value, yes)) return true;
    }
    for (std::string_view no : {"false", "0", "no"}) {
        if (iequals(value, no)) return false;
    }
    return std::nullopt;
}

std::vector<std::string> split_list(std::string_view text, char separator) {
    std::vector<std::string> items;
    while (true) {
        const std::size_t at = text.find(separator);
        const std::string_view item = trim(text.substr(0, at));
        if (!item.empty()) items.emplace_back(item);
        if (at == std::string_view::npos) break;
        text.remove_prefix(at + 1);
    }
    return items;
}

}  // namespace glint

namespace glint {

std::size_t utf8_sequence_length(std::string_view text, std::size_t at) noexcept {
    if (at >= text.size()) return 0;
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[at + i]); };
    const unsigned char lead = byte(0);
    if (lead < 0x80) return 1;
    std::size_t length = 0;
    std::uint32_t code = 0;
    if (lead >= 0xC2 && lead <= 0xDF) {
        length = 2;
        code = lead & 0x1Fu;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
        length = 3;
        code = lead & 0x0Fu;
    } else if (lead >= 0xF0 && lead <= 0xF4) {
        length = 4;
        code = lead & 0x07u;
    } else {
        return 0;  // a continuation byte, C0/C1 (overlong) or F5–FF
    }
    if (text.size() - at < length) return 0;
    for (std::size_t i = 1; i < length; ++i) {
        if ((byte(i) & 0xC0u) != 0x80u) return 0;
        code = (code << 6) | (byte(i) & 0x3Fu);
    }
    const bool overlong = (length == 3 && code < 0x800) || (length == 4 && code < 0x10000);
    const bool surrogate = code >= 0xD800 && code <= 0xDFFF;
    if (overlong || surrogate || code > 0x10FFFF) return 0;
    return length;
}

bool is_valid_utf8(std::string_view text) noexcept {
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t length = utf8_sequence_length(text, i);
        if (length == 0) return false;
        i += length;
    }
    return true;
}

std::string to_valid_utf8(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t length = utf8_sequence_length(text, i);
        if (length == 0) {
            out += "\xEF\xBF\xBD";  // U+FFFD REPLACEMENT CHARACTER
            ++i;
        } else {
            out.append(text.substr(i, length));
            i += length;
        }
    }
    return out;
}

std::string quote(std::string_view text, std::size_t max_bytes) {
    const std::string_view shown = text.substr(0, std::min(text.size(), max_bytes));
    std::string out = "\"";
    for (std::size_t i = 0; i < shown.size();) {
        const char c = shown[i];
        const auto byte = static_cast<unsigned char>(c);
        const std::size_t length = utf8_sequence_length(shown, i);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (c == '\n') {
            out += "\\n";
        } else if (c == '\t') {
            out += "\\t";
        } else if (c == '\r') {
            out += "\\r";
        } else if (length == 0) {
            append_escape(out, byte, true);
            ++i;
            continue;
        } else {
            const char32_t code_point = decode_utf8(shown, i, length);
            if (is_terminal_control(code_point)) {
                append_escape(out, code_point, false);
            } else {
                out.append(shown.substr(i, length));
            }
            i += length;
            continue;
        }
        ++i;
    }
    out += '"';
    if (shown.size() < text.size()) out += "... (" + std::to_string(text.size()) + " bytes)";
    return out;
}

std::vector<std::string_view> split_lines(std::string_view text) {
    std::vector<std::string_view> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        lines.push_back(line);
        start = end + 1;
    }
    return lines;
}

std::string plural(std::size_t count, std::string_view noun) {
    return std::to_string(count) + " " + std::string(noun) + (count == 1 ? "" : "s");
}

}  // namespace glint
