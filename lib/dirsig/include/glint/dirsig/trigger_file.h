// SPDX-License-Identifier: Apache-2.0
// Trigger files of external (irregular) clocks: a text file of trigger times in seconds after
// the tasks' reference time, read by the input loader (the period with which the list repeats when
// a task outlasts it is schedule::trigger_period_s) (docs/schedule.md, "External triggers").
//
// clang-format off
// | content | rule |
// |---|---|
// | numbers | decimal or exponent notation (`0.1`, `+2.5e-3`, `-1`), finite; negative allowed (task times may be negative) |
// | separators | blanks, tabs, commas, semicolons, newlines (LF or CRLF) |
// | comments | `#` to the end of the line |
// | order | strictly increasing: a time equal to or before the previous one is an error |
// | count | at least one time |
// clang-format on
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "glint/core/diagnostics.h"
#include "glint/dirsig/read_options.h"

namespace glint::dirsig {

/// Reads the trigger times of `file`. Every problem (unreadable file, a token that is not a
/// finite number, a time not after the previous one, no time at all) goes to `diagnostics`
/// as an error at `file:line`; the times that were valid are returned.
std::vector<double> read_trigger_file(const std::filesystem::path& file, const ReadOptions& options,
                                      Diagnostics& diagnostics);

/// Parses trigger times from `text` (the content of a file named `file_name` in messages),
/// with the rules of read_trigger_file.
std::vector<double> parse_trigger_times(std::string_view text, const std::string& file_name,
                                        Diagnostics& diagnostics);

}  // namespace glint::dirsig
