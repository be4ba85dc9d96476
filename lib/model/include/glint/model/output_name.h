// SPDX-License-Identifier: Apache-2.0
// What an output name part may hold. An image's file name is built from parts the user
// wrote — `<prefix><basename>[-tTTTT[-cCCCC]].<extension>` — and is joined to the output
// folder; a part holding a folder separator, `..` or a control character could name a
// file outside that folder (or an unprintable one), so such parts are refused where they
// are read.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace glint::model {

/// Why `text` cannot be part of an output file name (prefix, basename or extension), or
/// nullopt when it can: no `/` or `\`, no `..`, no control character (bytes below 0x20
/// and 0x7F). `text` may be empty (an empty prefix).
std::optional<std::string> output_name_problem(std::string_view text);

}  // namespace glint::model
