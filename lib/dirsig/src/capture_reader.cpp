#include "glint/core/text.h"
// SPDX-License-Identifier: Apache-2.0
#include "glint/core/text.h"
// The capture-method half of the `.platform` reader: `<capturemethod>` and its children
#include "glint/core/text.h"
// (sample strategy, image file, spatial response, temporal integration, detector model,
#include "glint/core/text.h"
// convergence, PSF, active area, processing tasks), the same extras written directly in
#include "glint/core/text.h"
// `<focalplane>`, and the checks that need the whole focal plane. The spectral response is
#include "glint/core/text.h"
// read by spectral_reader.cpp. Every problem goes to Diagnostics with its location.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "glint/core/text.h"
#include "platform_parts.h"
#include "spectral_reader.h"
namespace glint::dirsig::detail {
#include "glint/core/text.h"
namespace {
#include "glint/core/text.h"
using capture_io::number_text;
#include "glint/core/text.h"
using capture_io::required_attribute;
#include "glint/core/text.h"
using capture_io::single_child;
#include "glint/core/text.h"
using capture_io::trim;
#include "glint/core/text.h"
/// The most paths per pixel a convergence setting may ask for.
#include "glint/core/text.h"
constexpr std::int64_t kMaxPathsPerPixel = 1'000'000'000;
#include "glint/core/text.h"
/// ENVI data types an image file may be written as.
#include "glint/core/text.h"
constexpr int kEnviDataTypes[] = {1, 2, 3, 4, 5, 12, 13, 14, 15};
#include "glint/core/text.h"
/// A whole number >= 1 in attribute `name`; nullopt when absent or invalid (invalid: error).
#include "glint/core/text.h"
std::optional<int> attribute_count(const io::XmlNode& node, std::string_view name,
#include "glint/core/text.h"
                                   Diagnostics& diagnostics) {
#include "glint/core/text.h"
    const auto value = node.attribute_double(name, diagnostics, io::NumberRule{1.0, 1e9});
#include "glint/core/text.h"
    if (!value) return std::nullopt;
#include "glint/core/text.h"
    if (*value != std::floor(*value)) {
#include "glint/core/text.h"
        diagnostics.error(node.where_attribute(name), std::string(name) + " " +
#include "glint/core/text.h"
                                                          number_text(*value) +
#include "glint/core/text.h"
                                                          " is invalid, expected an integer >= 1");
#include "glint/core/text.h"
        return std::nullopt;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    return static_cast<int>(*value);
#include "glint/core/text.h"
}
#include "glint/core/text.h"
/// Text of child `name` that must not be empty when given.
#include "glint/core/text.h"
std::optional<std::string> non_empty_text(const io::XmlNode& node, std::string_view name,
#include "glint/core/text.h"
                                          std::string_view expected, Diagnostics& diagnostics) {
#include "glint/core/text.h"
    const auto child = node.child(name);
#include "glint/core/text.h"
    if (!child) return std::nullopt;
#include "glint/core/text.h"
    std::string text = child->text();
#include "glint/core/text.h"
    if (text.empty()) {
#include "glint/core/text.h"
        diagnostics.error(child->where(),
#include "glint/core/text.h"
                          std::string(name) + " is empty, expected " + std::string(expected));
#include "glint/core/text.h"
        return std::nullopt;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    return text;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
/// A file named by child `name` (required), resolved against the platform file's folder.
#include "glint/core/text.h"
model::FileRef read_file_ref(const io::XmlNode& node, std::string_view name,
#include "glint/core/text.h"
                             const ReadContext& context, Diagnostics& diagnostics) {
#include "glint/core/text.h"
    const auto child = node.child(name);
#include "glint/core/text.h"
    if (!child) {
#include "glint/core/text.h"
        diagnostics.error(node.where(), "missing required element <" + std::string(name) + ">");
#include "glint/core/text.h"
        return {};
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    const auto text = non_empty_text(node, name, "a file name", diagnostics);
#include "glint/core/text.h"
    if (!text) return {};
#include "glint/core/text.h"
    return context.options.paths.resolve(*text, context.base_dir, child->where(), diagnostics);
#include "glint/core/text.h"
}
#include "glint/core/text.h"
model::SampleStrategy read_sample_strategy(const io::XmlNode& node, Diagnostics& diagnostics) {
#include "glint/core/text.h"
    model::SampleStrategy strategy;
#include "glint/core/text.h"
    node.warn_unknown_children({"hypersamplingmultiplier"}, diagnostics);
#include "glint/core/text.h"
    const std::string type = trim(node.attribute("type").value_or("central"));
#include "glint/core/text.h"
    if (!type.empty()) strategy.type = type;
#include "glint/core/text.h"
    strategy.hypersampling_multiplier =
#include "glint/core/text.h"
        node.optional_double("hypersamplingmultiplier", diagnostics, io::NumberRule{1.0, {}})
#include "glint/core/text.h"
            .value_or(1.0);
#include "glint/core/text.h"
    return strategy;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
model::SpatialResponse read_spatial_response(const io::XmlNode& node, Diagnostics& diagnostics) {
#include "glint/core/text.h"
    model::SpatialResponse response;
#include "glint/core/text.h"
    response.where = node.where();
#include "glint/core/text.h"
    node.warn_unknown_children({"entry"}, diagnostics);
#include "glint/core/text.h"
    response.spatial_sampling = trim(node.attribute("spatialsampling").value_or(""));
#include "glint/core/text.h"
    response.spectral_units = trim(node.attribute("spectralunits").value_or(""));
#include "glint/core/text.h"
    response.x_sub_elements = attribute_count(node, "xsubelements", diagnostics).value_or(1);
#include "glint/core/text.h"
    response.y_sub_elements = attribute_count(node, "ysubelements", diagnostics).value_or(1);
#include "glint/core/text.h"
    for (const auto& entry_node : node.children("entry")) {
#include "glint/core/text.h"
        entry_node.warn_unknown_children({"spectralpoint", "xwidth", "ywidth", "totalweight"},
#include "glint/core/text.h"
                                         diagnostics);
#include "glint/core/text.h"
        model::SpatialResponseEntry entry;
#include "glint/core/text.h"
        entry.where = entry_node.where();
#include "glint/core/text.h"
        entry.type = trim(entry_node.attribute("type").value_or(""));
#include "glint/core/text.h"
        const auto non_negative = io::NumberRule::non_negative();
#include "glint/core/text.h"
        entry.spectral_point = entry_node.optional_double("spectralpoint", diagnostics).value_or(0);
#include "glint/core/text.h"
        entry.x_width = entry_node.optional_double("xwidth", diagnostics, non_negative).value_or(1);
#include "glint/core/text.h"
        entry.y_width = entry_node.optional_double("ywidth", diagnostics, non_negative).value_or(1);
#include "glint/core/text.h"
        entry.total_weight =
#include "glint/core/text.h"
            entry_node.optional_double("totalweight", diagnostics, non_negative).value_or(1);
#include "glint/core/text.h"
        response.entries.push_back(std::move(entry));
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    diagnostics.warning(node.where(),
#include "glint/core/text.h"
                        "<spatialresponse> is a DIRSIG4 setting; glint samples pixel areas as "
#include "glint/core/text.h"
                        "DIRSIG5 does and ignores it");
#include "glint/core/text.h"
    return response;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
model::TemporalIntegration read_temporal_integration(const io::XmlNode& node,
#include "glint/core/text.h"
                                                     Diagnostics& diagnostics) {
#include "glint/core/text.h"
    model::TemporalIntegration integration;
#include "glint/core/text.h"
    integration.where = node.where();
#include "glint/core/text.h"
    node.warn_unknown_children({"time", "samples"}, diagnostics);
#include "glint/core/text.h"
    integration.tdi = node.attribute_bool("tdi", diagnostics).value_or(false);
#include "glint/core/text.h"
    integration.time_s =
#include "glint/core/text.h"
        node.optional_double("time", diagnostics, io::NumberRule::non_negative()).value_or(0.0);
#include "glint/core/text.h"
    const auto samples =
#include "glint/core/text.h"
        node.optional_int("samples", diagnostics, 1, std::numeric_limits<int>::max());
#include "glint/core/text.h"
    integration.samples = static_cast<int>(samples.value_or(1));
#include "glint/core/text.h"
    if (samples && *samples > 1) {
#include "glint/core/text.h"
        diagnostics.warning(node.child("samples")->where(),
#include "glint/core/text.h"
                            "samples " + std::to_string(*samples) +
#include "glint/core/text.h"
                                ": DIRSIG5-style sampling ignores the DIRSIG4 temporal sample "
#include "glint/core/text.h"
                                "count and spreads ray times uniformly over the integration "
#include "glint/core/text.h"
                                "time");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    return integration;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
model::DetectorModel read_detector_model(const io::XmlNode& node, Diagnostics& diagnostics) {
#include "glint/core/text.h"
    model::DetectorModel detector;
#include "glint/core/text.h"
    detector.where = node.where();
#include "glint/core/text.h"
    node.warn_unknown_children({"quantumefficiency", "readnoise", "darkcurrentdensity",
#include "glint/core/text.h"
                                "minelectrons", "maxelectrons", "bitdepth"},
#include "glint/core/text.h"
                               diagnostics);
#include "glint/core/text.h"
    const auto non_negative = io::NumberRule::non_negative();
#include "glint/core/text.h"
    detector.quantum_efficiency =
#include "glint/core/text.h"
        node.required_double("quantumefficiency", diagnostics, io::NumberRule::fraction())
#include "glint/core/text.h"
            .value_or(1.0);
#include "glint/core/text.h"
    detector.read_noise_e =
#include "glint/core/text.h"
        node.optional_double("readnoise", diagnostics, non_negative).value_or(0);
#include "glint/core/text.h"
    detector.dark_current_density_a_per_m2 =
#include "glint/core/text.h"
        node.optional_double("darkcurrentdensity", diagnostics, non_negative).value_or(0.0);
#include "glint/core/text.h"
    const auto min_e = node.required_double("minelectrons", diagnostics, non_negative);
#include "glint/core/text.h"
    const auto max_e = node.required_double("maxelectrons", diagnostics, non_negative);
#include "glint/core/text.h"
    if (min_e) detector.min_electrons = *min_e;
#include "glint/core/text.h"
    if (max_e) detector.max_electrons = *max_e;
#include "glint/core/text.h"
    if (min_e && max_e && !(*min_e < *max_e)) {
#include "glint/core/text.h"
        diagnostics.error(node.child("maxelectrons")->where(),
#include "glint/core/text.h"
                          "minelectrons (" + number_text(*min_e) +
#include "glint/core/text.h"
                              ") must be less than maxelectrons (" + number_text(*max_e) + ")");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    const auto bits = node.required_int("bitdepth", diagnostics, 1, 32);
#include "glint/core/text.h"
    if (bits) detector.bit_depth = static_cast<int>(*bits);
#include "glint/core/text.h"
    return detector;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
model::Convergence read_convergence(const io::XmlNode& node, Diagnostics& diagnostics) {
#include "glint/core/text.h"
    model::Convergence convergence;
#include "glint/core/text.h"
    convergence.where = node.where();
#include "glint/core/text.h"
    node.warn_unknown_children({"minimumsamples", "maximumsamples", "threshold"}, diagnostics);
#include "glint/core/text.h"
    const auto minimum = node.required_int("minimumsamples", diagnostics, 1, kMaxPathsPerPixel);
#include "glint/core/text.h"
    const auto maximum = node.required_int("maximumsamples", diagnostics, 1, kMaxPathsPerPixel);
#include "glint/core/text.h"
    if (minimum) convergence.minimum_samples = *minimum;
#include "glint/core/text.h"
    if (maximum) convergence.maximum_samples = *maximum;
#include "glint/core/text.h"
    if (minimum && maximum && *maximum < *minimum) {
#include "glint/core/text.h"
        diagnostics.error(node.child("maximumsamples")->where(),
#include "glint/core/text.h"
                          "maximumsamples (" + std::to_string(*maximum) +
#include "glint/core/text.h"
                              ") is below minimumsamples (" + std::to_string(*minimum) +
#include "glint/core/text.h"
                              "), expected maximumsamples >= minimumsamples");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    convergence.threshold =
#include "glint/core/text.h"
        node.required_double("threshold", diagnostics, io::NumberRule::non_negative())
#include "glint/core/text.h"
            .value_or(0.0);
#include "glint/core/text.h"
    return convergence;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
model::Psf read_psf(const io::XmlNode& node, const ReadContext& context, Diagnostics& diagnostics) {
#include "glint/core/text.h"
    model::Psf psf;
#include "glint/core/text.h"
    psf.where = node.where();
#include "glint/core/text.h"
    node.warn_unknown_children({"width", "image", "scale"}, diagnostics);
#include "glint/core/text.h"
    const bool has_width = node.child("width").has_value();
#include "glint/core/text.h"
    const bool has_image = node.child("image").has_value();
#include "glint/core/text.h"
    const bool has_scale = node.child("scale").has_value();
#include "glint/core/text.h"
    const std::string either =
#include "glint/core/text.h"
        "expected either <width> (Gaussian σ in pixels) or <image> with <scale> (its extent in "
#include "glint/core/text.h"
        "pixels)";
#include "glint/core/text.h"
    if (has_width && (has_image || has_scale)) {
#include "glint/core/text.h"
        diagnostics.error(node.where(), "both <width> and <image>/<scale> given, " + either);
#include "glint/core/text.h"
        return psf;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (!has_width && !has_image && !has_scale) {
#include "glint/core/text.h"
        diagnostics.error(node.where(), "neither <width> nor <image> given, " + either);
#include "glint/core/text.h"
        return psf;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (has_width) {
#include "glint/core/text.h"
        psf.width_px = node.optional_double("width", diagnostics, io::NumberRule::positive());
#include "glint/core/text.h"
        return psf;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (!has_scale) {
#include "glint/core/text.h"
        diagnostics.error(node.where(),
#include "glint/core/text.h"
                          "missing required element <scale>: an <image> PSF needs its extent in "
#include "glint/core/text.h"
                          "pixels");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    psf.image = read_file_ref(node, "image", context, diagnostics);
#include "glint/core/text.h"
    if (has_scale) {
#include "glint/core/text.h"
        psf.scale_px =
#include "glint/core/text.h"
            node.optional_double("scale", diagnostics, io::NumberRule::positive()).value_or(0.0);
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    return psf;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
model::ProcessingTask read_processing_task(const io::XmlNode& node, Diagnostics& diagnostics) {
#include "glint/core/text.h"
    model::ProcessingTask task;
#include "glint/core/text.h"
    task.where = node.where();
#include "glint/core/text.h"
    node.warn_unknown_children({"message", "program", "argument", "removefile"}, diagnostics);
#include "glint/core/text.h"
    if (required_attribute(node, "schedule", diagnostics)) {
#include "glint/core/text.h"
        const auto schedule =
#include "glint/core/text.h"
            node.attribute_enum("schedule",
#include "glint/core/text.h"
                                {"collection_started", "task_started", "capture_started",
#include "glint/core/text.h"
                                 "capture_completed", "task_completed", "collection_completed"},
#include "glint/core/text.h"
                                diagnostics);
#include "glint/core/text.h"
        using S = model::ProcessingSchedule;
#include "glint/core/text.h"
        if (schedule == "collection_started") task.schedule = S::collection_started;
#include "glint/core/text.h"
        if (schedule == "task_started") task.schedule = S::task_started;
#include "glint/core/text.h"
        if (schedule == "capture_started") task.schedule = S::capture_started;
#include "glint/core/text.h"
        if (schedule == "capture_completed") task.schedule = S::capture_completed;
#include "glint/core/text.h"
        if (schedule == "task_completed") task.schedule = S::task_completed;
#include "glint/core/text.h"
        if (schedule == "collection_completed") task.schedule = S::collection_completed;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    task.message = node.optional_text("message").value_or("");
#include "glint/core/text.h"
    if (!node.child("program")) {
#include "glint/core/text.h"
        diagnostics.error(node.where(), "missing required element <program>");
#include "glint/core/text.h"
    } else {
#include "glint/core/text.h"
        task.program = non_empty_text(node, "program", "the name or path of a program", diagnostics)
#include "glint/core/text.h"
                           .value_or("");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    for (const auto& argument : node.children("argument")) {
#include "glint/core/text.h"
        std::string text = argument.text();
#include "glint/core/text.h"
        const bool blank = std::any_of(text.begin(), text.end(), [](char c) {
#include "glint/core/text.h"
            return std::isspace(static_cast<unsigned char>(c)) != 0;
#include "glint/core/text.h"
        });
#include "glint/core/text.h"
        if (blank) {
#include "glint/core/text.h"
            diagnostics.error(argument.where(),
#include "glint/core/text.h"
                              "argument '" + text +
#include "glint/core/text.h"
                                  "' contains whitespace, expected a single argument without "
#include "glint/core/text.h"
                                  "whitespace (split it into several <argument> elements)");
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
        task.arguments.push_back(std::move(text));
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    task.remove_file = node.optional_bool("removefile", diagnostics).value_or(false);
#include "glint/core/text.h"
    return task;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
std::vector<model::ProcessingTask> read_processing(const io::XmlNode& node,
#include "glint/core/text.h"
                                                   Diagnostics& diagnostics) {
#include "glint/core/text.h"
    node.warn_unknown_children({"task"}, diagnostics);
#include "glint/core/text.h"
    std::vector<model::ProcessingTask> tasks;
#include "glint/core/text.h"
    for (const auto& task : node.children("task")) {
#include "glint/core/text.h"
        tasks.push_back(read_processing_task(task, diagnostics));
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    return tasks;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
/// The error for an extra given both in `<capturemethod>` and in `<focalplane>`.
#include "glint/core/text.h"
void report_twice(const io::XmlNode& node, const ErrorContext& first, Diagnostics& diagnostics) {
#include "glint/core/text.h"
    diagnostics.error(node.where(), "<" + node.name() +
#include "glint/core/text.h"
                                        "> is given both in <capturemethod> (line " +
#include "glint/core/text.h"
                                        std::to_string(first.line) +
#include "glint/core/text.h"
                                        ") and in <focalplane>, expected one of the two");
#include "glint/core/text.h"
}
#include "glint/core/text.h"
/// Reads psf, activearea, convergence, processing and detectormodel under `parent` into
#include "glint/core/text.h"
/// `capture`. `in_focal_plane`: `parent` is the focal plane, and what the capture method
#include "glint/core/text.h"
/// already holds must not be given again.
#include "glint/core/text.h"
void read_extras(const io::XmlNode& parent, model::CaptureMethod& capture,
#include "glint/core/text.h"
                 const ReadContext& context, Diagnostics& diagnostics, bool in_focal_plane) {
#include "glint/core/text.h"
    if (const auto node = single_child(parent, "detectormodel", diagnostics)) {
#include "glint/core/text.h"
        if (in_focal_plane && capture.detector_model) {
#include "glint/core/text.h"
            report_twice(*node, capture.detector_model->where, diagnostics);
#include "glint/core/text.h"
        } else {
#include "glint/core/text.h"
            capture.detector_model = read_detector_model(*node, diagnostics);
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (const auto node = single_child(parent, "convergence", diagnostics)) {
#include "glint/core/text.h"
        if (in_focal_plane && capture.convergence) {
#include "glint/core/text.h"
            report_twice(*node, capture.convergence->where, diagnostics);
#include "glint/core/text.h"
        } else {
#include "glint/core/text.h"
            capture.convergence = read_convergence(*node, diagnostics);
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (const auto node = single_child(parent, "psf", diagnostics)) {
#include "glint/core/text.h"
        if (in_focal_plane && capture.psf) {
#include "glint/core/text.h"
            report_twice(*node, capture.psf->where, diagnostics);
#include "glint/core/text.h"
        } else {
#include "glint/core/text.h"
            capture.psf = read_psf(*node, context, diagnostics);
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (const auto node = single_child(parent, "activearea", diagnostics)) {
#include "glint/core/text.h"
        if (in_focal_plane && !capture.active_area_image.empty()) {
#include "glint/core/text.h"
            report_twice(*node, capture.active_area_image.where, diagnostics);
#include "glint/core/text.h"
        } else {
#include "glint/core/text.h"
            node->warn_unknown_children({"image"}, diagnostics);
#include "glint/core/text.h"
            capture.active_area_image = read_file_ref(*node, "image", context, diagnostics);
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (const auto node = single_child(parent, "processing", diagnostics)) {
#include "glint/core/text.h"
        if (in_focal_plane && !capture.processing.empty()) {
#include "glint/core/text.h"
            report_twice(*node, capture.processing.front().where, diagnostics);
#include "glint/core/text.h"
        } else {
#include "glint/core/text.h"
            capture.processing = read_processing(*node, diagnostics);
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
}
#include "glint/core/text.h"
}  // namespace
#include "glint/core/text.h"
model::ImageFile read_image_file(const io::XmlNode& node, bool radiometric,
#include "glint/core/text.h"
                                 Diagnostics& diagnostics) {
#include "glint/core/text.h"
    model::ImageFile file;
#include "glint/core/text.h"
    file.where = node.where();
#include "glint/core/text.h"
    node.warn_unknown_children({"basename", "extension", "schedule", "datatype"}, diagnostics);
#include "glint/core/text.h"
    if (radiometric) {
#include "glint/core/text.h"
        const auto area = node.attribute_enum("areaunits", {"cm2", "m2"}, diagnostics);
#include "glint/core/text.h"
        if (area == "m2") file.area_units = model::AreaUnits::m2;
#include "glint/core/text.h"
        const auto flux = node.attribute_enum(
#include "glint/core/text.h"
            "fluxunits",
#include "glint/core/text.h"
            {"watts", "milliwatts", "microwatts", "photonspersecond", "electronspersecond"},
#include "glint/core/text.h"
            diagnostics);
#include "glint/core/text.h"
        using F = model::FluxUnits;
#include "glint/core/text.h"
        if (flux == "milliwatts") file.flux_units = F::milliwatts;
#include "glint/core/text.h"
        if (flux == "microwatts") file.flux_units = F::microwatts;
#include "glint/core/text.h"
        if (flux == "photonspersecond") file.flux_units = F::photons_per_second;
#include "glint/core/text.h"
        if (flux == "electronspersecond") file.flux_units = F::electrons_per_second;
#include "glint/core/text.h"
    } else {
#include "glint/core/text.h"
        for (const char* attribute : {"areaunits", "fluxunits"}) {
#include "glint/core/text.h"
            if (node.attribute(attribute)) {
#include "glint/core/text.h"
                diagnostics.warning(
#include "glint/core/text.h"
                    node.where_attribute(attribute),
#include "glint/core/text.h"
                    std::string(attribute) + " does not apply to a truth image and is ignored");
#include "glint/core/text.h"
            }
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (!node.child("basename")) {
#include "glint/core/text.h"
        diagnostics.error(node.where(), "missing required element <basename>");
#include "glint/core/text.h"
    } else {
#include "glint/core/text.h"
        file.basename = non_empty_text(node, "basename", "a file name", diagnostics).value_or("");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (node.child("extension")) {
#include "glint/core/text.h"
        file.extension =
#include "glint/core/text.h"
            non_empty_text(node, "extension", "a file extension such as img", diagnostics)
#include "glint/core/text.h"
                .value_or("img");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    const auto schedule =
#include "glint/core/text.h"
        node.optional_enum("schedule", {"simulation", "task", "capture"}, diagnostics);
#include "glint/core/text.h"
    if (schedule == "task") file.schedule = model::ImageSchedule::task;
#include "glint/core/text.h"
    if (schedule == "capture") file.schedule = model::ImageSchedule::capture;
#include "glint/core/text.h"
    const auto datatype =
#include "glint/core/text.h"
        node.optional_int("datatype", diagnostics, std::numeric_limits<std::int64_t>::min(),
#include "glint/core/text.h"
                          std::numeric_limits<std::int64_t>::max());
#include "glint/core/text.h"
    if (datatype) {
#include "glint/core/text.h"
        if (std::find(std::begin(kEnviDataTypes), std::end(kEnviDataTypes), *datatype) ==
#include "glint/core/text.h"
            std::end(kEnviDataTypes)) {
#include "glint/core/text.h"
            diagnostics.error(node.child("datatype")->where(),
#include "glint/core/text.h"
                              "datatype " + std::to_string(*datatype) +
#include "glint/core/text.h"
                                  " is not a supported ENVI data type, expected 1, 2, 3, 4, 5, "
#include "glint/core/text.h"
                                  "12, 13, 14 or 15");
#include "glint/core/text.h"
        } else {
#include "glint/core/text.h"
            file.datatype = static_cast<int>(*datatype);
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    return file;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
model::CaptureMethod read_capture_method(const io::XmlNode& node, const ReadContext& context,
#include "glint/core/text.h"
                                         Diagnostics& diagnostics) {
#include "glint/core/text.h"
    model::CaptureMethod capture;
#include "glint/core/text.h"
    capture.where = node.where();
#include "glint/core/text.h"
    node.warn_unknown_children(
#include "glint/core/text.h"
        {"samplestrategy", "imagefile", "spectralresponse", "spatialresponse",
#include "glint/core/text.h"
         "temporalintegration", "detectormodel", "convergence", "psf", "activearea", "processing"},
#include "glint/core/text.h"
        diagnostics);
#include "glint/core/text.h"
    const auto type = node.attribute_enum("type", {"simple", "raw", "lidar"}, diagnostics);
#include "glint/core/text.h"
    if (type == "raw") capture.type = model::CaptureMethodType::raw;
#include "glint/core/text.h"
    if (type == "lidar") capture.type = model::CaptureMethodType::lidar;
#include "glint/core/text.h"
    capture.name = trim(node.attribute("name").value_or(""));
#include "glint/core/text.h"
    const bool passive = capture.type != model::CaptureMethodType::lidar;
#include "glint/core/text.h"
    if (const auto strategy = single_child(node, "samplestrategy", diagnostics)) {
#include "glint/core/text.h"
        capture.sample_strategy = read_sample_strategy(*strategy, diagnostics);
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (const auto file = single_child(node, "imagefile", diagnostics)) {
#include "glint/core/text.h"
        capture.image_file = read_image_file(*file, true, diagnostics);
#include "glint/core/text.h"
    } else if (passive) {
#include "glint/core/text.h"
        diagnostics.error(node.where(), "missing required element <imagefile>");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (const auto response = single_child(node, "spectralresponse", diagnostics)) {
#include "glint/core/text.h"
        capture.spectral_response = capture_io::read_spectral_response(
#include "glint/core/text.h"
            *response, capture.type == model::CaptureMethodType::simple, diagnostics);
#include "glint/core/text.h"
    } else if (passive) {
#include "glint/core/text.h"
        diagnostics.error(node.where(), "missing required element <spectralresponse>");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (const auto spatial = single_child(node, "spatialresponse", diagnostics)) {
#include "glint/core/text.h"
        capture.spatial_response = read_spatial_response(*spatial, diagnostics);
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (const auto temporal = single_child(node, "temporalintegration", diagnostics)) {
#include "glint/core/text.h"
        capture.temporal_integration = read_temporal_integration(*temporal, diagnostics);
#include "glint/core/text.h"
    } else {
#include "glint/core/text.h"
        capture.temporal_integration.where = capture.where;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    read_extras(node, capture, context, diagnostics, false);
#include "glint/core/text.h"
    return capture;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
void read_focal_plane_extras(const io::XmlNode& focal_plane, model::CaptureMethod& capture,
#include "glint/core/text.h"
                             const ReadContext& context, Diagnostics& diagnostics) {
#include "glint/core/text.h"
    read_extras(focal_plane, capture, context, diagnostics, true);
#include "glint/core/text.h"
}
#include "glint/core/text.h"
void check_focal_plane(const model::FocalPlane& focal_plane, Diagnostics& diagnostics) {
#include "glint/core/text.h"
    const auto& capture = focal_plane.capture_method;
#include "glint/core/text.h"
    capture_io::check_spectral_response(capture.spectral_response, capture.type, diagnostics);
#include "glint/core/text.h"
    const auto& integration = capture.temporal_integration;
#include "glint/core/text.h"
    if (integration.tdi) {
#include "glint/core/text.h"
        if (!(integration.time_s > 0.0)) {
#include "glint/core/text.h"
            diagnostics.error(integration.where,
#include "glint/core/text.h"
                              "tdi=\"true\" needs an integration time, expected <time> > 0");
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
        const std::size_t stages = focal_plane.detector_array.y_count;
#include "glint/core/text.h"
        if (stages == 1) {
#include "glint/core/text.h"
            diagnostics.error(integration.where,
#include "glint/core/text.h"
                              "tdi=\"true\" uses the array's rows as TDI stages, expected "
#include "glint/core/text.h"
                              "<yelementcount> > 1 in <detectorarray> (it is 1)");
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (capture.detector_model && capture.type != model::CaptureMethodType::simple) {
#include "glint/core/text.h"
        diagnostics.error(capture.detector_model->where,
#include "glint/core/text.h"
                          std::string("the detector model needs capturemethod type simple, "
#include "glint/core/text.h"
                                      "expected no <detectormodel> in a ") +
#include "glint/core/text.h"
                              (capture.type == model::CaptureMethodType::raw ? "raw" : "lidar") +
#include "glint/core/text.h"
                              " capture");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    const auto& file = capture.image_file;
#include "glint/core/text.h"
    if (capture.detector_model &&
#include "glint/core/text.h"
        (file.area_units != model::AreaUnits::cm2 || file.flux_units != model::FluxUnits::watts)) {
#include "glint/core/text.h"
        diagnostics.warning(file.where,
#include "glint/core/text.h"
                            "areaunits and fluxunits are ignored when the detector model is "
#include "glint/core/text.h"
                            "enabled (the output is in digital counts)");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
}
#include "glint/core/text.h"
}  // namespace glint::dirsig::detail
