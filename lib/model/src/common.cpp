// SPDX-License-Identifier: Apache-2.0
// Helpers of the shared model pieces: looking up metadata entries by name.
#include "glint/model/common.h"

#include <algorithm>
#include <cctype>

namespace glint::model {

std::optional<std::string> Metadata::find(const std::string& name) const {
    const auto same = [&name](const std::string& other) {
        return other.size() == name.size() &&
               std::equal(other.begin(), other.end(), name.begin(), [](char a, char b) {
                   return std::tolower(static_cast<unsigned char>(a)) ==
                          std::tolower(static_cast<unsigned char>(b));
               });
    };
    for (const auto& [key, value] : entries) {
        if (same(key)) return value;
    }
    return std::nullopt;
}

}  // namespace glint::model
