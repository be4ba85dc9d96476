// SPDX-License-Identifier: Apache-2.0
// Parsing YAML text into a yaml-cpp node, with the problems as diagnostics at file:line —
// shared by the scene and atmosphere readers.
#pragma once

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>

#include "glint/core/diagnostics.h"

namespace glint::yaml::detail {

/// Deepest nesting yaml-cpp parses (its DepthGuard); deeper input is refused with this
/// number in the message.
inline constexpr int kMaxYamlDepth = 2000;

/// The document of `text`, or nullopt after an error in `diagnostics` naming `file` and the
/// line: "invalid YAML: <yaml-cpp's message>", or for input nested deeper than
/// kMaxYamlDepth "invalid YAML: nested deeper than 2000 levels".
std::optional<YAML::Node> parse_yaml(const std::string& text, const std::string& file,
                                     Diagnostics& diagnostics);

}  // namespace glint::yaml::detail
