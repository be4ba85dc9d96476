// SPDX-License-Identifier: Apache-2.0
// One key's value with its problems at file:line (yaml_keys.h).
#include "yaml_keys.h"

#include <utility>

#include "glint/core/text.h"

namespace glint::yaml::detail {

ErrorContext at(const std::string& file, const YAML::Node& node, std::string key) {
    return ErrorContext{file, node.Mark().line >= 0 ? node.Mark().line + 1 : 0, std::move(key)};
}

std::optional<double> number_at(const YAML::Node& node, const std::string& file,
                                const std::string& key, const Bounds& bounds,
                                Diagnostics& diagnostics) {
    const ErrorContext where = at(file, node, key);
    std::optional<double> parsed;
    if (node.IsScalar()) parsed = parse_double(node.Scalar());
    if (!parsed) {
        diagnostics.error(where, "expected " + bounds.text);
        return std::nullopt;
    }
    const double v = *parsed;
    const bool low_bad = bounds.lo && (bounds.lo_open ? v <= *bounds.lo : v < *bounds.lo);
    const bool high_bad = bounds.hi && (bounds.hi_open ? v >= *bounds.hi : v > *bounds.hi);
    if (low_bad || high_bad) {
        diagnostics.error(where,
                          "value " + format_shortest(v) + " out of range, expected " + bounds.text);
        return std::nullopt;
    }
    return v;
}

void read_number(const YAML::Node& map, const char* key, const std::string& file,
                 const Bounds& bounds, double& value, Diagnostics& diagnostics) {
    if (const auto v = read_optional_number(map, key, file, bounds, diagnostics)) value = *v;
}

std::optional<double> read_optional_number(const YAML::Node& map, const char* key,
                                           const std::string& file, const Bounds& bounds,
                                           Diagnostics& diagnostics) {
    const YAML::Node node = map[key];
    if (!node) return std::nullopt;
    return number_at(node, file, key, bounds, diagnostics);
}

}  // namespace glint::yaml::detail
