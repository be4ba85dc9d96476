// SPDX-License-Identifier: Apache-2.0
// Trigger files of external clocks: tokenising (blanks, commas, semicolons, newlines, `#`
// comments), number checks with file:line, strict ordering, and the repeat period.
#include "glint/dirsig/trigger_file.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <system_error>

#include "glint/core/error.h"
#include "glint/core/text.h"
#include "named_text.h"

namespace glint::dirsig {

namespace {

bool is_separator(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v' || c == ',' ||
           c == ';';
}

}  // namespace

std::vector<double> parse_trigger_times(std::string_view text, const std::string& file_name,
                                        Diagnostics& diagnostics) {
    std::vector<double> times;
    int line = 1;
    int previous_line = 0;
    bool any_error = false;
    std::size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        if (c == '\n') {
            ++line;
            ++i;
        } else if (is_separator(c)) {
            ++i;
        } else if (c == '#') {
            while (i < text.size() && text[i] != '\n') ++i;
        } else {
            const std::size_t begin = i;
            while (i < text.size() && !is_separator(text[i]) && text[i] != '#') ++i;
            const std::string_view token = text.substr(begin, i - begin);
            const ErrorContext where{file_name, line, ""};
            const std::optional<double> value = parse_double(token);  // the token has no blanks
            if (!value) {
                any_error = true;
                diagnostics.error(where, "trigger time \"" + std::string(token) +
                                             "\" is not a finite number, expected seconds "
                                             "after the reference time");
            } else if (!times.empty() && *value <= times.back()) {
                any_error = true;
                diagnostics.error(where, "trigger time " + format_shortest(*value) + " s is " +
                                             (*value == times.back() ? "equal to" : "before") +
                                             " the previous one (" + format_shortest(times.back()) +
                                             " s at line " + std::to_string(previous_line) +
                                             "), expected strictly increasing times");
            } else {
                times.push_back(*value);
                previous_line = line;
            }
        }
    }
    if (times.empty() && !any_error) {
        diagnostics.error(ErrorContext{file_name, 0, ""},
                          "no trigger time in the file, expected at least one time in seconds");
    }
    return times;
}

std::vector<double> read_trigger_file(const std::filesystem::path& file, const ReadOptions& options,
                                      Diagnostics& diagnostics) {
    const std::string name = file.string();
    std::error_code ec;
    if (std::filesystem::is_directory(file, ec)) {
        diagnostics.error(ErrorContext{name, 0, ""}, "cannot read trigger file: it is a directory");
        return {};
    }
    const std::optional<std::string> text =
        detail::read_named_text(file, name, "trigger file", options, diagnostics);
    if (!text) return {};
    return parse_trigger_times(*text, name, diagnostics);
}

}  // namespace glint::dirsig
