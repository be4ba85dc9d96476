// SPDX-License-Identifier: Apache-2.0
// A file's bytes mapped read-only into memory (POSIX mmap): the operating system reads only
// the pages that are touched, and may drop them again under memory pressure (they are the
// file's, not the process's), so a 20k × 20k class map costs memory for the texels rays hit,
// not for the image. The map lasts as long as any copy of the pointer.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>

namespace glint::io {

/// The bytes [offset, offset + length) of `path`, mapped read-only. Throws glint::Error (io,
/// naming the file) when it cannot be opened or mapped, (input) when it is shorter than
/// offset + length.
std::shared_ptr<const std::uint8_t> map_file_bytes(const std::filesystem::path& path,
                                                   std::size_t offset, std::size_t length);

}  // namespace glint::io
