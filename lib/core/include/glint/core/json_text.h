// SPDX-License-Identifier: Apache-2.0
// JSON text of any value glint writes, whatever bytes its strings hold. JSON must be UTF-8,
// and nlohmann::json's plain dump() throws on other bytes — a Latin-1 file name in a .sim or
// byte 0xFF in an ENVI header would stop a tool with an internal error. Every JSON output
// goes through json_text, which writes each byte that is not UTF-8 as U+FFFD instead.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace glint {

/// `value` (nlohmann::json or ordered_json, whose key order is kept) as JSON text
/// (`indent` < 0: one line), bytes that are not UTF-8 replaced by U+FFFD.
template <typename Json>
std::string json_text(const Json& value, int indent = -1) {
    return value.dump(indent, ' ', false, Json::error_handler_t::replace);
}

}  // namespace glint
