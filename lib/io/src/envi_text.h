// SPDX-License-Identifier: Apache-2.0
// Internal text helpers shared by the ENVI header parser and formatter: trimming, key
// normalization, brace lists, and the set of keys glint models.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace glint::io::detail {

/// Whether `key` (normalized) is one of the header keys EnviHeader models.
bool is_standard_key(std::string_view key);
/// Blank characters of a header: space, tab, CR, LF, FF, VT.
bool is_space(char c);
/// `text` without leading and trailing blanks.
std::string_view trim(std::string_view text);
/// Lowercase, surrounding blanks removed, inner runs of blanks collapsed to one space.
std::string normalize_key(std::string_view key);
/// The text between braces (trimmed), or the whole value when it has none.
std::string_view brace_content(std::string_view value);
/// The comma-separated items of a brace value, each trimmed; `{}` gives none.
std::vector<std::string> split_list(std::string_view value);

}  // namespace glint::io::detail
