// SPDX-License-Identifier: Apache-2.0
// Mounts of a `.platform`: static, commanded and tabulated pointing, whisk scanners,
// tracking mounts (the other DIRSIG types are accepted with a warning and held static), and
// the per-axis pointing jitter of `<rotationdeviates>`. The XML glint defines for whisk,
// tracking and rotationdeviates is documented in docs/formats.md.
#include <algorithm>
#include <array>
#include <cctype>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "glint/core/text.h"
#include "jitter_reader.h"
#include "platform_tree.h"

namespace glint::dirsig::detail {

namespace {

constexpr std::array<std::string_view, 3> kRotations = {"xrotation", "yrotation", "zrotation"};
constexpr std::array<std::string_view, 3> kTranslations = {"xtranslation", "ytranslation",
                                                           "ztranslation"};

struct MountTypeName {
    std::string_view text;
    model::MountType type;
};

constexpr std::array<MountTypeName, 8> kMountTypes = {{
    {"static", model::MountType::static_mount},
    {"commanded", model::MountType::commanded},
    {"tabulated", model::MountType::tabulated},
    {"whisk", model::MountType::whisk},
    {"tracking", model::MountType::tracking},
    {"lemniscate", model::MountType::other},
    {"line", model::MountType::other},
    {"scripted", model::MountType::other},
}};

/// The `<entry>` table of a commanded or tabulated mount: times strictly increasing.
std::vector<model::MountEntry> read_entries(const io::XmlNode& data, std::string_view mount_type,
                                            double factor, Diagnostics& diagnostics) {
    std::vector<model::MountEntry> entries;
    std::optional<double> previous;
    for (const io::XmlNode& node : data.children("entry")) {
        model::MountEntry entry;
        entry.where = node.where();
        std::optional<double> time;
        if (const std::optional<io::XmlNode> datetime = node.child("datetime")) {
            const std::string type =
                lower_trimmed(datetime->attribute("type").value_or("relative"));
            if (type == "absolute") {
                diagnostics.error(datetime->where(),
                                  "absolute mount times need the tasks file's reference date and "
                                  "are not supported yet, expected type=\"relative\" (seconds "
                                  "after the reference time)");
            } else if (type != "relative") {
                diagnostics.error(datetime->where_attribute("type"),
                                  "unknown datetime type \"" + *datetime->attribute("type") +
                                      "\", expected relative or absolute");
            } else {
                time = datetime->own_double(diagnostics);
            }
        } else {
            diagnostics.error(node.where(), "missing required element <datetime>");
        }
        entry.rotation_rad = read_triplet(node, kRotations, factor, diagnostics);
        entry.translation_m = read_triplet(node, kTranslations, 1.0, diagnostics);
        node.warn_unknown_children({"datetime", "xrotation", "yrotation", "zrotation",
                                    "xtranslation", "ytranslation", "ztranslation"},
                                   diagnostics);
        if (time) {
            entry.time_s = *time;
            if (previous && *time <= *previous) {
                diagnostics.error(entry.where, "entry time " + number_text(*time) +
                                                   " s is not after the previous entry's " +
                                                   number_text(*previous) +
                                                   " s, expected strictly increasing times");
            }
            previous = time;
        }
        entries.push_back(std::move(entry));
    }
    if (entries.empty()) {
        diagnostics.error(data.where(),
                          std::string(mount_type) + " mount has no <entry>, expected at least one");
    }
    return entries;
}

/// Repeat period of a tabulated mount: @period or <period> on <data>, else the last time.
std::optional<double> read_period(const io::XmlNode& data,
                                  const std::vector<model::MountEntry>& entries,
                                  Diagnostics& diagnostics) {
    std::optional<double> period;
    const bool has_attribute = data.attribute("period").has_value();
    const std::optional<io::XmlNode> child = data.child("period");
    if (has_attribute && child) {
        diagnostics.error(child->where(),
                          "both @period and <period> given, expected only one of the two");
    }
    if (has_attribute) {
        period = data.attribute_double("period", diagnostics, io::NumberRule::positive());
    } else if (child) {
        period = data.optional_double("period", diagnostics, io::NumberRule::positive());
    }
    const double last = entries.empty() ? 0.0 : entries.back().time_s;
    if (period) {
        if (*period < last) {
            diagnostics.error(child ? child->where() : data.where_attribute("period"),
                              "period " + number_text(*period) +
                                  " s is shorter than the last entry time " + number_text(last) +
                                  " s, expected a period >= the last time");
        }
        return period;
    }
    if (last > 0.0) return last;
    return std::nullopt;
}

/// `<data>` of a whisk mount (see docs/formats.md).
model::WhiskScan read_whisk(const io::XmlNode& data, Diagnostics& diagnostics) {
    model::WhiskScan scan;
    const double factor = angular_unit_factor(data, diagnostics);
    const std::optional<io::XmlNode> along = data.child("alongtrack");
    const std::optional<io::XmlNode> across = data.child("acrosstrack");
    const std::optional<std::string> axis =
        data.optional_enum("axis", {"acrosstrack", "alongtrack"}, diagnostics);
    if (axis) {
        scan.axis = *axis == "alongtrack" ? model::WhiskScan::Axis::along_track
                                          : model::WhiskScan::Axis::across_track;
    }
    io::XmlNode source = data;
    if (along && across) {
        diagnostics.error(across->where(),
                          "both <alongtrack> and <acrosstrack> given, expected one scan axis");
    }
    if (along || across) {
        source = along ? *along : *across;
        const auto element_axis =
            along ? model::WhiskScan::Axis::along_track : model::WhiskScan::Axis::across_track;
        if (axis && element_axis != scan.axis) {
            diagnostics.error(source.where(), "<" + source.name() + "> contradicts <axis>" + *axis +
                                                  "</axis>, expected one scan axis");
        }
        scan.axis = element_axis;
    }
    // Each value may sit in the axis element or directly in <data>.
    const auto holder = [&](std::string_view name) -> const io::XmlNode& {
        return source.child(name) ? source : data;
    };
    const std::optional<double> min =
        holder("minimumangle").required_double("minimumangle", diagnostics);
    const std::optional<double> max =
        holder("maximumangle").required_double("maximumangle", diagnostics);
    if (min) scan.min_angle_rad = *min * factor;
    if (max) scan.max_angle_rad = *max * factor;
    if (min && max && *min > *max) {
        diagnostics.error(holder("maximumangle").child("maximumangle")->where(),
                          "maximumangle " + number_text(*max) + " is less than minimumangle " +
                              number_text(*min) + ", expected minimumangle <= maximumangle");
    }
    scan.rate_hz = holder("rate")
                       .required_double("rate", diagnostics, io::NumberRule::positive())
                       .value_or(0.0);
    scan.phase_rad = holder("phase").optional_double("phase", diagnostics).value_or(0.0) * factor;
    if (const auto profile =
            holder("profile").optional_enum("profile", {"sinusoidal", "linear"}, diagnostics)) {
        scan.sinusoidal = *profile == "sinusoidal";
    }
    data.warn_unknown_children({"axis", "alongtrack", "acrosstrack", "minimumangle", "maximumangle",
                                "rate", "phase", "profile"},
                               diagnostics);
    if (source.path() != data.path() || source.line() != data.line()) {
        source.warn_unknown_children({"minimumangle", "maximumangle", "rate", "phase", "profile"},
                                     diagnostics);
    }
    return scan;
}

/// A point: <x>, <y>, <z> children, or three numbers in the text (blank or comma separated).
std::optional<std::array<double, 3>> read_point(const io::XmlNode& node, Diagnostics& diagnostics) {
    if (node.child("x") || node.child("y") || node.child("z")) {
        node.warn_unknown_children({"x", "y", "z"}, diagnostics);
        return read_triplet(node, {"x", "y", "z"}, 1.0, diagnostics);
    }
    std::string text = node.text();
    std::replace(text.begin(), text.end(), ',', ' ');
    std::vector<double> values;
    std::size_t pos = 0;
    bool ok = true;
    while (pos < text.size()) {
        while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos]))) ++pos;
        std::size_t end = pos;
        while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end]))) ++end;
        if (end == pos) break;
        const std::optional<double> value = parse_double(text.substr(pos, end - pos));
        ok = ok && value.has_value();
        if (value) values.push_back(*value);
        pos = end;
    }
    if (!ok || values.size() != 3) {
        diagnostics.error(node.where(), "\"" + node.text() +
                                            "\" is not a point, expected x y z (three numbers, "
                                            "or <x>, <y>, <z> children) in m");
        return std::nullopt;
    }
    return std::array<double, 3>{values[0], values[1], values[2]};
}

/// Target of a tracking mount, read from <data> or from the mount itself.
model::TrackingTarget read_tracking(const io::XmlNode& source, Diagnostics& diagnostics) {
    model::TrackingTarget target;
    const std::optional<std::string> name = source.optional_text("targetname");
    if (name) target.name = *name;
    if (const std::optional<io::XmlNode> offset = source.child("targetoffset")) {
        const std::optional<io::XmlNode> point = offset->child("point");
        if (point) offset->warn_unknown_children({"point"}, diagnostics);
        if (auto value = read_point(point ? *point : *offset, diagnostics))
            target.offset_m = *value;
    }
    if (const std::optional<io::XmlNode> point = source.child("point")) {
        target.point_m = read_point(*point, diagnostics);
        if (name) {
            diagnostics.error(point->where(),
                              "both <targetname> and <point> given, expected one target");
        }
    } else if (!name || name->empty()) {
        diagnostics.error(source.where(),
                          "tracking mount has no target, expected <targetname> or <point>");
    }
    return target;
}

}  // namespace

model::RotationDeviates read_rotation_deviates(const io::XmlNode& node, const ReadContext& context,
                                               Diagnostics& diagnostics) {
    model::RotationDeviates deviates;
    deviates.where = node.where();
    const double factor = angular_unit_factor(node, diagnostics);
    std::array<std::string, 3> given_by;
    for (const io::XmlNode& child : node.children()) {
        std::size_t index = 3;
        if (child.name() == "xrotation" || child.name() == "alongtrack") index = 0;
        if (child.name() == "yrotation" || child.name() == "acrosstrack") index = 1;
        if (child.name() == "zrotation") index = 2;
        if (index == 3) continue;
        if (!given_by[index].empty()) {
            diagnostics.error(child.where(), "<" + given_by[index] + "> and <" + child.name() +
                                                 "> both give the jitter about " +
                                                 std::string(1, "xyz"[index]) + ", expected one");
            continue;
        }
        given_by[index] = child.name();
        deviates.axes[index] = read_jitter_axis(child, JitterQuantity::angle, factor,
                                                context.options, context.base_dir, diagnostics);
    }
    node.warn_unknown_children({"xrotation", "yrotation", "zrotation", "alongtrack", "acrosstrack"},
                               diagnostics);
    return deviates;
}

model::Mount read_mount(const io::XmlNode& node, const ReadContext& context,
                        Diagnostics& diagnostics) {
    model::Mount mount;
    mount.name = node.attribute("name").value_or("");
    mount.where = node.where();
    mount.deviates.where = node.where();
    if (const std::optional<std::string> raw = node.attribute("type")) {
        mount.type_text = *raw;
        const std::string type = lower_trimmed(*raw);
        const auto found = std::find_if(kMountTypes.begin(), kMountTypes.end(),
                                        [&](const MountTypeName& t) { return t.text == type; });
        if (found == kMountTypes.end()) {
            diagnostics.error(node.where_attribute("type"),
                              "unknown mount type \"" + *raw +
                                  "\", expected static, commanded, tabulated, whisk, tracking, "
                                  "lemniscate, line or scripted");
        } else {
            mount.type = found->type;
            if (mount.type == model::MountType::other) {
                diagnostics.warning(
                    node.where_attribute("type"),
                    "mount type \"" + *raw + "\" is not supported yet; treated as static");
            }
        }
    }
    const std::optional<io::XmlNode> data = node.child("data");
    std::vector<std::string_view> known = {"data", "attachment", "rotationdeviates", "uncertainty"};
    switch (mount.type) {
        case model::MountType::static_mount:
        case model::MountType::other:
            if (data) {
                const double factor = angular_unit_factor(*data, diagnostics);
                mount.rotation_order = read_rotation_order(*data, diagnostics);
                mount.rotation_rad = read_triplet(*data, kRotations, factor, diagnostics);
                if (mount.type == model::MountType::static_mount) {
                    data->warn_unknown_children({"xrotation", "yrotation", "zrotation"},
                                                diagnostics);
                }
            }
            break;
        case model::MountType::commanded:
        case model::MountType::tabulated:
            if (!data) {
                diagnostics.error(node.where(), "missing required element <data> (a " +
                                                    mount.type_text +
                                                    " mount needs a table of <entry>)");
                break;
            }
            {
                const double factor = angular_unit_factor(*data, diagnostics);
                mount.rotation_order = read_rotation_order(*data, diagnostics);
                mount.entries = read_entries(*data, mount.type_text, factor, diagnostics);
                if (mount.type == model::MountType::tabulated) {
                    mount.period_s = read_period(*data, mount.entries, diagnostics);
                    data->warn_unknown_children({"entry", "period"}, diagnostics);
                } else {
                    data->warn_unknown_children({"entry"}, diagnostics);
                }
            }
            break;
        case model::MountType::whisk:
            if (!data) {
                diagnostics.error(node.where(),
                                  "missing required element <data> (a whisk mount needs its scan)");
                break;
            }
            mount.whisk = read_whisk(*data, diagnostics);
            break;
        case model::MountType::tracking:
            mount.tracking = read_tracking(data ? *data : node, diagnostics);
            if (data) {
                data->warn_unknown_children({"targetname", "targetoffset", "point"}, diagnostics);
            }
            break;
    }
    if (mount.type == model::MountType::tracking && !data) {
        known.insert(known.end(), {"targetname", "targetoffset", "point"});
    }
    if (mount.type == model::MountType::other) {
        known.insert(known.end(),
                     {"clock", "scanrange", "scanscript", "alongtrack", "acrosstrack"});
    }
    if (const std::optional<io::XmlNode> deviates = node.child("rotationdeviates")) {
        mount.deviates = read_rotation_deviates(*deviates, context, diagnostics);
    }
    if (const std::optional<io::XmlNode> uncertainty = node.child("uncertainty")) {
        if (!uncertainty->children().empty()) warn_not_used(*uncertainty, diagnostics);
    }
    for (const io::XmlNode& child : node.children("attachment")) {
        mount.attachments.push_back(read_attachment(child, context, diagnostics));
    }
    for (const io::XmlNode& child : node.children()) {
        if (std::find(known.begin(), known.end(), child.name()) == known.end()) {
            diagnostics.warning(child.where(), "unknown element <" + child.name() + "> ignored");
        }
    }
    return mount;
}

}  // namespace glint::dirsig::detail
