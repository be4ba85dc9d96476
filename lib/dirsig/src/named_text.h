// SPDX-License-Identifier: Apache-2.0
// Reading a small text file a platform names (a trigger file, a pulse shape) for a reader that
// reports into Diagnostics rather than throwing.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "glint/core/diagnostics.h"
#include "glint/dirsig/read_options.h"

namespace glint::dirsig::detail {

/// The text of `file` (named `name` in messages), or nullopt after one error at `name` saying
/// "cannot open <what>: <reason>" (or the reader's own message for other failures).
std::optional<std::string> read_named_text(const std::filesystem::path& file,
                                           const std::string& name, const std::string& what,
                                           const ReadOptions& options, Diagnostics& diagnostics);

}  // namespace glint::dirsig::detail
