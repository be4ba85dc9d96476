// SPDX-License-Identifier: Apache-2.0
// What the DIRSIG BIN reader (lidar_bin_reader.cpp) and writer (lidar_bin_writer.cpp) share:
// the magic the file starts with.
#pragma once

#include <cstddef>

namespace glint::io::bin_detail {

inline constexpr char kMagic[] = "DIRSIGPROTO";  // 11 characters, no NUL in the file
inline constexpr std::size_t kMagicSize = 11;

}  // namespace glint::io::bin_detail
