// SPDX-License-Identifier: Apache-2.0
// The capture extras of a `.platform` focal plane, which the BasicPlatform manual places either
// in <capturemethod> or directly in <focalplane> (platform_parts.h): <detectormodel>,
// <convergence>, <psf>, <activearea> and <processing>.
#include <cmath>
#include <cstdint>
#include <string>

#include "glint/core/text.h"
#include "platform_parts.h"
#include "spectral_reader.h"

namespace glint::dirsig::detail {
namespace {

using capture_io::non_empty_text;
using capture_io::required_attribute;
using capture_io::single_child;

/// The most paths per pixel a convergence setting may ask for.
constexpr std::int64_t kMaxPathsPerPixel = 1'000'000'000;

/// A file named by child `name` (required), resolved against the platform file's folder.
model::FileRef read_file_ref(const io::XmlNode& node, std::string_view name,
                             const ReadContext& context, Diagnostics& diagnostics) {
    const auto child = node.child(name);
    if (!child) {
        diagnostics.error(node.where(), "missing required element <" + std::string(name) + ">");
        return {};
    }
    const auto text = non_empty_text(node, name, "a file name", diagnostics);
    if (!text) return {};
    return context.options.paths.resolve(*text, context.base_dir, child->where(), diagnostics);
}

/// `<detectormodel>`; for a lidar capture (`lidar`), which applies the QE alone, the ADC's
/// elements are optional.
model::DetectorModel read_detector_model(const io::XmlNode& node, bool lidar,
                                         Diagnostics& diagnostics) {
    model::DetectorModel detector;
    detector.where = node.where();
    node.warn_unknown_children({"quantumefficiency", "readnoise", "darkcurrentdensity",
                                "minelectrons", "maxelectrons", "bitdepth"},
                               diagnostics);
    if (lidar) {
        for (const char* element :
             {"readnoise", "darkcurrentdensity", "minelectrons", "maxelectrons", "bitdepth"}) {
            if (node.child(element)) {
                diagnostics.warning(node.where(),
                                    "a lidar capture applies only the detector model's "
                                    "<quantumefficiency> (its BIN file holds detected photons): "
                                    "the read noise, dark current and ADC are read, not applied");
                break;
            }
        }
    }
    const auto non_negative = io::NumberRule::non_negative();
    detector.quantum_efficiency =
        node.required_double("quantumefficiency", diagnostics, io::NumberRule::fraction())
            .value_or(1.0);
    detector.read_noise_e =
        node.optional_double("readnoise", diagnostics, non_negative).value_or(0);
    detector.dark_current_density_a_per_m2 =
        node.optional_double("darkcurrentdensity", diagnostics, non_negative).value_or(0.0);
    const auto min_e = lidar ? node.optional_double("minelectrons", diagnostics, non_negative)
                             : node.required_double("minelectrons", diagnostics, non_negative);
    const auto max_e = lidar ? node.optional_double("maxelectrons", diagnostics, non_negative)
                             : node.required_double("maxelectrons", diagnostics, non_negative);
    if (min_e) detector.min_electrons = *min_e;
    if (max_e) detector.max_electrons = *max_e;
    if (min_e && max_e && !(*min_e < *max_e)) {
        diagnostics.error(node.child("maxelectrons")->where(),
                          "minelectrons (" + format_ten_digits(*min_e) +
                              ") must be less than maxelectrons (" + format_ten_digits(*max_e) + ")");
    }
    const auto bits = lidar ? node.optional_int("bitdepth", diagnostics, 1, 32)
                            : node.required_int("bitdepth", diagnostics, 1, 32);
    if (bits) detector.bit_depth = static_cast<int>(*bits);
    return detector;
}

model::Convergence read_convergence(const io::XmlNode& node, Diagnostics& diagnostics) {
    model::Convergence convergence;
    convergence.where = node.where();
    node.warn_unknown_children({"minimumsamples", "maximumsamples", "threshold"}, diagnostics);
    const auto minimum = node.required_int("minimumsamples", diagnostics, 1, kMaxPathsPerPixel);
    const auto maximum = node.required_int("maximumsamples", diagnostics, 1, kMaxPathsPerPixel);
    if (minimum) convergence.minimum_samples = *minimum;
    if (maximum) convergence.maximum_samples = *maximum;
    if (minimum && maximum && *maximum < *minimum) {
        diagnostics.error(node.child("maximumsamples")->where(),
                          "maximumsamples (" + std::to_string(*maximum) +
                              ") is below minimumsamples (" + std::to_string(*minimum) +
                              "), expected maximumsamples >= minimumsamples");
    }
    convergence.threshold =
        node.required_double("threshold", diagnostics, io::NumberRule::non_negative())
            .value_or(0.0);
    return convergence;
}

model::Psf read_psf(const io::XmlNode& node, const ReadContext& context, Diagnostics& diagnostics) {
    model::Psf psf;
    psf.where = node.where();
    node.warn_unknown_children({"width", "image", "scale"}, diagnostics);
    const bool has_width = node.child("width").has_value();
    const bool has_image = node.child("image").has_value();
    const bool has_scale = node.child("scale").has_value();
    const std::string either =
        "expected either <width> (Gaussian σ in pixels) or <image> with <scale> (its extent in "
        "pixels)";
    if (has_width && (has_image || has_scale)) {
        diagnostics.error(node.where(), "both <width> and <image>/<scale> given, " + either);
        return psf;
    }
    if (!has_width && !has_image && !has_scale) {
        diagnostics.error(node.where(), "neither <width> nor <image> given, " + either);
        return psf;
    }
    if (has_width) {
        psf.width_px = node.optional_double("width", diagnostics, io::NumberRule::positive());
        return psf;
    }
    if (!has_scale) {
        diagnostics.error(node.where(),
                          "missing required element <scale>: an <image> PSF needs its extent in "
                          "pixels");
    }
    psf.image = read_file_ref(node, "image", context, diagnostics);
    if (has_scale) {
        psf.scale_px =
            node.optional_double("scale", diagnostics, io::NumberRule::positive()).value_or(0.0);
    }
    return psf;
}

model::ProcessingTask read_processing_task(const io::XmlNode& node, Diagnostics& diagnostics) {
    model::ProcessingTask task;
    task.where = node.where();
    node.warn_unknown_children({"message", "program", "argument", "removefile"}, diagnostics);
    if (required_attribute(node, "schedule", diagnostics)) {
        const auto schedule =
            node.attribute_enum("schedule",
                                {"collection_started", "task_started", "capture_started",
                                 "capture_completed", "task_completed", "collection_completed"},
                                diagnostics);
        using S = model::ProcessingSchedule;
        if (schedule == "collection_started") task.schedule = S::collection_started;
        if (schedule == "task_started") task.schedule = S::task_started;
        if (schedule == "capture_started") task.schedule = S::capture_started;
        if (schedule == "capture_completed") task.schedule = S::capture_completed;
        if (schedule == "task_completed") task.schedule = S::task_completed;
        if (schedule == "collection_completed") task.schedule = S::collection_completed;
    }
    task.message = node.optional_text("message").value_or("");
    if (!node.child("program")) {
        diagnostics.error(node.where(), "missing required element <program>");
    } else {
        task.program = non_empty_text(node, "program", "the name or path of a program", diagnostics)
                           .value_or("");
    }
    for (const auto& argument : node.children("argument")) {
        std::string text = argument.text();
        const bool blank = std::any_of(text.begin(), text.end(), [](char c) {
            return std::isspace(static_cast<unsigned char>(c)) != 0;
        });
        if (blank) {
            diagnostics.error(argument.where(),
                              "argument '" + text +
                                  "' contains whitespace, expected a single argument without "
                                  "whitespace (split it into several <argument> elements)");
        }
        task.arguments.push_back(std::move(text));
    }
    task.remove_file = node.optional_bool("removefile", diagnostics).value_or(false);
    return task;
}

std::vector<model::ProcessingTask> read_processing(const io::XmlNode& node,
                                                   Diagnostics& diagnostics) {
    node.warn_unknown_children({"task"}, diagnostics);
    std::vector<model::ProcessingTask> tasks;
    for (const auto& task : node.children("task")) {
        tasks.push_back(read_processing_task(task, diagnostics));
    }
    return tasks;
}

/// The error for an extra given both in `<capturemethod>` and in `<focalplane>`.
void report_twice(const io::XmlNode& node, const ErrorContext& first, Diagnostics& diagnostics) {
    diagnostics.error(node.where(), "<" + node.name() +
                                        "> is given both in <capturemethod> (line " +
                                        std::to_string(first.line) +
                                        ") and in <focalplane>, expected one of the two");
}

}  // namespace

void read_capture_extras(const io::XmlNode& parent, model::CaptureMethod& capture,
                         const ReadContext& context, Diagnostics& diagnostics,
                         bool in_focal_plane) {
    if (const auto node = single_child(parent, "detectormodel", diagnostics)) {
        if (in_focal_plane && capture.detector_model) {
            report_twice(*node, capture.detector_model->where, diagnostics);
        } else {
            capture.detector_model = read_detector_model(
                *node, capture.type == model::CaptureMethodType::lidar, diagnostics);
        }
    }
    if (const auto node = single_child(parent, "convergence", diagnostics)) {
        if (in_focal_plane && capture.convergence) {
            report_twice(*node, capture.convergence->where, diagnostics);
        } else {
            capture.convergence = read_convergence(*node, diagnostics);
        }
    }
    if (const auto node = single_child(parent, "psf", diagnostics)) {
        if (in_focal_plane && capture.psf) {
            report_twice(*node, capture.psf->where, diagnostics);
        } else {
            capture.psf = read_psf(*node, context, diagnostics);
        }
    }
    if (const auto node = single_child(parent, "activearea", diagnostics)) {
        if (in_focal_plane && !capture.active_area_image.empty()) {
            report_twice(*node, capture.active_area_image.where, diagnostics);
        } else {
            node->warn_unknown_children({"image"}, diagnostics);
            capture.active_area_image = read_file_ref(*node, "image", context, diagnostics);
        }
    }
    if (const auto node = single_child(parent, "processing", diagnostics)) {
        if (in_focal_plane && !capture.processing.empty()) {
            report_twice(*node, capture.processing.front().where, diagnostics);
        } else {
            capture.processing = read_processing(*node, diagnostics);
        }
    }
}

void read_focal_plane_extras(const io::XmlNode& focal_plane, model::CaptureMethod& capture,
                             const ReadContext& context, Diagnostics& diagnostics) {
    read_capture_extras(focal_plane, capture, context, diagnostics, true);
}

}  // namespace glint::dirsig::detail
