// SPDX-License-Identifier: Apache-2.0
// The capture-method half of the `.platform` reader: `<capturemethod>` and its children
// (sample strategy, image file, spatial response, temporal integration, lidar signal gate).
// Its extras (detector model, convergence, PSF, active area, processing tasks) are read by
// capture_extras_reader.cpp, the spectral response by spectral_reader.cpp, the checks that
// need the whole focal plane are focal_plane_checks.cpp. Every problem goes to Diagnostics
// with its location.
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

using capture_io::non_empty_text;
using capture_io::single_child;
using capture_io::trim;

/// ENVI data types an image file may be written as.
constexpr int kEnviDataTypes[] = {1, 2, 3, 4, 5, 12, 13, 14, 15};

/// A whole number >= 1 in attribute `name`; nullopt when absent or invalid (invalid: error).
std::optional<int> attribute_count(const io::XmlNode& node, std::string_view name,
                                   Diagnostics& diagnostics) {
    const auto value = node.attribute_double(name, diagnostics, io::NumberRule{1.0, 1e9});
    if (!value) return std::nullopt;
    if (*value != std::floor(*value)) {
        diagnostics.error(node.where_attribute(name), std::string(name) + " " +
                                                          format_ten_digits(*value) +
                                                          " is invalid, expected an integer >= 1");
        return std::nullopt;
    }
    return static_cast<int>(*value);
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
    if (gate.samples_per_bin > 1) {
        // The published BIN readers size a pixel differently when a bin has several samples
        // (docs/lidar-bin.md): glint writes one reading, and says so.
        diagnostics.warning(node.child("samplespertimebin")->where(),
                            "samplespertimebin " + std::to_string(gate.samples_per_bin) +
                                ": the BIN file holds 1 + bins x " +
                                std::to_string(gate.samples_per_bin) +
                                " values per pixel; published BIN readers disagree on this "
                                "layout (docs/lidar-bin.md, \"Pixel order\")");
    }
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
    read_capture_extras(node, capture, context, diagnostics, false);
    return capture;
}

}  // namespace glint::dirsig::detail
