// SPDX-License-Identifier: Apache-2.0
// The capture-method half of the `.platform` reader: `<capturemethod>` and its children
// (sample strategy, image file, spatial response, temporal integration, detector model,
// convergence, PSF, active area, processing tasks), the same extras written directly in
// `<focalplane>`, and the checks that need the whole focal plane. The spectral response is
// read by spectral_reader.cpp. Every problem goes to Diagnostics with its location.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "glint/core/text.h"
#include "glint/model/output_name.h"
#include "platform_parts.h"
#include "spectral_reader.h"

namespace glint::dirsig::detail {
namespace {

using capture_io::number_text;
using capture_io::required_attribute;
using capture_io::single_child;
using capture_io::trim;

/// The most paths per pixel a convergence setting may ask for.
constexpr std::int64_t kMaxPathsPerPixel = 1'000'000'000;

/// ENVI data types an image file may be written as.
constexpr int kEnviDataTypes[] = {1, 2, 3, 4, 5, 12, 13, 14, 15};

/// A whole number >= 1 in attribute `name`; nullopt when absent or invalid (invalid: error).
std::optional<int> attribute_count(const io::XmlNode& node, std::string_view name,
                                   Diagnostics& diagnostics) {
    const auto value = node.attribute_double(name, diagnostics, io::NumberRule{1.0, 1e9});
    if (!value) return std::nullopt;
    if (*value != std::floor(*value)) {
        diagnostics.error(node.where_attribute(name), std::string(name) + " " +
                                                          number_text(*value) +
                                                          " is invalid, expected an integer >= 1");
        return std::nullopt;
    }
    return static_cast<int>(*value);
}

/// Text of child `name` that must not be empty when given.
std::optional<std::string> non_empty_text(const io::XmlNode& node, std::string_view name,
                                          std::string_view expected, Diagnostics& diagnostics) {
    const auto child = node.child(name);
    if (!child) return std::nullopt;
    std::string text = child->text();
    if (text.empty()) {
        diagnostics.error(child->where(),
                          std::string(name) + " is empty, expected " + std::string(expected));
        return std::nullopt;
    }
    return text;
}

/// Child `name` as a part of an output file name: non-empty, and nothing that could leave
/// the output folder (model::output_name_problem); "" after an error.
std::string output_name_part(const io::XmlNode& node, std::string_view name,
                             std::string_view expected, Diagnostics& diagnostics) {
    std::string text = non_empty_text(node, name, expected, diagnostics).value_or("");
    if (const auto problem = model::output_name_problem(text)) {
        diagnostics.error(node.child(name)->where(),
                          "<" + std::string(name) + "> " + quote(text) + " " + *problem);
        return "";
    }
    return text;
}

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

model::SampleStrategy read_sample_strategy(const io::XmlNode& node, Diagnostics& diagnostics) {
    model::SampleStrategy strategy;
    node.warn_unknown_children({"hypersamplingmultiplier"}, diagnostics);
    const std::string type = trim(node.attribute("type").value_or("central"));
    if (!type.empty()) strategy.type = type;
    if (!type.empty() && type != "central") {
        diagnostics.warning(node.where_attribute("type"),
                            "samplestrategy type \"" + type +
                                "\" is read, not applied: glint spreads each pixel's samples "
                                "uniformly over its area (as for central)");
    }
    strategy.hypersampling_multiplier =
        node.optional_double("hypersamplingmultiplier", diagnostics, io::NumberRule{1.0, {}})
            .value_or(1.0);
    return strategy;
}

model::SpatialResponse read_spatial_response(const io::XmlNode& node, Diagnostics& diagnostics) {
    model::SpatialResponse response;
    response.where = node.where();
    node.warn_unknown_children({"entry"}, diagnostics);
    response.spatial_sampling = trim(node.attribute("spatialsampling").value_or(""));
    response.spectral_units = trim(node.attribute("spectralunits").value_or(""));
    response.x_sub_elements = attribute_count(node, "xsubelements", diagnostics).value_or(1);
    response.y_sub_elements = attribute_count(node, "ysubelements", diagnostics).value_or(1);
    for (const auto& entry_node : node.children("entry")) {
        entry_node.warn_unknown_children({"spectralpoint", "xwidth", "ywidth", "totalweight"},
                                         diagnostics);
        model::SpatialResponseEntry entry;
        entry.where = entry_node.where();
        entry.type = trim(entry_node.attribute("type").value_or(""));
        const auto non_negative = io::NumberRule::non_negative();
        entry.spectral_point = entry_node.optional_double("spectralpoint", diagnostics).value_or(0);
        entry.x_width = entry_node.optional_double("xwidth", diagnostics, non_negative).value_or(1);
        entry.y_width = entry_node.optional_double("ywidth", diagnostics, non_negative).value_or(1);
        entry.total_weight =
            entry_node.optional_double("totalweight", diagnostics, non_negative).value_or(1);
        response.entries.push_back(std::move(entry));
    }
    diagnostics.warning(node.where(),
                        "<spatialresponse> is a DIRSIG4 setting; glint samples pixel areas as "
                        "DIRSIG5 does and ignores it");
    return response;
}

model::TemporalIntegration read_temporal_integration(const io::XmlNode& node,
                                                     Diagnostics& diagnostics) {
    model::TemporalIntegration integration;
    integration.where = node.where();
    node.warn_unknown_children({"time", "samples"}, diagnostics);
    integration.tdi = node.attribute_bool("tdi", diagnostics).value_or(false);
    integration.time_s =
        node.optional_double("time", diagnostics, io::NumberRule::non_negative()).value_or(0.0);
    const auto samples =
        node.optional_int("samples", diagnostics, 1, std::numeric_limits<int>::max());
    integration.samples = static_cast<int>(samples.value_or(1));
    if (samples && *samples > 1) {
        diagnostics.warning(node.child("samples")->where(),
                            "samples " + std::to_string(*samples) +
                                ": DIRSIG5-style sampling ignores the DIRSIG4 temporal sample "
                                "count and spreads ray times uniformly over the integration "
                                "time");
    }
    return integration;
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
                          "minelectrons (" + number_text(*min_e) +
                              ") must be less than maxelectrons (" + number_text(*max_e) + ")");
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

/// Reads psf, activearea, convergence, processing and detectormodel under `parent` into
/// `capture`. `in_focal_plane`: `parent` is the focal plane, and what the capture method
/// already holds must not be given again.
void read_extras(const io::XmlNode& parent, model::CaptureMethod& capture,
                 const ReadContext& context, Diagnostics& diagnostics, bool in_focal_plane) {
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

}  // namespace

model::ImageFile read_image_file(const io::XmlNode& node, bool radiometric,
                                 Diagnostics& diagnostics) {
    model::ImageFile file;
    file.where = node.where();
    node.warn_unknown_children({"basename", "extension", "schedule", "datatype"}, diagnostics);
    if (radiometric) {
        const auto area = node.attribute_enum("areaunits", {"cm2", "m2"}, diagnostics);
        if (area == "m2") file.area_units = model::AreaUnits::m2;
        const auto flux = node.attribute_enum(
            "fluxunits",
            {"watts", "milliwatts", "microwatts", "photonspersecond", "electronspersecond"},
            diagnostics);
        using F = model::FluxUnits;
        if (flux == "milliwatts") file.flux_units = F::milliwatts;
        if (flux == "microwatts") file.flux_units = F::microwatts;
        if (flux == "photonspersecond") file.flux_units = F::photons_per_second;
        if (flux == "electronspersecond") file.flux_units = F::electrons_per_second;
    } else {
        for (const char* attribute : {"areaunits", "fluxunits"}) {
            if (node.attribute(attribute)) {
                diagnostics.warning(
                    node.where_attribute(attribute),
                    std::string(attribute) +
                        " does not apply to a truth image or a lidar BIN file and is ignored");
            }
        }
    }
    if (!node.child("basename")) {
        diagnostics.error(node.where(), "missing required element <basename>");
    } else {
        file.basename = output_name_part(node, "basename", "a file name", diagnostics);
    }
    if (node.child("extension")) {
        file.extension =
            output_name_part(node, "extension", "a file extension such as img", diagnostics);
        if (file.extension.empty()) file.extension = "img";
    }
    const auto schedule =
        node.optional_enum("schedule", {"simulation", "task", "capture"}, diagnostics);
    if (schedule == "task") file.schedule = model::ImageSchedule::task;
    if (schedule == "capture") file.schedule = model::ImageSchedule::capture;
    const auto datatype =
        node.optional_int("datatype", diagnostics, std::numeric_limits<std::int64_t>::min(),
                          std::numeric_limits<std::int64_t>::max());
    if (datatype) {
        if (std::find(std::begin(kEnviDataTypes), std::end(kEnviDataTypes), *datatype) ==
            std::end(kEnviDataTypes)) {
            diagnostics.error(node.child("datatype")->where(),
                              "datatype " + std::to_string(*datatype) +
                                  " is not a supported ENVI data type, expected 1, 2, 3, 4, 5, "
                                  "12, 13, 14 or 15");
        } else {
            file.datatype = static_cast<int>(*datatype);
        }
    }
    return file;
}

/// `<signalgate>`: start, stop (s after the pulse), bin width (s), samples per bin.
static model::SignalGate read_signal_gate(const io::XmlNode& node, Diagnostics& diagnostics) {
    model::SignalGate gate;
    gate.where = node.where();
    node.warn_unknown_children({"start", "stop", "binwidth", "samplespertimebin"}, diagnostics);
    const std::size_t errors = diagnostics.error_count();
    const auto start = node.required_double("start", diagnostics, io::NumberRule::non_negative());
    const auto stop = node.required_double("stop", diagnostics, io::NumberRule::positive());
    const auto width = node.required_double("binwidth", diagnostics, io::NumberRule::positive());
    gate.samples_per_bin = static_cast<std::uint32_t>(
        node.optional_int("samplespertimebin", diagnostics, 1, 1024).value_or(1));
    if (diagnostics.error_count() != errors || !start || !stop || !width) return gate;
    gate.start_s = *start;
    gate.stop_s = *stop;
    gate.bin_width_s = *width;
    if (!(*stop > *start)) {
        diagnostics.error(node.child("stop")->where(),
                          "the gate stops at " + format_shortest(*stop) +
                              " s, expected after its start (" + format_shortest(*start) + " s)");
        return gate;
    }
    const double bins = (*stop - *start) / *width;
    if (std::abs(bins - std::round(bins)) > 1e-6 * bins || bins > 1e7) {
        diagnostics.error(node.child("binwidth")->where(),
                          "the " + format_shortest(*stop - *start) + " s gate holds " +
                              format_shortest(bins) + " bins of " + format_shortest(*width) +
                              " s, expected a whole number up to 10^7");
    }
    return gate;
}

model::CaptureMethod read_capture_method(const io::XmlNode& node, const ReadContext& context,
                                         Diagnostics& diagnostics) {
    model::CaptureMethod capture;
    capture.where = node.where();
    node.warn_unknown_children({"samplestrategy", "imagefile", "spectralresponse",
                                "spatialresponse", "temporalintegration", "detectormodel",
                                "convergence", "psf", "activearea", "processing", "signalgate"},
                               diagnostics);
    const auto type = node.attribute_enum("type", {"simple", "raw", "lidar"}, diagnostics);
    if (type == "raw") capture.type = model::CaptureMethodType::raw;
    if (type == "lidar") capture.type = model::CaptureMethodType::lidar;
    capture.name = trim(node.attribute("name").value_or(""));
    const bool passive = capture.type != model::CaptureMethodType::lidar;
    if (const auto gate = single_child(node, "signalgate", diagnostics)) {
        if (passive) {
            diagnostics.warning(gate->where(),
                                "<signalgate> is read only in a lidar capture "
                                "(capturemethod type lidar): ignored");
        } else {
            capture.signal_gate = read_signal_gate(*gate, diagnostics);
        }
    } else if (!passive) {
        diagnostics.error(node.where(),
                          "a lidar capture needs a <signalgate> (the range gate: "
                          "<start>, <stop> and <binwidth> in s after the pulse)");
    }

    if (const auto strategy = single_child(node, "samplestrategy", diagnostics)) {
        capture.sample_strategy = read_sample_strategy(*strategy, diagnostics);
    }
    if (const auto file = single_child(node, "imagefile", diagnostics)) {
        capture.image_file = read_image_file(*file, passive, diagnostics);
        // A lidar capture writes a DIRSIG BIN file: float64 photons, named .bin by default.
        if (!passive) {
            if (!file->child("extension")) capture.image_file.extension = "bin";
            if (const auto datatype = file->child("datatype")) {
                diagnostics.warning(datatype->where(),
                                    "<datatype> does not apply to a lidar capture, whose BIN "
                                    "file holds float64 photons; ignored");
            }
        }
    } else if (passive) {
        diagnostics.error(node.where(), "missing required element <imagefile>");
    } else {
        diagnostics.error(node.where(),
                          "a lidar capture needs an <imagefile> (the <basename> "
                          "of its BIN file)");
    }
    if (const auto response = single_child(node, "spectralresponse", diagnostics)) {
        capture.spectral_response = capture_io::read_spectral_response(
            *response, capture.type == model::CaptureMethodType::simple, diagnostics);
    } else if (passive) {
        diagnostics.error(node.where(), "missing required element <spectralresponse>");
    }
    if (const auto spatial = single_child(node, "spatialresponse", diagnostics)) {
        capture.spatial_response = read_spatial_response(*spatial, diagnostics);
    }
    if (const auto temporal = single_child(node, "temporalintegration", diagnostics)) {
        capture.temporal_integration = read_temporal_integration(*temporal, diagnostics);
    } else {
        capture.temporal_integration.where = capture.where;
    }
    read_extras(node, capture, context, diagnostics, false);
    return capture;
}

void read_focal_plane_extras(const io::XmlNode& focal_plane, model::CaptureMethod& capture,
                             const ReadContext& context, Diagnostics& diagnostics) {
    read_extras(focal_plane, capture, context, diagnostics, true);
}

void check_focal_plane(const model::FocalPlane& focal_plane, Diagnostics& diagnostics) {
    const auto& capture = focal_plane.capture_method;
    capture_io::check_spectral_response(capture.spectral_response, capture.type, diagnostics);

    const auto& integration = capture.temporal_integration;
    if (integration.tdi) {
        if (!(integration.time_s > 0.0)) {
            diagnostics.error(integration.where,
                              "tdi=\"true\" needs an integration time, expected <time> > 0");
        }
        const std::size_t stages = focal_plane.detector_array.y_count;
        if (stages == 1) {
            diagnostics.error(integration.where,
                              "tdi=\"true\" uses the array's rows as TDI stages, expected "
                              "<yelementcount> > 1 in <detectorarray> (it is 1)");
        }
    }
    if (capture.detector_model && capture.type == model::CaptureMethodType::raw) {
        diagnostics.error(capture.detector_model->where,
                          "the detector model needs capturemethod type simple, expected no "
                          "<detectormodel> in a raw capture");
    }
    if (capture.type == model::CaptureMethodType::lidar) {
        // A pulse is one instant for every pixel and each pixel is one problem.
        if (integration.tdi) {
            diagnostics.error(integration.where,
                              "tdi=\"true\" needs capturemethod type simple (a lidar receiver "
                              "records every pixel at each pulse)");
        }
        if (focal_plane.detector_array.rolling_line_time_s) {
            diagnostics.warning(focal_plane.detector_array.where,
                                "rollingreadout is read, not applied on a lidar receiver: every "
                                "row records the same pulse");
        }
        if (capture.sample_strategy.hypersampling_multiplier > 1.0) {
            diagnostics.warning(capture.where,
                                "<hypersamplingmultiplier> is read, not applied on a lidar "
                                "receiver: its returns take the convergence maximum of samples "
                                "in every pixel");
        }
    }
    if (capture.type == model::CaptureMethodType::lidar && integration.time_s > 0.0) {
        diagnostics.warning(integration.where,
                            "<temporalintegration> does not apply to a lidar capture (the "
                            "signal gate sets its times, and the passive term is a rate); "
                            "ignored");
    }
    // A raw capture is the bandpass-sampled radiance for an external detection model: the
    // TDI accumulation of the in-render detection is not for it (a <channelpattern> on it is
    // refused by check_spectral_response).
    if (capture.type == model::CaptureMethodType::raw && integration.tdi) {
        diagnostics.error(integration.where,
                          "tdi=\"true\" needs capturemethod type simple (TDI stages are "
                          "accumulated by detection, which a raw capture leaves to an external "
                          "model)");
    }
    if (capture.type == model::CaptureMethodType::raw &&
        !capture.spectral_response.channels.empty()) {
        diagnostics.warning(capture.spectral_response.channels.front().where,
                            "the <channel>s of a raw capture are read, not applied: raw writes "
                            "one band per bandpass sample");
    }
    const model::DetectorArray& array = focal_plane.detector_array;
    if ((array.x_oversample > 1 || array.y_oversample > 1) &&
        capture.type != model::CaptureMethodType::raw) {
        diagnostics.warning(array.oversample_where,
                            "<xoversample>/<yoversample> are read, not applied: they oversample "
                            "a raw capture only (a simple capture samples each element's area)");
    } else if (array.y_oversample > 1 && array.rolling_line_time_s) {
        diagnostics.error(array.oversample_where,
                          "<yoversample> with rollingreadout: the sub-rows of a raw capture have "
                          "no readout time of their own, expected one of the two");
    }
    if (integration.tdi && focal_plane.detector_array.y_count > 1 &&
        focal_plane.detector_array.rolling_line_time_s) {
        diagnostics.warning(focal_plane.detector_array.where,
                            "rollingreadout is read, not applied on a TDI array: its stages are "
                            "read once per capture");
    }
    if (capture.detector_model && capture.type == model::CaptureMethodType::simple) {
        for (const model::Channel& channel : capture.spectral_response.channels) {
            if (channel.normalize) {
                diagnostics.warning(channel.where,
                                    "normalize of channel \"" + channel.name +
                                        "\" is ignored with a detector model (detection counts "
                                        "photons through the channel's response)");
            }
        }
    }
    const auto& file = capture.image_file;
    if (capture.detector_model &&
        (file.area_units != model::AreaUnits::cm2 || file.flux_units != model::FluxUnits::watts)) {
        diagnostics.warning(file.where,
                            "areaunits and fluxunits are ignored when the detector model is "
                            "enabled (the output is in digital counts)");
    }
}

}  // namespace glint::dirsig::detail
