// SPDX-License-Identifier: Apache-2.0
// The check every input goes through before it is opened: only a regular file (a symbolic
// link is followed) is read. Opening a FIFO blocks until someone writes to it, /dev/zero
// never ends, a socket or a terminal waits for input — and archives and hand-made folders
// carry such entries — so glint refuses them by their type, before opening (standard input
// has its own, explicit name: "-").
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace glint::io {

/// What `path` is when it exists and is not a regular file — "is a folder", "is a FIFO (a
/// named pipe)", "is a socket", "is a device" — or nullopt for a regular file or nothing
/// readable there (opening it then says why). Reads the type with stat(2): nothing is opened.
std::optional<std::string> not_a_regular_file(const std::filesystem::path& path);

/// Throws glint::Error (io) naming `display_name` (default: the path), "<what>, expected a
/// <kind>", when not_a_regular_file says `path` is something else than a regular file.
void require_regular_file(const std::filesystem::path& path, const std::string& display_name = {},
                          std::string_view kind = "file");

}  // namespace glint::io
