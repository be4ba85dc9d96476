// SPDX-License-Identifier: Apache-2.0
// Jitter, read one way wherever DIRSIG files give it (jitter_reader.h): the axes of the
// platform jitter elements of both motion file kinds (`locationjitter`, `orientationjitter`)
// and of a mount's `<rotationdeviates>`, each uncorrelated (mean, stddev) or correlated (an
// inline `<psd>` entry table or a PSD file), into model::JitterSpec.
#include "jitter_reader.h"

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "glint/core/units.h"
#include "motion_parts.h"
#include "platform_tree.h"

namespace glint::dirsig::detail {
namespace {

/// Reads a psd `<entry>` table into `table`.
void read_psd_entries(const io::XmlNode& psd, double magnitude_factor, double phase_factor,
                      model::PsdTable& table, Diagnostics& diagnostics) {
    table.where = psd.where();
    std::size_t with_phase = 0;
    std::size_t index = 0;
    std::optional<double> previous;
    const std::vector<io::XmlNode> entries = psd.children("entry");
    for (const io::XmlNode& entry : entries) {
        ++index;
        entry.warn_unknown_children({"frequency", "magnitude", "phase"}, diagnostics);
        const std::optional<double> f =
            entry.required_double("frequency", diagnostics, io::NumberRule::non_negative());
        const std::optional<double> m =
            entry.required_double("magnitude", diagnostics, io::NumberRule::non_negative());
        const std::optional<double> phase = entry.optional_double("phase", diagnostics);
        if (entry.child("phase")) ++with_phase;
        if (!f || !m) continue;
        if (previous && *f <= *previous) {
            const std::string name = "entry " + std::to_string(index);
            const std::string before = "entry " + std::to_string(index - 1);
            diagnostics.error(
                entry.where(),
                *f == *previous
                    ? name + " has the same frequency (" + number_text(*f) + " Hz) as " + before +
                          ": duplicate frequencies, expected strictly increasing frequencies"
                    : name + " frequency " + number_text(*f) + " Hz is below " + before + "'s " +
                          number_text(*previous) + " Hz, expected strictly increasing frequencies");
            continue;
        }
        previous = f;
        table.frequency_hz.push_back(*f);
        table.psd.push_back(*m * magnitude_factor);
        table.phase_rad.push_back(phase.value_or(0.0) * phase_factor);
    }
    if (entries.size() < 2) {
        diagnostics.error(psd.where(), "<psd> has " + std::to_string(entries.size()) +
                                           " entries, expected at least 2 (frequency, magnitude "
                                           "pairs)");
    }
    if (with_phase == 0) {
        table.phase_rad.clear();
    } else if (with_phase != entries.size()) {
        diagnostics.error(psd.where(), "<phase> given in " + std::to_string(with_phase) + " of " +
                                           std::to_string(entries.size()) +
                                           " entries, expected it in every entry or in none");
        table.phase_rad.clear();
    }
}

}  // namespace

model::JitterSpec read_jitter_axis(const io::XmlNode& axis, JitterQuantity quantity,
                                   double parent_factor, const ReadOptions& options,
                                   const std::filesystem::path& base_dir,
                                   Diagnostics& diagnostics) {
    const bool location = quantity == JitterQuantity::length;
    model::JitterSpec spec;
    spec.where = axis.where();
    const char* const unit_attribute = location ? "spatialunits" : "angularunits";
    const double factor = location
                              ? length_unit_factor(axis, unit_attribute, parent_factor, diagnostics)
                              : angle_unit_factor(axis, unit_attribute, parent_factor, diagnostics);
    const std::optional<io::XmlNode> psd = axis.child("psd");
    const std::optional<io::XmlNode> psd_file = axis.child("psdfile");
    const std::optional<io::XmlNode> file_name = axis.child("filename");

    std::string type;
    if (const std::optional<std::string> raw = axis.attribute("type")) {
        const std::string value = lower_trimmed(*raw);
        if (value == "correlated" || value == "psd") {
            type = "psd";
        } else if (value == "uncorrelated" || value == "normal" || value == "gaussian") {
            type = "normal";
        } else if (value == "none") {
            type = "none";
        } else {
            diagnostics.error(axis.where_attribute("type"),
                              "unknown jitter type \"" + *raw +
                                  "\", expected correlated (psd), uncorrelated (normal) or none");
            return spec;
        }
    } else if (psd || psd_file || file_name) {
        type = "psd";
    } else if (axis.child("mean") || axis.child("stddev") || axis.child("sigma")) {
        type = "normal";
    } else {
        type = "none";
    }

    if (type == "normal") {
        spec.kind = model::JitterSpec::Kind::normal;
        spec.mean = axis.optional_double("mean", diagnostics).value_or(0.0) * factor;
        const std::optional<double> stddev =
            read_either(axis, "stddev", "sigma", diagnostics, io::NumberRule::non_negative());
        if (stddev) {
            spec.stddev = *stddev * factor;
        } else if (!axis.child("stddev") && !axis.child("sigma")) {
            diagnostics.error(axis.where(),
                              "missing required element <stddev> (an uncorrelated (normal) "
                              "jitter needs a standard deviation)");
        }
    } else if (type == "psd") {
        spec.kind = model::JitterSpec::Kind::psd;
        if (psd_file && file_name) {
            diagnostics.error(file_name->where(),
                              "both <psdfile> and <filename> given, expected only one of the two");
        }
        const std::optional<io::XmlNode> file = psd_file ? psd_file : file_name;
        if (psd && file) {
            diagnostics.error(file->where(), "both <psd> and <" + file->name() +
                                                 "> given, expected the PSD table or its file");
        }
        if (psd) {
            if (const std::optional<std::string> raw = psd->attribute("frequencyunits")) {
                const std::string units = lower_trimmed(*raw);
                if (units != "hertz" && units != "hz") {
                    diagnostics.error(psd->where_attribute("frequencyunits"),
                                      "unknown frequencyunits \"" + *raw + "\", expected hertz");
                }
            }
            const double magnitude =
                location ? length_unit_factor(*psd, "magnitudeunits", factor, diagnostics)
                         : angle_unit_factor(*psd, "magnitudeunits", factor, diagnostics);
            const double phase = angle_unit_factor(*psd, "phaseunits", 1.0, diagnostics);
            psd->warn_unknown_children({"entry"}, diagnostics);
            model::PsdTable table;
            read_psd_entries(*psd, magnitude * magnitude, phase, table, diagnostics);
            spec.psd = std::move(table);
        } else if (file) {
            if (file->text().empty()) {
                diagnostics.error(file->where(), "expected a file path, got an empty one");
            } else {
                spec.psd_file =
                    options.paths.resolve(file->text(), base_dir, file->where(), diagnostics);
            }
        } else {
            diagnostics.error(axis.where(),
                              "missing required element <psd> (a correlated jitter needs a <psd> "
                              "table or a <psdfile>)");
        }
    }
    axis.warn_unknown_children({"mean", "stddev", "sigma", "psd", "psdfile", "filename"},
                               diagnostics);
    return spec;
}

namespace {

/// The axes of one jitter element into `axes`.
void read_jitter_axes(const io::XmlNode& node, bool location,
                      std::array<model::JitterSpec, 3>& axes, const MotionReadContext& context,
                      Diagnostics& diagnostics) {
    const double factor = location ? length_unit_factor(node, "spatialunits", 1.0, diagnostics)
                                   : angle_unit_factor(node, "angularunits", 1.0, diagnostics);
    constexpr std::array<std::string_view, 3> kAxes = {"xaxis", "yaxis", "zaxis"};
    for (std::size_t i = 0; i < 3; ++i) {
        const std::vector<io::XmlNode> given = node.children(kAxes[i]);
        if (given.empty()) continue;
        for (std::size_t k = 1; k < given.size(); ++k) {
            diagnostics.error(given[k].where(), "<" + std::string(kAxes[i]) +
                                                    "> given again (first at line " +
                                                    std::to_string(given[0].line()) +
                                                    "), expected one element per axis");
        }
        axes[i] =
            read_jitter_axis(given[0], location ? JitterQuantity::length : JitterQuantity::angle,
                             factor, context.options, context.base_dir, diagnostics);
    }
    node.warn_unknown_children({"xaxis", "yaxis", "zaxis"}, diagnostics);
}

}  // namespace

model::PlatformJitter read_platform_jitter(const io::XmlNode& parent,
                                           const MotionReadContext& context,
                                           Diagnostics& diagnostics) {
    model::PlatformJitter jitter;
    for (const io::XmlNode& node : parent.children("locationjitter")) {
        read_jitter_axes(node, true, jitter.location_m, context, diagnostics);
    }
    for (const io::XmlNode& node : parent.children("orientationjitter")) {
        read_jitter_axes(node, false, jitter.orientation_rad, context, diagnostics);
    }
    for (const std::string_view name : {"locationjitter", "orientationjitter"}) {
        const std::vector<io::XmlNode> given = parent.children(name);
        for (std::size_t k = 1; k < given.size(); ++k) {
            diagnostics.error(given[k].where(),
                              "<" + std::string(name) + "> given again (first at line " +
                                  std::to_string(given[0].line()) + "), expected at most one");
        }
    }
    return jitter;
}

}  // namespace glint::dirsig::detail
