// SPDX-License-Identifier: Apache-2.0
// What an output name part may hold (see output_name.h).
#include "glint/model/output_name.h"

#include <cstdio>

namespace glint::model {

std::optional<std::string> output_name_problem(std::string_view text) {
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (c == '/' || c == '\\') {
            return std::string("contains '") + c +
                   "', expected a file name without folder separators (the output folder "
                   "says where files go)";
        }
        if (byte < 0x20 || byte == 0x7F) {
            char code[8];
            std::snprintf(code, sizeof code, "0x%02X", byte);
            return std::string("contains the control character ") + code +
                   ", expected printable characters";
        }
    }
    if (text.find("..") != std::string_view::npos) {
        return "contains '..', expected a file name that cannot name a parent folder";
    }
    return std::nullopt;
}

}  // namespace glint::model
