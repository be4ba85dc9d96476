// SPDX-License-Identifier: Apache-2.0
// Internal interface of the motion readers: what ppd_reader.cpp (GenericMotion) and
// flexmotion_reader.cpp (FlexMotion) share, implemented in motion_common.cpp: unit
// attributes, locations in scene/ECEF/geodetic frames, direction hints, CDATA data tables
// with the file line of every row, the strictly-increasing time check, and platform jitter.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "glint/core/diagnostics.h"
#include "glint/dirsig/motion_reader.h"
#include "glint/io/xml.h"
#include "glint/model/motion.h"

namespace glint::dirsig::detail {

/// Metres per unit of the length attribute `attribute` on `node` (meters, kilometers, feet);
/// `fallback` when absent; an unknown unit is an error and reads as `fallback`.
double length_unit_factor(const io::XmlNode& node, std::string_view attribute, double fallback,
                          Diagnostics& diagnostics);

/// Radians per unit of the angle attribute `attribute` on `node` (degrees, radians);
/// `fallback` when absent; an unknown unit is an error and reads as `fallback`.
double angle_unit_factor(const io::XmlNode& node, std::string_view attribute, double fallback,
                         Diagnostics& diagnostics);

/// Numbers separated by commas and/or blanks; nullopt when any item is not a number.
std::optional<std::vector<double>> parse_number_list(std::string_view text);

/// A location under `node`: its frame from @frame or @type (scene, ecef, geodetic; default
/// scene); scene/ECEF x, y, z from a `<point>` child, from `<x>`, `<y>`, `<z>` children or
/// from the text "x, y, z"; geodetic from `<latitude>`, `<longitude>`, `<altitude>` children
/// or the text "lat, lon, alt". Lengths are multiplied by `length_factor`. Problems are
/// errors; nullopt when the location could not be read.
std::optional<model::Location> read_location(const io::XmlNode& node, double length_factor,
                                             Diagnostics& diagnostics);

/// A direction hint (`<constraint>`, `<up>`): @type constant (or velocity when
/// `allow_velocity`), @frame scene or ecef, @vector (or the text) "x, y, z", not zero.
model::DirectionHint read_direction_hint(const io::XmlNode& node, bool allow_velocity,
                                         Diagnostics& diagnostics);

/// The message for a time that does not follow the previous one (nullopt when it does):
/// "<label> 3 has the same time (5 s) as <label> 2: duplicate times, expected strictly
/// increasing times" or "<label> 3 time 4 s is before <label> 2's 5 s, expected strictly
/// increasing times". `index` is 1-based.
std::optional<std::string> time_order_problem(std::string_view label, std::size_t index,
                                              double previous_s, double time_s);

/// The rows of a `<data>` table: @source internal, @datetime relative, @delimiter one
/// character (default ","); each non-blank line of the text (CDATA) holds a time and
/// `value_count` numbers (`columns` names them for messages, e.g. "t, x, y, z"); lines
/// starting with '#' are comments. Times must increase strictly. Each bad row is an error at
/// its own file line (see MotionReadContext::source_text). At least one row is required.
std::vector<model::MotionTableRow> read_table(const io::XmlNode& data, std::size_t value_count,
                                              std::string_view columns,
                                              const MotionReadContext& context,
                                              Diagnostics& diagnostics);

/// The `<locationjitter>` and `<orientationjitter>` children of `parent` (absent or empty:
/// no jitter).
model::PlatformJitter read_platform_jitter(const io::XmlNode& parent,
                                           const MotionReadContext& context,
                                           Diagnostics& diagnostics);

}  // namespace glint::dirsig::detail
