// SPDX-License-Identifier: Apache-2.0
// The line budget of the line-by-line readers (io::EnviReader, io::ImageReader): tools plan
// for at most kLinesPerMaxMemory lines as doubles within their --max-memory, so a reader
// refuses, before allocating anything, a line over max_memory / kLinesPerMaxMemory.
#pragma once

#include <cstddef>
#include <filesystem>

#include "glint/core/context.h"

namespace glint::io {

/// Lines (as doubles) a line-by-line tool may hold within its --max-memory.
inline constexpr std::size_t kLinesPerMaxMemory = 16;
/// The largest line a reader opens by default, as doubles (256 MiB, a sixteenth of the default
/// --max-memory: 3.3·10⁷ values, e.g. 10⁵ samples × 335 bands).
inline constexpr std::size_t kMaxLineBytes = kDefaultMaxMemoryBytes / kLinesPerMaxMemory;

/// Throws glint::Error (input) at `file` when a line of `samples` × `bands` doubles is over
/// `max_memory_bytes` / kLinesPerMaxMemory, naming the memory it needs and the --max-memory
/// that would read it.
void check_line_memory(std::size_t samples, std::size_t bands, std::size_t max_memory_bytes,
                       const std::filesystem::path& file);

}  // namespace glint::io
