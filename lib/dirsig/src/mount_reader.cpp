#include "glint/core/text.h"
// SPDX-License-Identifier: Apache-2.0
#include "glint/core/text.h"
// Mounts of a `.platform`: static, commanded and tabulated pointing, whisk scanners,
#include "glint/core/text.h"
// tracking mounts (the other DIRSIG types are accepted with a warning and held static), and
#include "glint/core/text.h"
// the per-axis pointing jitter of `<rotationdeviates>`. The XML glint defines for whisk,
#include "glint/core/text.h"
// tracking and rotationdeviates is documented in docs/formats.md.
#include <algorithm>
#include <array>
#include <cctype>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "glint/core/text.h"
#include "platform_tree.h"
namespace glint::dirsig::detail {
#include "glint/core/text.h"
namespace {
#include "glint/core/text.h"
constexpr std::array<std::string_view, 3> kRotations = {"xrotation", "yrotation", "zrotation"};
#include "glint/core/text.h"
constexpr std::array<std::string_view, 3> kTranslations = {"xtranslation", "ytranslation",
#include "glint/core/text.h"
                                                           "ztranslation"};
#include "glint/core/text.h"
struct MountTypeName {
#include "glint/core/text.h"
    std::string_view text;
#include "glint/core/text.h"
    model::MountType type;
#include "glint/core/text.h"
};
#include "glint/core/text.h"
constexpr std::array<MountTypeName, 8> kMountTypes = {{
#include "glint/core/text.h"
    {"static", model::MountType::static_mount},
#include "glint/core/text.h"
    {"commanded", model::MountType::commanded},
#include "glint/core/text.h"
    {"tabulated", model::MountType::tabulated},
#include "glint/core/text.h"
    {"whisk", model::MountType::whisk},
#include "glint/core/text.h"
    {"tracking", model::MountType::tracking},
#include "glint/core/text.h"
    {"lemniscate", model::MountType::other},
#include "glint/core/text.h"
    {"line", model::MountType::other},
#include "glint/core/text.h"
    {"scripted", model::MountType::other},
#include "glint/core/text.h"
}};
#include "glint/core/text.h"
/// The `<entry>` table of a commanded or tabulated mount: times strictly increasing.
#include "glint/core/text.h"
std::vector<model::MountEntry> read_entries(const io::XmlNode& data, std::string_view mount_type,
#include "glint/core/text.h"
                                            double factor, Diagnostics& diagnostics) {
#include "glint/core/text.h"
    std::vector<model::MountEntry> entries;
#include "glint/core/text.h"
    std::optional<double> previous;
#include "glint/core/text.h"
    for (const io::XmlNode& node : data.children("entry")) {
#include "glint/core/text.h"
        model::MountEntry entry;
#include "glint/core/text.h"
        entry.where = node.where();
#include "glint/core/text.h"
        std::optional<double> time;
#include "glint/core/text.h"
        if (const std::optional<io::XmlNode> datetime = node.child("datetime")) {
#include "glint/core/text.h"
            const std::string type =
#include "glint/core/text.h"
                lower_trimmed(datetime->attribute("type").value_or("relative"));
#include "glint/core/text.h"
            if (type == "absolute") {
#include "glint/core/text.h"
                diagnostics.error(datetime->where(),
#include "glint/core/text.h"
                                  "absolute mount times need the tasks file's reference date and "
#include "glint/core/text.h"
                                  "are not supported yet, expected type=\"relative\" (seconds "
#include "glint/core/text.h"
                                  "after the reference time)");
#include "glint/core/text.h"
            } else if (type != "relative") {
#include "glint/core/text.h"
                diagnostics.error(datetime->where_attribute("type"),
#include "glint/core/text.h"
                                  "unknown datetime type \"" + *datetime->attribute("type") +
#include "glint/core/text.h"
                                      "\", expected relative or absolute");
#include "glint/core/text.h"
            } else {
#include "glint/core/text.h"
                time = datetime->own_double(diagnostics);
#include "glint/core/text.h"
            }
#include "glint/core/text.h"
        } else {
#include "glint/core/text.h"
            diagnostics.error(node.where(), "missing required element <datetime>");
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
        entry.rotation_rad = read_triplet(node, kRotations, factor, diagnostics);
#include "glint/core/text.h"
        entry.translation_m = read_triplet(node, kTranslations, 1.0, diagnostics);
#include "glint/core/text.h"
        node.warn_unknown_children({"datetime", "xrotation", "yrotation", "zrotation",
#include "glint/core/text.h"
                                    "xtranslation", "ytranslation", "ztranslation"},
#include "glint/core/text.h"
                                   diagnostics);
#include "glint/core/text.h"
        if (time) {
#include "glint/core/text.h"
            entry.time_s = *time;
#include "glint/core/text.h"
            if (previous && *time <= *previous) {
#include "glint/core/text.h"
                diagnostics.error(entry.where, "entry time " + number_text(*time) +
#include "glint/core/text.h"
                                                   " s is not after the previous entry's " +
#include "glint/core/text.h"
                                                   number_text(*previous) +
#include "glint/core/text.h"
                                                   " s, expected strictly increasing times");
#include "glint/core/text.h"
            }
#include "glint/core/text.h"
            previous = time;
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
        entries.push_back(std::move(entry));
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (entries.empty()) {
#include "glint/core/text.h"
        diagnostics.error(data.where(),
#include "glint/core/text.h"
                          std::string(mount_type) + " mount has no <entry>, expected at least one");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    return entries;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
/// Repeat period of a tabulated mount: @period or <period> on <data>, else the last time.
#include "glint/core/text.h"
std::optional<double> read_period(const io::XmlNode& data,
#include "glint/core/text.h"
                                  const std::vector<model::MountEntry>& entries,
#include "glint/core/text.h"
                                  Diagnostics& diagnostics) {
#include "glint/core/text.h"
    std::optional<double> period;
#include "glint/core/text.h"
    const bool has_attribute = data.attribute("period").has_value();
#include "glint/core/text.h"
    const std::optional<io::XmlNode> child = data.child("period");
#include "glint/core/text.h"
    if (has_attribute && child) {
#include "glint/core/text.h"
        diagnostics.error(child->where(),
#include "glint/core/text.h"
                          "both @period and <period> given, expected only one of the two");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (has_attribute) {
#include "glint/core/text.h"
        period = data.attribute_double("period", diagnostics, io::NumberRule::positive());
#include "glint/core/text.h"
    } else if (child) {
#include "glint/core/text.h"
        period = data.optional_double("period", diagnostics, io::NumberRule::positive());
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    const double last = entries.empty() ? 0.0 : entries.back().time_s;
#include "glint/core/text.h"
    if (period) {
#include "glint/core/text.h"
        if (*period < last) {
#include "glint/core/text.h"
            diagnostics.error(child ? child->where() : data.where_attribute("period"),
#include "glint/core/text.h"
                              "period " + number_text(*period) +
#include "glint/core/text.h"
                                  " s is shorter than the last entry time " + number_text(last) +
#include "glint/core/text.h"
                                  " s, expected a period >= the last time");
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
        return period;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (last > 0.0) return last;
#include "glint/core/text.h"
    return std::nullopt;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
/// `<data>` of a whisk mount (see docs/formats.md).
#include "glint/core/text.h"
model::WhiskScan read_whisk(const io::XmlNode& data, Diagnostics& diagnostics) {
#include "glint/core/text.h"
    model::WhiskScan scan;
#include "glint/core/text.h"
    const double factor = angular_unit_factor(data, diagnostics);
#include "glint/core/text.h"
    const std::optional<io::XmlNode> along = data.child("alongtrack");
#include "glint/core/text.h"
    const std::optional<io::XmlNode> across = data.child("acrosstrack");
#include "glint/core/text.h"
    const std::optional<std::string> axis =
#include "glint/core/text.h"
        data.optional_enum("axis", {"acrosstrack", "alongtrack"}, diagnostics);
#include "glint/core/text.h"
    if (axis) {
#include "glint/core/text.h"
        scan.axis = *axis == "alongtrack" ? model::WhiskScan::Axis::along_track
#include "glint/core/text.h"
                                          : model::WhiskScan::Axis::across_track;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    io::XmlNode source = data;
#include "glint/core/text.h"
    if (along && across) {
#include "glint/core/text.h"
        diagnostics.error(across->where(),
#include "glint/core/text.h"
                          "both <alongtrack> and <acrosstrack> given, expected one scan axis");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (along || across) {
#include "glint/core/text.h"
        source = along ? *along : *across;
#include "glint/core/text.h"
        const auto element_axis =
#include "glint/core/text.h"
            along ? model::WhiskScan::Axis::along_track : model::WhiskScan::Axis::across_track;
#include "glint/core/text.h"
        if (axis && element_axis != scan.axis) {
#include "glint/core/text.h"
            diagnostics.error(source.where(), "<" + source.name() + "> contradicts <axis>" + *axis +
#include "glint/core/text.h"
                                                  "</axis>, expected one scan axis");
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
        scan.axis = element_axis;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    // Each value may sit in the axis element or directly in <data>.
#include "glint/core/text.h"
    const auto holder = [&](std::string_view name) -> const io::XmlNode& {
#include "glint/core/text.h"
        return source.child(name) ? source : data;
#include "glint/core/text.h"
    };
#include "glint/core/text.h"
    const std::optional<double> min =
#include "glint/core/text.h"
        holder("minimumangle").required_double("minimumangle", diagnostics);
#include "glint/core/text.h"
    const std::optional<double> max =
#include "glint/core/text.h"
        holder("maximumangle").required_double("maximumangle", diagnostics);
#include "glint/core/text.h"
    if (min) scan.min_angle_rad = *min * factor;
#include "glint/core/text.h"
    if (max) scan.max_angle_rad = *max * factor;
#include "glint/core/text.h"
    if (min && max && *min > *max) {
#include "glint/core/text.h"
        diagnostics.error(holder("maximumangle").child("maximumangle")->where(),
#include "glint/core/text.h"
                          "maximumangle " + number_text(*max) + " is less than minimumangle " +
#include "glint/core/text.h"
                              number_text(*min) + ", expected minimumangle <= maximumangle");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    scan.rate_hz = holder("rate")
#include "glint/core/text.h"
                       .required_double("rate", diagnostics, io::NumberRule::positive())
#include "glint/core/text.h"
                       .value_or(0.0);
#include "glint/core/text.h"
    scan.phase_rad = holder("phase").optional_double("phase", diagnostics).value_or(0.0) * factor;
#include "glint/core/text.h"
    if (const auto profile =
#include "glint/core/text.h"
            holder("profile").optional_enum("profile", {"sinusoidal", "linear"}, diagnostics)) {
#include "glint/core/text.h"
        scan.sinusoidal = *profile == "sinusoidal";
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    data.warn_unknown_children({"axis", "alongtrack", "acrosstrack", "minimumangle", "maximumangle",
#include "glint/core/text.h"
                                "rate", "phase", "profile"},
#include "glint/core/text.h"
                               diagnostics);
#include "glint/core/text.h"
    if (source.path() != data.path() || source.line() != data.line()) {
#include "glint/core/text.h"
        source.warn_unknown_children({"minimumangle", "maximumangle", "rate", "phase", "profile"},
#include "glint/core/text.h"
                                     diagnostics);
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    return scan;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
/// A point: <x>, <y>, <z> children, or three numbers in the text (blank or comma separated).
#include "glint/core/text.h"
std::optional<std::array<double, 3>> read_point(const io::XmlNode& node, Diagnostics& diagnostics) {
#include "glint/core/text.h"
    if (node.child("x") || node.child("y") || node.child("z")) {
#include "glint/core/text.h"
        node.warn_unknown_children({"x", "y", "z"}, diagnostics);
#include "glint/core/text.h"
        return read_triplet(node, {"x", "y", "z"}, 1.0, diagnostics);
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    std::string text = node.text();
#include "glint/core/text.h"
    std::replace(text.begin(), text.end(), ',', ' ');
#include "glint/core/text.h"
    std::vector<double> values;
#include "glint/core/text.h"
    std::size_t pos = 0;
#include "glint/core/text.h"
    bool ok = true;
#include "glint/core/text.h"
    while (pos < text.size()) {
#include "glint/core/text.h"
        while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos]))) ++pos;
#include "glint/core/text.h"
        std::size_t end = pos;
#include "glint/core/text.h"
        while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end]))) ++end;
#include "glint/core/text.h"
        if (end == pos) break;
#include "glint/core/text.h"
        const std::optional<double> value = parse_double(text.substr(pos, end - pos));
#include "glint/core/text.h"
        ok = ok && value.has_value();
#include "glint/core/text.h"
        if (value) values.push_back(*value);
#include "glint/core/text.h"
        pos = end;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (!ok || values.size() != 3) {
#include "glint/core/text.h"
        diagnostics.error(node.where(), "\"" + node.text() +
#include "glint/core/text.h"
                                            "\" is not a point, expected x y z (three numbers, "
#include "glint/core/text.h"
                                            "or <x>, <y>, <z> children) in m");
#include "glint/core/text.h"
        return std::nullopt;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    return std::array<double, 3>{values[0], values[1], values[2]};
#include "glint/core/text.h"
}
#include "glint/core/text.h"
/// Target of a tracking mount, read from <data> or from the mount itself.
#include "glint/core/text.h"
model::TrackingTarget read_tracking(const io::XmlNode& source, Diagnostics& diagnostics) {
#include "glint/core/text.h"
    model::TrackingTarget target;
#include "glint/core/text.h"
    const std::optional<std::string> name = source.optional_text("targetname");
#include "glint/core/text.h"
    if (name) target.name = *name;
#include "glint/core/text.h"
    if (const std::optional<io::XmlNode> offset = source.child("targetoffset")) {
#include "glint/core/text.h"
        const std::optional<io::XmlNode> point = offset->child("point");
#include "glint/core/text.h"
        if (point) offset->warn_unknown_children({"point"}, diagnostics);
#include "glint/core/text.h"
        if (auto value = read_point(point ? *point : *offset, diagnostics))
#include "glint/core/text.h"
            target.offset_m = *value;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (const std::optional<io::XmlNode> point = source.child("point")) {
#include "glint/core/text.h"
        target.point_m = read_point(*point, diagnostics);
#include "glint/core/text.h"
        if (name) {
#include "glint/core/text.h"
            diagnostics.error(point->where(),
#include "glint/core/text.h"
                              "both <targetname> and <point> given, expected one target");
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    } else if (!name || name->empty()) {
#include "glint/core/text.h"
        diagnostics.error(source.where(),
#include "glint/core/text.h"
                          "tracking mount has no target, expected <targetname> or <point>");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    return target;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
/// One axis of <rotationdeviates>.
#include "glint/core/text.h"
model::JitterAxis read_jitter_axis(const io::XmlNode& node, double factor,
#include "glint/core/text.h"
                                   const ReadContext& context, Diagnostics& diagnostics) {
#include "glint/core/text.h"
    model::JitterAxis axis;
#include "glint/core/text.h"
    const std::optional<std::string> raw = node.attribute("type");
#include "glint/core/text.h"
    const std::optional<io::XmlNode> file =
#include "glint/core/text.h"
        node.child("psdfile") ? node.child("psdfile") : node.child("filename");
#include "glint/core/text.h"
    std::string type;
#include "glint/core/text.h"
    if (raw) {
#include "glint/core/text.h"
        type = lower_trimmed(*raw);
#include "glint/core/text.h"
    } else if (file) {
#include "glint/core/text.h"
        type = "psd";
#include "glint/core/text.h"
    } else if (!node.children().empty()) {
#include "glint/core/text.h"
        type = "normal";
#include "glint/core/text.h"
    } else {
#include "glint/core/text.h"
        type = "none";
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (type == "normal" || type == "gaussian") {
#include "glint/core/text.h"
        axis.kind = model::JitterAxis::Kind::normal;
#include "glint/core/text.h"
        axis.mean_rad = node.optional_double("mean", diagnostics).value_or(0.0) * factor;
#include "glint/core/text.h"
        const std::optional<double> stddev =
#include "glint/core/text.h"
            read_either(node, "stddev", "sigma", diagnostics, io::NumberRule::non_negative());
#include "glint/core/text.h"
        if (stddev) {
#include "glint/core/text.h"
            axis.stddev_rad = *stddev * factor;
#include "glint/core/text.h"
        } else if (!node.child("stddev") && !node.child("sigma")) {
#include "glint/core/text.h"
            diagnostics.error(node.where(),
#include "glint/core/text.h"
                              "missing required element <stddev> (a normal jitter needs a "
#include "glint/core/text.h"
                              "standard deviation)");
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    } else if (type == "psd") {
#include "glint/core/text.h"
        axis.kind = model::JitterAxis::Kind::psd;
#include "glint/core/text.h"
        if (node.child("psdfile") && node.child("filename")) {
#include "glint/core/text.h"
            diagnostics.error(node.child("filename")->where(),
#include "glint/core/text.h"
                              "both <psdfile> and <filename> given, expected only one of the two");
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
        if (!file || file->text().empty()) {
#include "glint/core/text.h"
            diagnostics.error(node.where(),
#include "glint/core/text.h"
                              "missing required element <psdfile> (a psd jitter needs a file of "
#include "glint/core/text.h"
                              "frequency, PSD pairs)");
#include "glint/core/text.h"
        } else {
#include "glint/core/text.h"
            axis.psd_file = context.options.paths.resolve(file->text(), context.base_dir,
#include "glint/core/text.h"
                                                          file->where(), diagnostics);
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    } else if (type != "none") {
#include "glint/core/text.h"
        diagnostics.error(node.where_attribute("type"),
#include "glint/core/text.h"
                          "unknown jitter type \"" + *raw + "\", expected normal, psd or none");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    node.warn_unknown_children({"mean", "stddev", "sigma", "psdfile", "filename"}, diagnostics);
#include "glint/core/text.h"
    return axis;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
}  // namespace
#include "glint/core/text.h"
model::RotationDeviates read_rotation_deviates(const io::XmlNode& node, const ReadContext& context,
#include "glint/core/text.h"
                                               Diagnostics& diagnostics) {
#include "glint/core/text.h"
    model::RotationDeviates deviates;
#include "glint/core/text.h"
    deviates.where = node.where();
#include "glint/core/text.h"
    const double factor = angular_unit_factor(node, diagnostics);
#include "glint/core/text.h"
    std::array<std::string, 3> given_by;
#include "glint/core/text.h"
    for (const io::XmlNode& child : node.children()) {
#include "glint/core/text.h"
        std::size_t index = 3;
#include "glint/core/text.h"
        if (child.name() == "xrotation" || child.name() == "alongtrack") index = 0;
#include "glint/core/text.h"
        if (child.name() == "yrotation" || child.name() == "acrosstrack") index = 1;
#include "glint/core/text.h"
        if (child.name() == "zrotation") index = 2;
#include "glint/core/text.h"
        if (index == 3) continue;
#include "glint/core/text.h"
        if (!given_by[index].empty()) {
#include "glint/core/text.h"
            diagnostics.error(child.where(), "<" + given_by[index] + "> and <" + child.name() +
#include "glint/core/text.h"
                                                 "> both give the jitter about " +
#include "glint/core/text.h"
                                                 std::string(1, "xyz"[index]) + ", expected one");
#include "glint/core/text.h"
            continue;
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
        given_by[index] = child.name();
#include "glint/core/text.h"
        deviates.axes[index] = read_jitter_axis(child, factor, context, diagnostics);
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    node.warn_unknown_children({"xrotation", "yrotation", "zrotation", "alongtrack", "acrosstrack"},
#include "glint/core/text.h"
                               diagnostics);
#include "glint/core/text.h"
    return deviates;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
model::Mount read_mount(const io::XmlNode& node, const ReadContext& context,
#include "glint/core/text.h"
                        Diagnostics& diagnostics) {
#include "glint/core/text.h"
    model::Mount mount;
#include "glint/core/text.h"
    mount.name = node.attribute("name").value_or("");
#include "glint/core/text.h"
    mount.where = node.where();
#include "glint/core/text.h"
    mount.deviates.where = node.where();
#include "glint/core/text.h"
    if (const std::optional<std::string> raw = node.attribute("type")) {
#include "glint/core/text.h"
        mount.type_text = *raw;
#include "glint/core/text.h"
        const std::string type = lower_trimmed(*raw);
#include "glint/core/text.h"
        const auto found = std::find_if(kMountTypes.begin(), kMountTypes.end(),
#include "glint/core/text.h"
                                        [&](const MountTypeName& t) { return t.text == type; });
#include "glint/core/text.h"
        if (found == kMountTypes.end()) {
#include "glint/core/text.h"
            diagnostics.error(node.where_attribute("type"),
#include "glint/core/text.h"
                              "unknown mount type \"" + *raw +
#include "glint/core/text.h"
                                  "\", expected static, commanded, tabulated, whisk, tracking, "
#include "glint/core/text.h"
                                  "lemniscate, line or scripted");
#include "glint/core/text.h"
        } else {
#include "glint/core/text.h"
            mount.type = found->type;
#include "glint/core/text.h"
            if (mount.type == model::MountType::other) {
#include "glint/core/text.h"
                diagnostics.warning(
#include "glint/core/text.h"
                    node.where_attribute("type"),
#include "glint/core/text.h"
                    "mount type \"" + *raw + "\" is not supported yet; treated as static");
#include "glint/core/text.h"
            }
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    const std::optional<io::XmlNode> data = node.child("data");
#include "glint/core/text.h"
    std::vector<std::string_view> known = {"data", "attachment", "rotationdeviates", "uncertainty"};
#include "glint/core/text.h"
    switch (mount.type) {
#include "glint/core/text.h"
        case model::MountType::static_mount:
#include "glint/core/text.h"
        case model::MountType::other:
#include "glint/core/text.h"
            if (data) {
#include "glint/core/text.h"
                const double factor = angular_unit_factor(*data, diagnostics);
#include "glint/core/text.h"
                mount.rotation_order = read_rotation_order(*data, diagnostics);
#include "glint/core/text.h"
                mount.rotation_rad = read_triplet(*data, kRotations, factor, diagnostics);
#include "glint/core/text.h"
                if (mount.type == model::MountType::static_mount) {
#include "glint/core/text.h"
                    data->warn_unknown_children({"xrotation", "yrotation", "zrotation"},
#include "glint/core/text.h"
                                                diagnostics);
#include "glint/core/text.h"
                }
#include "glint/core/text.h"
            }
#include "glint/core/text.h"
            break;
#include "glint/core/text.h"
        case model::MountType::commanded:
#include "glint/core/text.h"
        case model::MountType::tabulated:
#include "glint/core/text.h"
            if (!data) {
#include "glint/core/text.h"
                diagnostics.error(node.where(), "missing required element <data> (a " +
#include "glint/core/text.h"
                                                    mount.type_text +
#include "glint/core/text.h"
                                                    " mount needs a table of <entry>)");
#include "glint/core/text.h"
                break;
#include "glint/core/text.h"
            }
#include "glint/core/text.h"
            {
#include "glint/core/text.h"
                const double factor = angular_unit_factor(*data, diagnostics);
#include "glint/core/text.h"
                mount.rotation_order = read_rotation_order(*data, diagnostics);
#include "glint/core/text.h"
                mount.entries = read_entries(*data, mount.type_text, factor, diagnostics);
#include "glint/core/text.h"
                if (mount.type == model::MountType::tabulated) {
#include "glint/core/text.h"
                    mount.period_s = read_period(*data, mount.entries, diagnostics);
#include "glint/core/text.h"
                    data->warn_unknown_children({"entry", "period"}, diagnostics);
#include "glint/core/text.h"
                } else {
#include "glint/core/text.h"
                    data->warn_unknown_children({"entry"}, diagnostics);
#include "glint/core/text.h"
                }
#include "glint/core/text.h"
            }
#include "glint/core/text.h"
            break;
#include "glint/core/text.h"
        case model::MountType::whisk:
#include "glint/core/text.h"
            if (!data) {
#include "glint/core/text.h"
                diagnostics.error(node.where(),
#include "glint/core/text.h"
                                  "missing required element <data> (a whisk mount needs its scan)");
#include "glint/core/text.h"
                break;
#include "glint/core/text.h"
            }
#include "glint/core/text.h"
            mount.whisk = read_whisk(*data, diagnostics);
#include "glint/core/text.h"
            break;
#include "glint/core/text.h"
        case model::MountType::tracking:
#include "glint/core/text.h"
            mount.tracking = read_tracking(data ? *data : node, diagnostics);
#include "glint/core/text.h"
            if (data) {
#include "glint/core/text.h"
                data->warn_unknown_children({"targetname", "targetoffset", "point"}, diagnostics);
#include "glint/core/text.h"
            }
#include "glint/core/text.h"
            break;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (mount.type == model::MountType::tracking && !data) {
#include "glint/core/text.h"
        known.insert(known.end(), {"targetname", "targetoffset", "point"});
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (mount.type == model::MountType::other) {
#include "glint/core/text.h"
        known.insert(known.end(),
#include "glint/core/text.h"
                     {"clock", "scanrange", "scanscript", "alongtrack", "acrosstrack"});
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (const std::optional<io::XmlNode> deviates = node.child("rotationdeviates")) {
#include "glint/core/text.h"
        mount.deviates = read_rotation_deviates(*deviates, context, diagnostics);
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (const std::optional<io::XmlNode> uncertainty = node.child("uncertainty")) {
#include "glint/core/text.h"
        if (!uncertainty->children().empty()) warn_not_used(*uncertainty, diagnostics);
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    for (const io::XmlNode& child : node.children("attachment")) {
#include "glint/core/text.h"
        mount.attachments.push_back(read_attachment(child, context, diagnostics));
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    for (const io::XmlNode& child : node.children()) {
#include "glint/core/text.h"
        if (std::find(known.begin(), known.end(), child.name()) == known.end()) {
#include "glint/core/text.h"
            diagnostics.warning(child.where(), "unknown element <" + child.name() + "> ignored");
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    return mount;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
}  // namespace glint::dirsig::detail
