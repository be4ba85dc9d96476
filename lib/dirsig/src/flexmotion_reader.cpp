// SPDX-License-Identifier: Apache-2.0
// Reader of FlexMotion (`<motion type="flexible">`, a `.motion` file or inline in a GLIST):
// the location engines (waypoints, straight, fixed, sgp4), the orientation engines
// (velocity, lookat, euler, quaternions, spin) and the platform jitter. The XML glint
// defines where DIRSIG's is unknown (fixed, lookat targets, euler/quaternion tables, spin)
// is listed in glint/model/motion.h and docs/motion.md ("Platform motion files and trajectories").
#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "glint/core/units.h"
#include "motion_parts.h"
#include "platform_tree.h"

namespace glint::dirsig {

namespace {

using detail::lower_trimmed;

/// The required child `name` of `node` (an error when missing).
std::optional<io::XmlNode> required_child(const io::XmlNode& node, std::string_view name,
                                          std::string_view why, Diagnostics& diagnostics) {
    std::optional<io::XmlNode> child = node.child(name);
    if (!child) {
        diagnostics.error(node.where(),
                          "missing required element <" + std::string(name) + ">" +
                              (why.empty() ? std::string() : " (" + std::string(why) + ")"));
    }
    return child;
}

/// @type of an engine element as one of `names` (index), or nullopt after an error.
std::optional<std::size_t> engine_type(const io::XmlNode& node,
                                       std::initializer_list<std::string_view> names,
                                       Diagnostics& diagnostics) {
    std::string list;
    std::size_t i = 0;
    for (const std::string_view name : names) {
        if (i > 0) list += i + 1 == names.size() ? " or " : ", ";
        list += name;
        ++i;
    }
    const std::string what = node.name() == "locationengine" ? "location" : "orientation";
    const std::optional<std::string> raw = node.attribute("type");
    if (!raw) {
        diagnostics.error(node.where(), "missing required attribute type, expected " + list);
        return std::nullopt;
    }
    const std::string type = lower_trimmed(*raw);
    std::size_t index = 0;
    for (const std::string_view name : names) {
        if (type == name) return index;
        ++index;
    }
    diagnostics.error(node.where_attribute("type"),
                      "unknown " + what + " engine type \"" + *raw + "\", expected " + list);
    return std::nullopt;
}

model::LocationEngine read_location_engine(const io::XmlNode& node,
                                           const MotionReadContext& context,
                                           Diagnostics& diagnostics) {
    model::LocationEngine engine;
    engine.where = node.where();
    const std::optional<std::size_t> type =
        engine_type(node, {"waypoints", "straight", "fixed", "sgp4"}, diagnostics);
    if (!type) return engine;
    switch (*type) {
        case 0: {
            engine.type = model::LocationEngineType::waypoints;
            node.warn_unknown_children({"data"}, diagnostics);
            const std::optional<io::XmlNode> data =
                required_child(node, "data", "the waypoint table", diagnostics);
            if (!data) break;
            if (const std::optional<std::string> raw = data->attribute("frame")) {
                const std::string frame = lower_trimmed(*raw);
                if (frame == "scene") {
                    engine.waypoint_frame = model::LocationFrame::scene;
                } else if (frame == "ecef") {
                    engine.waypoint_frame = model::LocationFrame::ecef;
                } else if (frame == "geodetic") {
                    engine.waypoint_frame = model::LocationFrame::geodetic;
                } else {
                    diagnostics.error(data->where_attribute("frame"),
                                      "unknown waypoint frame \"" + *raw +
                                          "\", expected scene, ecef or geodetic");
                    break;
                }
            }
            const bool geodetic = engine.waypoint_frame == model::LocationFrame::geodetic;
            engine.waypoints = detail::read_table(
                *data, 3, geodetic ? "t, latitude, longitude, altitude" : "t, x, y, z", context,
                diagnostics);
            if (geodetic) {
                std::size_t row = 0;
                for (const model::MotionTableRow& r : engine.waypoints) {
                    ++row;
                    if (std::abs(r.values[0]) > 90.0) {
                        diagnostics.error(ErrorContext{data->file(), r.line, data->path()},
                                          "row " + std::to_string(row) + " latitude " +
                                              detail::number_text(r.values[0]) +
                                              " is out of range, expected [-90, 90] degrees");
                    }
                }
            }
            break;
        }
        case 1: {
            engine.type = model::LocationEngineType::straight;
            node.warn_unknown_children({"heading", "velocity", "start"}, diagnostics);
            const double factor =
                detail::angle_unit_factor(node, "angularunits", deg_to_rad(1.0), diagnostics);
            engine.heading_rad =
                node.optional_double("heading", diagnostics).value_or(0.0) * factor;
            engine.speed_m_s =
                node.required_double("velocity", diagnostics, io::NumberRule::non_negative())
                    .value_or(0.0);
            if (const std::optional<io::XmlNode> start =
                    required_child(node, "start", "the position at t = 0", diagnostics)) {
                if (auto location = detail::read_location(*start, 1.0, diagnostics)) {
                    engine.location = *location;
                }
            }
            break;
        }
        case 2: {
            engine.type = model::LocationEngineType::fixed;
            node.warn_unknown_children({"location", "point"}, diagnostics);
            std::optional<io::XmlNode> where = node.child("location");
            if (!where) where = node.child("point");
            if (node.child("location") && node.child("point")) {
                diagnostics.error(node.child("point")->where(),
                                  "both <location> and <point> given, expected one location");
            }
            if (!where) {
                diagnostics.error(node.where(), "missing required element <location>");
            } else if (auto location = detail::read_location(*where, 1.0, diagnostics)) {
                engine.location = *location;
            }
            break;
        }
        case 3: {
            engine.type = model::LocationEngineType::sgp4;
            node.warn_unknown_children({"data"}, diagnostics);
            const std::optional<io::XmlNode> data =
                required_child(node, "data", "the two-line element set", diagnostics);
            if (!data) break;
            if (const std::optional<std::string> raw = data->attribute("source")) {
                if (lower_trimmed(*raw) != "internal") {
                    diagnostics.error(data->where_attribute("source"),
                                      "data source \"" + *raw +
                                          "\" is not supported yet, expected internal (<tle1> "
                                          "and <tle2> in <data>)");
                    break;
                }
            }
            data->warn_unknown_children({"tle1", "tle2"}, diagnostics);
            const std::optional<io::XmlNode> tle1 = required_child(*data, "tle1", "", diagnostics);
            const std::optional<io::XmlNode> tle2 = required_child(*data, "tle2", "", diagnostics);
            if (tle1) {
                engine.tle1 = tle1->text();
                engine.tle_where = tle1->where();
            }
            if (tle2) engine.tle2 = tle2->text();
            for (const auto& line : {tle1, tle2}) {
                if (line && line->text().empty()) {
                    diagnostics.error(line->where(),
                                      "<" + line->name() + "> is empty, expected a TLE line");
                }
            }
            break;
        }
        default:
            break;
    }
    return engine;
}

/// The target of a lookat engine: `<point>`/`<location>` (a fixed engine) or a nested
/// `<locationengine>`.
std::optional<model::LocationEngine> read_lookat_target(const io::XmlNode& node,
                                                        const MotionReadContext& context,
                                                        Diagnostics& diagnostics) {
    std::vector<io::XmlNode> given;
    for (const std::string_view name : {"point", "location", "locationengine"}) {
        for (const io::XmlNode& child : node.children(name)) given.push_back(child);
    }
    if (given.empty()) {
        diagnostics.error(node.where(),
                          "missing required element <point> (the look-at target: <point>, "
                          "<location> or a nested <locationengine>)");
        return std::nullopt;
    }
    if (given.size() > 1) {
        diagnostics.error(given[1].where(), "<" + given[1].name() + "> given after <" +
                                                given[0].name() + ">, expected one look-at target");
    }
    const io::XmlNode& target = given[0];
    if (target.name() == "locationengine") {
        return read_location_engine(target, context, diagnostics);
    }
    model::LocationEngine engine;
    engine.type = model::LocationEngineType::fixed;
    engine.where = target.where();
    std::optional<model::Location> location = detail::read_location(target, 1.0, diagnostics);
    if (!location) return std::nullopt;
    engine.location = *location;
    return engine;
}

model::OrientationEngine read_orientation_engine(const io::XmlNode& node,
                                                 const MotionReadContext& context,
                                                 Diagnostics& diagnostics) {
    model::OrientationEngine engine;
    engine.where = node.where();
    const std::optional<std::size_t> type =
        engine_type(node, {"velocity", "lookat", "euler", "quaternions", "spin"}, diagnostics);
    if (!type) return engine;
    switch (*type) {
        case 0:
            engine.type = model::OrientationEngineType::velocity;
            node.warn_unknown_children({"constraint"}, diagnostics);
            if (const std::optional<io::XmlNode> constraint = node.child("constraint")) {
                engine.up = detail::read_direction_hint(*constraint, false, diagnostics);
            }
            break;
        case 1:
            engine.type = model::OrientationEngineType::lookat;
            node.warn_unknown_children({"point", "location", "locationengine", "up"}, diagnostics);
            engine.target = read_lookat_target(node, context, diagnostics);
            if (const std::optional<io::XmlNode> up = node.child("up")) {
                engine.up = detail::read_direction_hint(*up, true, diagnostics);
            }
            break;
        case 2: {
            engine.type = model::OrientationEngineType::euler;
            node.warn_unknown_children({"data"}, diagnostics);
            const std::optional<io::XmlNode> data =
                required_child(node, "data", "the Euler angle table", diagnostics);
            if (!data) break;
            engine.rotation_order = detail::read_rotation_order(*data, diagnostics);
            const double factor = detail::angular_unit_factor(*data, diagnostics);
            engine.table = detail::read_table(*data, 3, "t, x, y, z", context, diagnostics);
            for (model::MotionTableRow& row : engine.table) {
                for (std::size_t i = 0; i < 3; ++i) row.values[i] *= factor;
            }
            break;
        }
        case 3: {
            engine.type = model::OrientationEngineType::quaternions;
            node.warn_unknown_children({"data"}, diagnostics);
            const std::optional<io::XmlNode> data =
                required_child(node, "data", "the quaternion table", diagnostics);
            if (!data) break;
            bool scalar_last = false;
            if (const std::optional<std::string> raw = data->attribute("scalar")) {
                const std::string scalar = lower_trimmed(*raw);
                if (scalar == "last") {
                    scalar_last = true;
                } else if (scalar != "first") {
                    diagnostics.error(data->where_attribute("scalar"),
                                      "unknown scalar position \"" + *raw +
                                          "\", expected first (t, w, x, y, z) or last (t, x, y, "
                                          "z, w)");
                }
            }
            engine.table = detail::read_table(
                *data, 4, scalar_last ? "t, x, y, z, w" : "t, w, x, y, z", context, diagnostics);
            std::size_t row = 0;
            for (model::MotionTableRow& r : engine.table) {
                ++row;
                if (scalar_last)
                    std::rotate(r.values.rbegin(), r.values.rbegin() + 1, r.values.rend());
                if (r.values == std::array<double, 4>{0.0, 0.0, 0.0, 0.0}) {
                    diagnostics.error(
                        ErrorContext{data->file(), r.line, data->path()},
                        "row " + std::to_string(row) + " quaternion is zero, expected a rotation");
                }
            }
            break;
        }
        case 4: {
            engine.type = model::OrientationEngineType::spin;
            node.warn_unknown_children({"axis", "rate", "phase"}, diagnostics);
            const double factor =
                detail::angle_unit_factor(node, "angularunits", deg_to_rad(1.0), diagnostics);
            if (const std::optional<io::XmlNode> axis = node.child("axis")) {
                const std::optional<std::vector<double>> list =
                    detail::parse_number_list(axis->text());
                if (!list || list->size() != 3) {
                    diagnostics.error(
                        axis->where(),
                        "\"" + axis->text() + "\" is not a vector, expected \"x, y, z\"");
                } else if ((*list)[0] == 0.0 && (*list)[1] == 0.0 && (*list)[2] == 0.0) {
                    diagnostics.error(axis->where(), "the spin axis is zero, expected a direction");
                } else {
                    engine.spin_axis = {(*list)[0], (*list)[1], (*list)[2]};
                }
            }
            engine.spin_rate_rad_s =
                node.required_double("rate", diagnostics).value_or(0.0) * factor;
            engine.spin_phase_rad =
                node.optional_double("phase", diagnostics).value_or(0.0) * factor;
            break;
        }
        default:
            break;
    }
    return engine;
}

}  // namespace

model::FlexMotion read_flex_motion(const io::XmlNode& motion, const MotionReadContext& context,
                                   Diagnostics& diagnostics) {
    model::FlexMotion flex;
    flex.where = motion.where();
    motion.warn_unknown_children(
        {"locationengine", "orientationengine", "locationjitter", "orientationjitter"},
        diagnostics);
    for (const std::string_view name : {"locationengine", "orientationengine"}) {
        const std::vector<io::XmlNode> given = motion.children(name);
        if (given.empty()) {
            diagnostics.error(motion.where(),
                              "missing required element <" + std::string(name) + ">");
            continue;
        }
        for (std::size_t k = 1; k < given.size(); ++k) {
            diagnostics.error(given[k].where(),
                              "<" + std::string(name) + "> given again (first at line " +
                                  std::to_string(given[0].line()) + "), expected exactly one");
        }
        if (name == "locationengine") {
            flex.location = read_location_engine(given[0], context, diagnostics);
        } else {
            flex.orientation = read_orientation_engine(given[0], context, diagnostics);
        }
    }
    flex.jitter = detail::read_platform_jitter(motion, context, diagnostics);
    return flex;
}

}  // namespace glint::dirsig
