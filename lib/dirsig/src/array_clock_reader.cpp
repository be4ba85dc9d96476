// SPDX-License-Identifier: Apache-2.0
// Detector arrays and clocks of a `.platform`: element counts (checked against the memory
// limits before anything downstream allocates), element sizes and pitches converted to m,
// the rolling readout, the focal plane's clock (independent, synchronous to a clock-table
// master, or external triggers from a file) and the clock table's master clocks.
#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include "platform_tree.h"

namespace glint::dirsig::detail {

namespace {

struct SpatialUnit {
    std::string_view text;
    double metres;
};

constexpr std::array<SpatialUnit, 9> kSpatialUnits = {{
    {"microns", 1e-6},
    {"micron", 1e-6},
    {"micrometers", 1e-6},
    {"um", 1e-6},
    {"millimeters", 1e-3},
    {"mm", 1e-3},
    {"meters", 1.0},
    {"metres", 1.0},
    {"m", 1.0},
}};

/// Largest element count along one axis, and of the whole array.
constexpr std::int64_t kMaxAxisCount = 1000000;
constexpr std::int64_t kMaxElementCount = std::int64_t{1} << 31;
/// Largest synchronous divider and offset count.
constexpr std::int64_t kMaxTickCount = 1000000000;

/// A count of at least 1 (the upper limit is checked with the other axis).
std::optional<std::int64_t> read_count(const io::XmlNode& node, std::string_view name,
                                       Diagnostics& diagnostics) {
    std::optional<std::int64_t> count =
        node.required_int(name, diagnostics, std::numeric_limits<std::int64_t>::min(),
                          std::numeric_limits<std::int64_t>::max());
    if (count && *count < 1) {
        diagnostics.error(node.child(name)->where(),
                          std::string(name) + " " + std::to_string(*count) +
                              " is out of range, expected an integer in [1, " +
                              std::to_string(kMaxAxisCount) + "]");
        return std::nullopt;
    }
    return count;
}

/// @temporalunits: hertz (the default; also hz).
void check_temporal_units(const io::XmlNode& node, std::string& units, Diagnostics& diagnostics) {
    const std::optional<std::string> raw = node.attribute("temporalunits");
    if (!raw) return;
    units = *raw;
    const std::string value = lower_trimmed(*raw);
    if (value != "hertz" && value != "hz") {
        diagnostics.error(node.where_attribute("temporalunits"),
                          "unknown temporalunits \"" + *raw + "\", expected hertz");
    }
}

/// A name given as an attribute or a child element (both is an error), trimmed; nullopt
/// when absent or blank.
std::optional<std::string> attribute_or_child(const io::XmlNode& node, std::string_view name,
                                              Diagnostics& diagnostics) {
    const std::optional<std::string> attribute = node.attribute(name);
    const std::optional<io::XmlNode> child = node.child(name);
    if (attribute && child) {
        diagnostics.error(child->where(), "both @" + std::string(name) + " and <" +
                                              std::string(name) +
                                              "> given, expected only one of the two");
    }
    std::string text = trimmed(attribute ? *attribute : child ? child->text() : std::string());
    if (text.empty()) return std::nullopt;
    return text;
}

}  // namespace

model::Clock read_clock(const io::XmlNode& node, const ReadContext& context,
                        Diagnostics& diagnostics) {
    model::Clock clock;
    clock.where = node.where();
    const std::optional<std::string> raw = node.attribute("type");
    if (!raw) {
        diagnostics.error(node.where(),
                          "missing required attribute type, expected independent, synchronous "
                          "or external");
        return clock;
    }
    const std::string type = lower_trimmed(*raw);
    if (type == "independent") {
        clock.type = model::ClockType::independent;
        check_temporal_units(node, clock.temporal_units, diagnostics);
        clock.rate_hz =
            node.required_double("rate", diagnostics, io::NumberRule::positive()).value_or(0.0);
        clock.offset_s = node.optional_double("offset", diagnostics).value_or(0.0);
        node.warn_unknown_children({"rate", "offset"}, diagnostics);
    } else if (type == "synchronous") {
        clock.type = model::ClockType::synchronous;
        if (auto master = attribute_or_child(node, "master", diagnostics)) {
            clock.master = *master;
        } else {
            diagnostics.error(node.where(),
                              "synchronous clock has no master, expected @master or <master> "
                              "naming a <clocktable> clock");
        }
        clock.divider = node.optional_int("divider", diagnostics, 1, kMaxTickCount).value_or(1);
        clock.offset_count = node.optional_int("offset", diagnostics, 0, kMaxTickCount).value_or(0);
        node.warn_unknown_children({"master", "divider", "offset"}, diagnostics);
    } else if (type == "external" || type == "externaltrigger" || type == "trigger" ||
               type == "irregular") {
        clock.type = model::ClockType::external_trigger;
        const std::optional<io::XmlNode> filename = node.child("filename");
        const std::optional<io::XmlNode> trigger = node.child("triggerfile");
        const std::optional<std::string> attribute = node.attribute("filename");
        const int given = (filename ? 1 : 0) + (trigger ? 1 : 0) + (attribute ? 1 : 0);
        if (given > 1) {
            diagnostics.error(node.where(),
                              "trigger file given more than once, expected one of @filename, "
                              "<filename> or <triggerfile>");
        }
        std::string text;
        ErrorContext where = node.where_attribute("filename");
        if (filename || trigger) {
            const io::XmlNode& element = filename ? *filename : *trigger;
            text = element.text();
            where = element.where();
        } else if (attribute) {
            text = *attribute;
        }
        if (text.empty()) {
            diagnostics.error(node.where(),
                              "external clock has no trigger file, expected <filename> (a text "
                              "file of trigger times in seconds)");
        } else {
            clock.trigger_file =
                context.options.paths.resolve(text, context.base_dir, where, diagnostics);
        }
        node.warn_unknown_children({"filename", "triggerfile"}, diagnostics);
    } else {
        diagnostics.error(node.where_attribute("type"),
                          "unknown clock type \"" + *raw +
                              "\", expected independent, synchronous or external (also "
                              "externaltrigger, trigger, irregular)");
    }
    return clock;
}

model::MasterClock read_master_clock(const io::XmlNode& node, Diagnostics& diagnostics) {
    model::MasterClock clock;
    clock.where = node.where();
    clock.name = trimmed(node.attribute("name").value_or(""));
    if (clock.name.empty()) {
        diagnostics.error(node.where(),
                          "clocktable clock has no name, expected @name (synchronous clocks "
                          "refer to it)");
    }
    if (const std::optional<std::string> type = node.attribute("type")) {
        if (lower_trimmed(*type) != "independent") {
            diagnostics.error(
                node.where_attribute("type"),
                "clocktable clock type \"" + *type + "\" is not supported, expected independent");
        }
    }
    std::string units;
    check_temporal_units(node, units, diagnostics);
    clock.rate_hz =
        node.required_double("rate", diagnostics, io::NumberRule::positive()).value_or(0.0);
    clock.offset_s = node.optional_double("offset", diagnostics).value_or(0.0);
    node.warn_unknown_children({"rate", "offset"}, diagnostics);
    return clock;
}

/// The largest raw oversampling factor per axis.
constexpr std::int64_t kMaxOversample = 64;

model::DetectorArray read_detector_array(const io::XmlNode& node, const ReadContext& context,
                                         Diagnostics& diagnostics) {
    model::DetectorArray array;
    array.where = node.where();
    double unit_m = 1e-6;
    if (const std::optional<std::string> raw = node.attribute("spatialunits")) {
        array.spatial_units = *raw;
        const std::string units = lower_trimmed(*raw);
        const auto found =
            std::find_if(kSpatialUnits.begin(), kSpatialUnits.end(),
                         [&](const SpatialUnit& unit) { return unit.text == units; });
        if (found == kSpatialUnits.end()) {
            diagnostics.error(node.where_attribute("spatialunits"),
                              "unknown spatialunits \"" + *raw +
                                  "\", expected microns, millimeters or meters (or um, mm, m)");
        } else {
            unit_m = found->metres;
        }
    }

    // Counts: refused before anything is sized from them.
    const std::optional<std::int64_t> x_count = read_count(node, "xelementcount", diagnostics);
    const std::optional<std::int64_t> y_count = read_count(node, "yelementcount", diagnostics);
    const bool x_huge = x_count && *x_count > kMaxAxisCount;
    const bool y_huge = y_count && *y_count > kMaxAxisCount;
    const bool product_huge =
        x_count && y_count && !x_huge && !y_huge && *x_count * *y_count > kMaxElementCount;
    if (x_huge || y_huge || product_huge) {
        const auto text = [](const std::optional<std::int64_t>& count) {
            return count ? std::to_string(*count) : std::string("?");
        };
        const ErrorContext where = x_huge   ? node.child("xelementcount")->where()
                                   : y_huge ? node.child("yelementcount")->where()
                                            : node.where();
        diagnostics.error(where, "xelementcount x yelementcount = " + text(x_count) + " x " +
                                     text(y_count) +
                                     ": a detector array so large it would exhaust memory "
                                     "(refused before allocation), expected each count in [1, " +
                                     std::to_string(kMaxAxisCount) + "] and at most " +
                                     std::to_string(kMaxElementCount) + " elements");
    } else {
        if (x_count) array.x_count = static_cast<std::size_t>(*x_count);
        if (y_count) array.y_count = static_cast<std::size_t>(*y_count);
    }

    // Element sizes and pitches.
    const auto read_axis = [&](char axis, double& size_m, double& spacing_m) {
        const std::string size_name = std::string(1, axis) + "elementsize";
        const std::string spacing_name = std::string(1, axis) + "elementspacing";
        const std::optional<double> spacing =
            node.required_double(spacing_name, diagnostics, io::NumberRule::positive());
        const std::optional<double> size =
            node.optional_double(size_name, diagnostics, io::NumberRule::positive());
        if (size && spacing && *spacing < *size) {
            diagnostics.error(node.child(spacing_name)->where(),
                              spacing_name + " " + number_text(*spacing) + " is smaller than " +
                                  size_name + " " + number_text(*size) +
                                  ", expected a spacing >= the element size (elements cannot "
                                  "overlap)");
        }
        if (spacing) spacing_m = *spacing * unit_m;
        if (size) {
            size_m = *size * unit_m;
        } else if (spacing) {
            size_m = *spacing * unit_m;
        }
    };
    read_axis('x', array.x_size_m, array.x_spacing_m);
    read_axis('y', array.y_size_m, array.y_spacing_m);
    array.x_offset_m = node.optional_double("xarrayoffset", diagnostics).value_or(0.0) * unit_m;
    array.y_offset_m = node.optional_double("yarrayoffset", diagnostics).value_or(0.0) * unit_m;
    array.x_flip = node.optional_bool("xflipaxis", diagnostics).value_or(false);
    array.y_flip = node.optional_bool("yflipaxis", diagnostics).value_or(false);

    if (const std::optional<io::XmlNode> clock = node.child("clock")) {
        array.clock = read_clock(*clock, context, diagnostics);
    } else {
        diagnostics.error(node.where(), "missing required element <clock>");
        array.clock.where = node.where();
    }

    // Rolling readout (glint's definition, docs/formats.md).
    const bool rolling = node.attribute_bool("rollingreadout", diagnostics).value_or(false);
    const std::optional<io::XmlNode> line_time = node.child("linetime");
    if (rolling) {
        if (!line_time) {
            diagnostics.error(node.where_attribute("rollingreadout"),
                              "rollingreadout=\"true\" needs <linetime> (seconds between the "
                              "readout of consecutive rows)");
        } else {
            array.rolling_line_time_s =
                node.optional_double("linetime", diagnostics, io::NumberRule::positive());
        }
    } else if (line_time) {
        diagnostics.warning(line_time->where(),
                            "<linetime> ignored: rollingreadout is not \"true\"");
    }

    // Raw-capture spatial oversampling (docs/units.md, "Raw capture"): whole factors.
    for (const auto& [name, factor] : {std::pair{"xoversample", &array.x_oversample},
                                       std::pair{"yoversample", &array.y_oversample}}) {
        const auto element = node.child(name);
        if (!element) continue;
        if (array.oversample_where.file.empty()) array.oversample_where = element->where();
        if (const auto k = node.optional_int(name, diagnostics, 1, kMaxOversample)) {
            *factor = static_cast<std::size_t>(*k);
        }
    }
    for (const io::XmlNode& child : node.children()) {
        static constexpr std::array<std::string_view, 7> kNotUsed = {
            "xsubsamples",      "ysubsamples",  "fieldcount", "clockrate",
            "selectorfilename", "selectorlist", "filename"};
        if (std::find(kNotUsed.begin(), kNotUsed.end(), child.name()) != kNotUsed.end()) {
            warn_not_used(child, diagnostics);
        }
    }
    node.warn_unknown_children(
        {"clock",           "xelementcount",   "yelementcount", "xelementsize",     "yelementsize",
         "xelementspacing", "yelementspacing", "xarrayoffset",  "yarrayoffset",     "xflipaxis",
         "yflipaxis",       "linetime",        "xoversample",   "yoversample",      "xsubsamples",
         "ysubsamples",     "fieldcount",      "clockrate",     "selectorfilename", "selectorlist",
         "filename"},
        diagnostics);
    return array;
}

}  // namespace glint::dirsig::detail
