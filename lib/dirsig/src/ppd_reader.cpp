// SPDX-License-Identifier: Apache-2.0
// Reader of GenericMotion `.ppd` files (`<platformmotion type="generic">`): the `<data>`
// attributes (rotation frame, order, angle type, units), the timed entries of position
// (scene, ECEF or geodetic) and Euler orientation, and the platform jitter elements.
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "motion_parts.h"
#include "platform_tree.h"

namespace glint::dirsig {

namespace {

using detail::lower_trimmed;

/// The time of an `<entry>` (seconds after the reference), or nullopt after an error.
std::optional<double> read_entry_time(const io::XmlNode& entry, Diagnostics& diagnostics) {
    const std::optional<io::XmlNode> datetime = entry.child("datetime");
    if (!datetime) {
        diagnostics.error(entry.where(), "missing required element <datetime>");
        return std::nullopt;
    }
    datetime->warn_unknown_children({}, diagnostics);
    if (const std::optional<std::string> raw = datetime->attribute("type")) {
        const std::string type = lower_trimmed(*raw);
        if (type == "absolute") {
            diagnostics.error(datetime->where_attribute("type"),
                              "absolute motion times need the tasks file's reference date and are "
                              "not supported yet, expected type=\"relative\" (seconds after the "
                              "reference time)");
            return std::nullopt;
        }
        if (type != "relative") {
            diagnostics.error(datetime->where_attribute("type"),
                              "unknown datetime type \"" + *raw + "\", expected relative");
            return std::nullopt;
        }
    }
    return datetime->own_double(diagnostics);
}

/// `<position><location type=…>` of an entry.
std::optional<model::Location> read_entry_position(const io::XmlNode& entry, double length_factor,
                                                   Diagnostics& diagnostics) {
    const std::optional<io::XmlNode> position = entry.child("position");
    if (!position) {
        diagnostics.error(entry.where(), "missing required element <position>");
        return std::nullopt;
    }
    position->warn_unknown_children({"location"}, diagnostics);
    const std::optional<io::XmlNode> location = position->child("location");
    if (!location) {
        diagnostics.error(position->where(), "missing required element <location>");
        return std::nullopt;
    }
    return detail::read_location(*location, length_factor, diagnostics);
}

/// `<orientation><eulerangles><cartesiantriple>` of an entry, in radians.
std::optional<std::array<double, 3>> read_entry_orientation(const io::XmlNode& entry,
                                                            double angle_factor,
                                                            Diagnostics& diagnostics) {
    const std::optional<io::XmlNode> orientation = entry.child("orientation");
    if (!orientation) {
        diagnostics.error(entry.where(), "missing required element <orientation>");
        return std::nullopt;
    }
    orientation->warn_unknown_children({"eulerangles"}, diagnostics);
    const std::optional<io::XmlNode> euler = orientation->child("eulerangles");
    if (!euler) {
        diagnostics.error(orientation->where(), "missing required element <eulerangles>");
        return std::nullopt;
    }
    euler->warn_unknown_children({"cartesiantriple"}, diagnostics);
    const std::optional<io::XmlNode> triple = euler->child("cartesiantriple");
    if (!triple) {
        diagnostics.error(euler->where(), "missing required element <cartesiantriple>");
        return std::nullopt;
    }
    triple->warn_unknown_children({"x", "y", "z"}, diagnostics);
    const std::optional<double> x = triple->required_double("x", diagnostics);
    const std::optional<double> y = triple->required_double("y", diagnostics);
    const std::optional<double> z = triple->required_double("z", diagnostics);
    if (!x || !y || !z) return std::nullopt;
    return std::array<double, 3>{*x * angle_factor, *y * angle_factor, *z * angle_factor};
}

/// The attributes of `<data>` into `motion`; returns the (length, angle) unit factors.
std::pair<double, double> read_data_attributes(const io::XmlNode& data,
                                               model::GenericMotion& motion,
                                               Diagnostics& diagnostics) {
    if (const std::optional<std::string> raw = data.attribute("rotationframe")) {
        const std::string frame = lower_trimmed(*raw);
        if (frame == "sceneenu" || frame == "scene") {
            motion.rotation_frame = model::RotationFrame::scene_enu;
        } else if (frame == "ecef") {
            motion.rotation_frame = model::RotationFrame::ecef;
        } else {
            diagnostics.error(
                data.where_attribute("rotationframe"),
                "rotationframe \"" + *raw + "\" is not supported, expected sceneenu or ecef");
        }
    }
    motion.rotation_order = detail::read_rotation_order(data, diagnostics);
    if (const std::optional<std::string> raw = data.attribute("angletype")) {
        const std::string type = lower_trimmed(*raw);
        if (type == "delta") {
            diagnostics.error(data.where_attribute("angletype"),
                              "angletype \"delta\" is not supported yet, expected absolute");
        } else if (type != "absolute") {
            diagnostics.error(data.where_attribute("angletype"),
                              "unknown angletype \"" + *raw + "\", expected absolute");
        }
    }
    const double angle = detail::angular_unit_factor(data, diagnostics);
    const double length = detail::length_unit_factor(data, "spatialunits", 1.0, diagnostics);
    return {length, angle};
}

}  // namespace

model::GenericMotion read_generic_motion(const io::XmlNode& platform_motion,
                                         const MotionReadContext& context,
                                         Diagnostics& diagnostics) {
    model::GenericMotion motion;
    motion.where = platform_motion.where();
    platform_motion.warn_unknown_children({"method", "locationjitter", "orientationjitter", "data"},
                                          diagnostics);
    if (const std::optional<io::XmlNode> method = platform_motion.child("method")) {
        method->warn_unknown_children({}, diagnostics);
        if (const std::optional<std::string> raw = method->attribute("type")) {
            if (lower_trimmed(*raw) != "raw") {
                diagnostics.error(method->where_attribute("type"),
                                  "unknown method type \"" + *raw + "\", expected raw");
            }
        }
    }
    motion.jitter = detail::read_platform_jitter(platform_motion, context, diagnostics);

    const std::optional<io::XmlNode> data = platform_motion.child("data");
    if (!data) {
        diagnostics.error(platform_motion.where(), "missing required element <data>");
        return motion;
    }
    const auto [length_factor, angle_factor] = read_data_attributes(*data, motion, diagnostics);
    data->warn_unknown_children({"entry"}, diagnostics);

    std::optional<double> previous;
    std::size_t index = 0;
    for (const io::XmlNode& node : data->children("entry")) {
        ++index;
        node.warn_unknown_children({"datetime", "position", "orientation"}, diagnostics);
        model::GenericMotionEntry entry;
        entry.where = node.where();
        const std::optional<double> time = read_entry_time(node, diagnostics);
        const std::optional<model::Location> location =
            read_entry_position(node, length_factor, diagnostics);
        const std::optional<std::array<double, 3>> euler =
            read_entry_orientation(node, angle_factor, diagnostics);
        if (time && previous) {
            if (auto problem = detail::time_order_problem("entry", index, *previous, *time)) {
                diagnostics.error(entry.where, *problem);
            }
        }
        if (time) previous = time;
        if (!time || !location || !euler) continue;
        entry.time_s = *time;
        entry.location = *location;
        entry.euler_rad = *euler;
        motion.entries.push_back(std::move(entry));
    }
    if (index == 0) {
        diagnostics.error(data->where(), "no <entry> in <data>, expected at least one");
    }
    return motion;
}

}  // namespace glint::dirsig
