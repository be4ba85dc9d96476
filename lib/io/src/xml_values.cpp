// SPDX-License-Identifier: Apache-2.0
// Value readers of the XML node view: whole-string number, integer and boolean parsing with
// std::from_chars (no locale, no trailing junk, no NaN/infinity, no hex), numeric rules, and
// the XmlNode readers that report a bad or missing value to Diagnostics as
// `expected <what>, got "<text>"` at the element (or attribute) that holds it.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>

#include "glint/core/text.h"
#include "glint/io/xml.h"

namespace glint::io {
namespace {

/// A number for messages: integers without a fraction, others in shortest round-trip form.
std::string format_number(double value) {
    if (std::abs(value) < 1e15 && value == std::trunc(value)) {
        return std::to_string(static_cast<std::int64_t>(value));
    }
    return format_shortest(value);
}

std::string describe_int_range(std::int64_t min, std::int64_t max) {
    constexpr auto kLowest = std::numeric_limits<std::int64_t>::min();
    constexpr auto kHighest = std::numeric_limits<std::int64_t>::max();
    if (min == kLowest && max == kHighest) return "an integer";
    if (max == kHighest) return "an integer >= " + std::to_string(min);
    if (min == kLowest) return "an integer <= " + std::to_string(max);
    return "an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
}

std::string describe_enum(std::initializer_list<std::string_view> allowed) {
    return "one of " +
           join(std::span<const std::string_view>(allowed.begin(), allowed.size()), ", ");
}

std::optional<double> check_double(std::string_view text, const ErrorContext& where,
                                   const NumberRule& rule, Diagnostics& diagnostics) {
    const std::optional<double> value = parse_double(text);
    if (!value || !rule.accepts(*value)) {
        diagnostics.error(where, "expected " + rule.describe() + ", got " + quote(trim(text)));
        return std::nullopt;
    }
    return value;
}

std::optional<std::int64_t> check_int(std::string_view text, const ErrorContext& where,
                                      std::int64_t min, std::int64_t max,
                                      Diagnostics& diagnostics) {
    const std::optional<std::int64_t> value = parse_int(text);
    if (!value || *value < min || *value > max) {
        diagnostics.error(
            where, "expected " + describe_int_range(min, max) + ", got " + quote(trim(text)));
        return std::nullopt;
    }
    return value;
}

std::optional<bool> check_bool(std::string_view text, const ErrorContext& where,
                               Diagnostics& diagnostics) {
    const std::optional<bool> value = parse_bool(text);
    if (!value) {
        diagnostics.error(
            where, "expected a boolean (true, false, yes, no, 1 or 0), got " + quote(trim(text)));
    }
    return value;
}

std::optional<std::string> check_enum(std::string_view text,
                                      std::initializer_list<std::string_view> allowed,
                                      const ErrorContext& where, Diagnostics& diagnostics) {
    const std::string_view value = trim(text);
    for (std::string_view item : allowed) {
        if (iequals(value, item)) return std::string(item);
    }
    diagnostics.error(where, "expected " + describe_enum(allowed) + ", got " + quote(value));
    return std::nullopt;
}

}  // namespace

// ---- NumberRule ----

bool NumberRule::accepts(double value) const {
    if (!std::isfinite(value)) return false;
    if (min && (min_exclusive ? value <= *min : value < *min)) return false;
    if (max && (max_exclusive ? value >= *max : value > *max)) return false;
    return true;
}

std::string NumberRule::describe() const {
    if (min && max) {
        return std::string("a number in ") + (min_exclusive ? "(" : "[") + format_number(*min) +
               ", " + format_number(*max) + (max_exclusive ? ")" : "]");
    }
    if (min) return std::string("a number ") + (min_exclusive ? "> " : ">= ") + format_number(*min);
    if (max) return std::string("a number ") + (max_exclusive ? "< " : "<= ") + format_number(*max);
    return "a number";
}

// ---- XmlNode value readers ----

std::optional<double> XmlNode::optional_double(std::string_view name, Diagnostics& diagnostics,
                                               NumberRule rule) const {
    const auto node = child(name);
    if (!node) return std::nullopt;
    return check_double(node->text(), node->where(), rule, diagnostics);
}

std::optional<double> XmlNode::required_double(std::string_view name, Diagnostics& diagnostics,
                                               NumberRule rule) const {
    if (!child(name)) {
        diagnostics.error(where(), "missing required element <" + std::string(name) + ">");
        return std::nullopt;
    }
    return optional_double(name, diagnostics, rule);
}

std::optional<std::int64_t> XmlNode::optional_int(std::string_view name, Diagnostics& diagnostics,
                                                  std::int64_t min, std::int64_t max) const {
    const auto node = child(name);
    if (!node) return std::nullopt;
    return check_int(node->text(), node->where(), min, max, diagnostics);
}

std::optional<std::int64_t> XmlNode::required_int(std::string_view name, Diagnostics& diagnostics,
                                                  std::int64_t min, std::int64_t max) const {
    if (!child(name)) {
        diagnostics.error(where(), "missing required element <" + std::string(name) + ">");
        return std::nullopt;
    }
    return optional_int(name, diagnostics, min, max);
}

std::optional<bool> XmlNode::optional_bool(std::string_view name, Diagnostics& diagnostics) const {
    const auto node = child(name);
    if (!node) return std::nullopt;
    return check_bool(node->text(), node->where(), diagnostics);
}

std::optional<std::string> XmlNode::optional_enum(std::string_view name,
                                                  std::initializer_list<std::string_view> allowed,
                                                  Diagnostics& diagnostics) const {
    const auto node = child(name);
    if (!node) return std::nullopt;
    return check_enum(node->text(), allowed, node->where(), diagnostics);
}

std::optional<double> XmlNode::attribute_double(std::string_view name, Diagnostics& diagnostics,
                                                NumberRule rule) const {
    const auto value = attribute(name);
    if (!value) return std::nullopt;
    return check_double(*value, where_attribute(name), rule, diagnostics);
}

std::optional<bool> XmlNode::attribute_bool(std::string_view name, Diagnostics& diagnostics) const {
    const auto value = attribute(name);
    if (!value) return std::nullopt;
    return check_bool(*value, where_attribute(name), diagnostics);
}

std::optional<std::string> XmlNode::attribute_enum(std::string_view name,
                                                   std::initializer_list<std::string_view> allowed,
                                                   Diagnostics& diagnostics) const {
    const auto value = attribute(name);
    if (!value) return std::nullopt;
    return check_enum(*value, allowed, where_attribute(name), diagnostics);
}

std::optional<double> XmlNode::own_double(Diagnostics& diagnostics, NumberRule rule) const {
    return check_double(text(), where(), rule, diagnostics);
}

}  // namespace glint::io
