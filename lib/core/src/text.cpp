// SPDX-License-Identifier: Apache-2.0
// Number formatting shared by messages and file writers.
#include "glint/core/text.h"

#include <charconv>

namespace glint {

std::string format_shortest(double value) {
    char buffer[64];  // the longest shortest-form double is 24 characters
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

}  // namespace glint
