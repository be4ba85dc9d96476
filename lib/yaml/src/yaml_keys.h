// SPDX-License-Identifier: Apache-2.0
// Reading one key's value from a yaml-cpp mapping with its problems at file:line — shared by
// the atmosphere reader and its aerosol profile (atmosphere_reader.cpp,
// aerosol_profile_reader.cpp).
#pragma once

#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>

#include "glint/core/diagnostics.h"

namespace glint::yaml::detail {

/// `file`, the line of `node` (0 when yaml-cpp has none) and `key`.
ErrorContext at(const std::string& file, const YAML::Node& node, std::string key);

/// A number rule for YAML values: lo/hi bounds, each inclusive or exclusive.
struct Bounds {
    std::optional<double> lo;
    std::optional<double> hi;
    bool lo_open = false;
    bool hi_open = false;
    std::string text;  ///< e.g. "a number >= 0"
};

/// The number at `node` (named `key` in messages), or nullopt after an error at its line:
/// "expected <text>" for a value that is not a number, "value V out of range, expected <text>"
/// for one outside `bounds`.
std::optional<double> number_at(const YAML::Node& node, const std::string& file,
                                const std::string& key, const Bounds& bounds,
                                Diagnostics& diagnostics);

/// `map[key]` into `value` when present and valid (number_at's errors otherwise); an absent key
/// leaves `value` as it was.
void read_number(const YAML::Node& map, const char* key, const std::string& file,
                 const Bounds& bounds, double& value, Diagnostics& diagnostics);

/// `map[key]` when present and valid; nullopt when absent or after number_at's error.
std::optional<double> read_optional_number(const YAML::Node& map, const char* key,
                                           const std::string& file, const Bounds& bounds,
                                           Diagnostics& diagnostics);

}  // namespace glint::yaml::detail
