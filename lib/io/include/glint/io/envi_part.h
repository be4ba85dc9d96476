// SPDX-License-Identifier: Apache-2.0
// The capture keys glint-render writes into every image, and the header keys of a *part*: an ENVI
// image a sharded glint-render wrote that holds some of the lines or captures of the file one run
// writes (docs/scale.md). glint-render writes them; glint-envi merge reads them to join parts into
// the whole file. A file that holds all of its lines and captures carries none of them and is the
// whole file.
//
//   glint part rows = {A, B}              lines A … B−1 of each capture it holds
//   glint part lines per capture = L      lines of each capture in the whole file
//   glint part of captures = {0:4, 7, 9:11}  global capture indices of the whole file
//
// The part's own `glint lines per capture` is B − A and its capture lists hold its
// captures, so every other tool reads a part as the image it is.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glint::io {

/// The capture keys of every glint-render image (which captures it holds, in file order).
inline constexpr const char* kCapturesKey = "glint captures";
inline constexpr const char* kLinesPerCaptureKey = "glint lines per capture";
inline constexpr const char* kIdsKey = "glint capture ids";
inline constexpr const char* kIndicesKey = "glint capture indices";
inline constexpr const char* kWindowsKey = "glint capture windows s";
inline constexpr const char* kDatetimesKey = "glint capture datetimes utc";

/// The part keys.
inline constexpr const char* kPartRowsKey = "glint part rows";
inline constexpr const char* kPartLinesPerCaptureKey = "glint part lines per capture";
inline constexpr const char* kPartCapturesKey = "glint part of captures";

/// Sorted indices as a brace list of runs: consecutive indices A … B−1 as "A:B", a lone index
/// as "N" ({0:4, 7, 9:11}).
std::string format_index_runs(const std::vector<std::uint64_t>& sorted);
/// The indices of a brace list format_index_runs writes, sorted; nullopt when it is not one
/// (junk, a run B <= A, indices out of order or repeated) or names more than 2^32 indices.
std::optional<std::vector<std::uint64_t>> parse_index_runs(std::string_view value);
/// How many indices the brace list `value` holds, without listing them (a few bytes can
/// name 2^64 indices); nullopt when it is not a list parse_index_runs reads.
std::optional<std::uint64_t> count_index_runs(std::string_view value);

}  // namespace glint::io
