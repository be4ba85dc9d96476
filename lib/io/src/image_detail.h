// SPDX-License-Identifier: Apache-2.0
// What the image reader (image_reader.cpp) and writer (image_writer.cpp) share: the error
// context of a file, OIIO's messages on one line, the bytes of a stored value.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

#include "glint/core/error.h"
#include "image_backend.h"

namespace glint::io::image_detail {

using detail::RawType;

inline ErrorContext at_file(const std::filesystem::path& path) {
    return ErrorContext{path.string(), 0, {}};
}

/// OIIO messages may span lines; diagnostics are one line.
inline std::string one_line(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    for (char& c : text) {
        if (c == '\n') c = ' ';
    }
    return text.empty() ? std::string("unknown OpenImageIO error") : text;
}

/// Bytes of one value stored as `type`.
inline std::size_t raw_size(RawType type) {
    switch (type) {
        case RawType::uint8:
        case RawType::int8:
            return 1;
        case RawType::uint16:
        case RawType::int16:
        case RawType::half:
            return 2;
        case RawType::uint32:
        case RawType::int32:
        case RawType::float32:
            return 4;
        case RawType::float64:
            return 8;
    }
    return 8;
}

}  // namespace glint::io::image_detail
