// SPDX-License-Identifier: Apache-2.0
// Instruments of a `.platform`: type and optical properties (focal length mm → m, aperture,
// throughput, focus distance, Brown distortion), focal planes (capture method via
// capture_reader.cpp, detector array, capture extras) and truth collections. Elements that
// real files carry but glint does not model yet are warned about, never fatal.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include "glint/core/text.h"
#include "glint/model/output_name.h"
#include "glint/model/truth.h"
#include "platform_tree.h"

namespace glint::dirsig::detail {

namespace {

/// Lower case with '_', '-' and blanks removed ("Data_Recorder" → "datarecorder").
std::string squeezed(std::string_view text) {
    std::string out;
    for (char c : lower_trimmed(text)) {
        if (c != '_' && c != '-' && c != ' ') out += c;
    }
    return out;
}

/// `<properties>`; the focal length is required of a generic instrument (`known_type`: the
/// instrument's type was readable, so its requirements apply).
model::InstrumentProperties read_properties(const io::XmlNode& node, model::InstrumentType type,
                                            bool known_type, Diagnostics& diagnostics) {
    model::InstrumentProperties properties;
    properties.where = node.where();
    if (const std::optional<std::string> units = node.attribute("spatialunits")) {
        const std::string value = lower_trimmed(*units);
        if (value != "millimeters" && value != "mm") {
            diagnostics.warning(node.where_attribute("spatialunits"),
                                "spatialunits=\"" + *units +
                                    "\" ignored: focallength is read in mm, aperturediameter and "
                                    "focusdistance in m");
        }
    }
    if (const auto focal =
            node.optional_double("focallength", diagnostics, io::NumberRule::positive())) {
        properties.focal_length_m = *focal * 1e-3;
    } else if (!node.child("focallength") && known_type && type == model::InstrumentType::generic) {
        diagnostics.error(node.where(),
                          "missing required element <focallength> (a generic instrument needs "
                          "a focal length in mm)");
    }
    properties.aperture_diameter_m =
        node.optional_double("aperturediameter", diagnostics, io::NumberRule::positive());
    properties.aperture_throughput =
        node.optional_double("aperturethroughput", diagnostics, {0.0, 1.0, true, false})
            .value_or(1.0);
    properties.focus_distance_m =
        node.optional_double("focusdistance", diagnostics, io::NumberRule::positive());
    if (node.child("focusdistance") && !node.child("aperturediameter")) {
        diagnostics.error(node.child("focusdistance")->where(),
                          "<focusdistance> given without <aperturediameter>, expected an "
                          "aperture (a finite focus needs one to sample)");
    }
    if (const std::optional<io::XmlNode> distortion = node.child("distortion")) {
        model::Distortion d;
        d.k1 = distortion->optional_double("k1", diagnostics).value_or(0.0);
        d.k2 = distortion->optional_double("k2", diagnostics).value_or(0.0);
        d.k3 = distortion->optional_double("k3", diagnostics).value_or(0.0);
        d.p1 = distortion->optional_double("p1", diagnostics).value_or(0.0);
        d.p2 = distortion->optional_double("p2", diagnostics).value_or(0.0);
        distortion->warn_unknown_children({"k1", "k2", "k3", "p1", "p2"}, diagnostics);
        properties.distortion = d;
    }
    static constexpr std::array<std::string_view, 6> kNotUsed = {
        "magnification",      "telecentricity", "receiverradius",
        "receiverthroughput", "signalgate",     "dynamicgateinfo"};
    for (const io::XmlNode& child : node.children()) {
        if (std::find(kNotUsed.begin(), kNotUsed.end(), child.name()) != kNotUsed.end()) {
            warn_not_used(child, diagnostics);
        }
    }
    node.warn_unknown_children(
        {"focallength", "aperturediameter", "aperturethroughput", "focusdistance", "distortion",
         "magnification", "telecentricity", "receiverradius", "receiverthroughput", "signalgate",
         "dynamicgateinfo"},
        diagnostics);
    return properties;
}

model::TruthCollector read_collector(const io::XmlNode& node, Diagnostics& diagnostics) {
    model::TruthCollector collector;
    collector.where = node.where();
    collector.name = node.required_text("name", diagnostics);
    if (!collector.name.empty() && !model::expand_truth_collector(collector.name)) {
        diagnostics.error(node.child("name")->where(), "unknown truth collector " +
                                                           quote(collector.name) + " (" +
                                                           model::known_truth_collectors() + ")");
    }
    const std::optional<std::string> materials = node.optional_text("materials");
    const std::optional<std::string> tags = node.optional_text("tags");
    if (materials) collector.materials = split_list(*materials);
    if (tags) collector.tags = split_list(*tags);
    const bool abundance = lower_trimmed(collector.name) == "abundance";
    if (materials && tags) {
        diagnostics.error(node.child("tags")->where(),
                          "both <materials> and <tags> given, expected one of the two");
    }
    if (abundance && collector.materials.empty() && collector.tags.empty()) {
        diagnostics.error(node.where(),
                          "the Abundance collector needs <materials> (comma-separated material "
                          "ids) or <tags> (comma-separated geometry tags)");
    }
    if (!abundance && !collector.name.empty()) {
        for (std::string_view name : {"materials", "tags"}) {
            if (const auto child = node.child(name)) {
                diagnostics.warning(child->where(), "<" + std::string(name) +
                                                        "> ignored: only the Abundance "
                                                        "collector uses it");
            }
        }
    }
    node.warn_unknown_children({"name", "materials", "tags"}, diagnostics);
    return collector;
}

model::TruthCollection read_truth_collection(const io::XmlNode& node, Diagnostics& diagnostics) {
    model::TruthCollection truth;
    truth.where = node.where();
    truth.image_file.where = node.where();
    if (node.children().empty()) {
        // Read as disabled: an empty element names no file and no collector.
        truth.enabled = false;
        diagnostics.warning(node.where(), "empty <truthcollection>: nothing to collect");
        return truth;
    }
    truth.enabled = node.optional_bool("enabled", diagnostics).value_or(true);
    truth.name = node.optional_text("name").value_or("");
    if (!truth.enabled) {
        diagnostics.warning(node.child("enabled")->where(),
                            "truth collection " + quote(truth.name) +
                                " is disabled: no truth image is written for it");
    }
    if (const std::optional<io::XmlNode> image = node.child("imagefile")) {
        truth.image_file = read_image_file(*image, false, diagnostics);
        if (image->child("datatype") && truth.image_file.datatype != 4 &&
            truth.image_file.datatype != 5) {
            diagnostics.error(image->child("datatype")->where(),
                              "a truth image is float32 (<datatype>4) or float64 (5, the "
                              "default): its no-data value is NaN");
        }
    } else if (truth.enabled) {
        diagnostics.error(node.where(), "missing required element <imagefile>");
    }
    if (const std::optional<io::XmlNode> list = node.child("collectorlist")) {
        for (const io::XmlNode& collector : list->children("collector")) {
            truth.collectors.push_back(read_collector(collector, diagnostics));
        }
        list->warn_unknown_children({"collector"}, diagnostics);
    }
    if (truth.enabled && truth.collectors.empty()) {
        diagnostics.warning(node.where(),
                            "truth collection has no <collector>: nothing to collect");
    }
    node.warn_unknown_children({"enabled", "name", "imagefile", "collectorlist"}, diagnostics);
    return truth;
}

model::FocalPlane read_focal_plane(const io::XmlNode& node, const ReadContext& context,
                                   Diagnostics& diagnostics) {
    model::FocalPlane plane;
    plane.where = node.where();
    plane.enabled = node.attribute_bool("enabled", diagnostics).value_or(true);
    plane.name = node.attribute("name").value_or("");
    const std::optional<io::XmlNode> capture = node.child("capturemethod");
    if (capture) {
        plane.capture_method = read_capture_method(*capture, context, diagnostics);
    } else {
        diagnostics.error(node.where(), "missing required element <capturemethod>");
        plane.capture_method.where = node.where();
    }
    read_focal_plane_extras(node, plane.capture_method, context, diagnostics);
    const std::optional<io::XmlNode> array = node.child("detectorarray");
    if (array) {
        plane.detector_array = read_detector_array(*array, context, diagnostics);
    } else {
        diagnostics.error(node.where(), "missing required element <detectorarray>");
        plane.detector_array.where = node.where();
    }
    for (const io::XmlNode& truth : node.children("truthcollection")) {
        plane.truth_collections.push_back(read_truth_collection(truth, diagnostics));
    }
    node.warn_unknown_children({"capturemethod", "detectorarray", "truthcollection", "psf",
                                "activearea", "convergence", "processing", "detectormodel"},
                               diagnostics);
    if (capture && array) check_focal_plane(plane, diagnostics);
    return plane;
}

/// A lidar instrument's `<transmitter>` (docs/lidar.md).
model::Transmitter read_transmitter(const io::XmlNode& node, const ReadContext& context,
                                    Diagnostics& diagnostics) {
    model::Transmitter t;
    t.where = node.where();
    node.warn_unknown_children({"wavelength", "spectralwidth", "pulseenergy", "pulseduration",
                                "pulseshape", "beamdivergence", "pulserate"},
                               diagnostics);
    const io::NumberRule positive = io::NumberRule::positive();
    t.wavelength_um = node.required_double("wavelength", diagnostics, positive).value_or(0.0);
    t.spectral_width_um =
        node.optional_double("spectralwidth", diagnostics, io::NumberRule::non_negative())
            .value_or(0.0);
    t.pulse_energy_j = node.required_double("pulseenergy", diagnostics, positive).value_or(0.0);
    t.pulse_duration_s = node.required_double("pulseduration", diagnostics, positive).value_or(0.0);
    t.beam_divergence_rad =
        node.required_double("beamdivergence", diagnostics, positive).value_or(0.0);
    t.pulse_rate_hz = node.optional_double("pulserate", diagnostics, positive);
    if (const auto shape = node.child("pulseshape")) {
        shape->warn_unknown_children({"filename"}, diagnostics);
        const auto type = shape->attribute_enum("type", {"gaussian", "tabulated"}, diagnostics);
        if (type == "tabulated") {
            const auto file = shape->child("filename");
            if (!file) {
                diagnostics.error(shape->where(),
                                  "a tabulated <pulseshape> needs <filename> "
                                  "(time s, relative power)");
            } else {
                t.pulse_shape_file = context.options.paths.resolve(file->text(), context.base_dir,
                                                                   file->where(), diagnostics);
            }
        }
    }
    return t;
}

/// The transmitter's `<pulserate>` against its receivers' clocks: the receiver's clock fires
/// the pulses, so an independent clock of another rate contradicts it.
void check_pulse_rate(const model::Transmitter& t, const std::vector<model::FocalPlane>& planes,
                      const io::XmlNode& node, Diagnostics& diagnostics) {
    if (!t.pulse_rate_hz) return;
    for (const model::FocalPlane& plane : planes) {
        const model::Clock& clock = plane.detector_array.clock;
        if (clock.type != model::ClockType::independent || !(clock.rate_hz > 0.0)) continue;
        if (std::abs(clock.rate_hz - *t.pulse_rate_hz) > 1e-9 * *t.pulse_rate_hz) {
            diagnostics.error(node.child("pulserate")->where(),
                              "the pulse rate " + format_shortest(*t.pulse_rate_hz) +
                                  " Hz differs from the " + format_shortest(clock.rate_hz) +
                                  " Hz clock of receiver \"" + plane.name +
                                  "\", whose ticks fire the pulses (give one rate)");
        }
    }
}

/// A data recorder's `<clock>`, `<output>` and `<noise>` (docs/data-recorder.md).
model::DataRecorder read_data_recorder(const io::XmlNode& node, const std::string& name,
                                       const ReadContext& context, Diagnostics& diagnostics) {
    model::DataRecorder recorder;
    recorder.where = node.where();
    recorder.basename = name;
    if (const auto clock = node.child("clock")) {
        recorder.clock = read_clock(*clock, context, diagnostics);
        if (recorder.clock->type == model::ClockType::external_trigger) {
            diagnostics.error(clock->where(),
                              "a data recorder's own <clock> is independent or synchronous; "
                              "for external triggers give it a focal plane with that clock");
        }
    }
    ErrorContext name_where = node.where_attribute("name");
    if (const auto output = node.child("output")) {
        output->warn_unknown_children({"basename"}, diagnostics);
        if (const auto basename = output->child("basename")) {
            recorder.basename = basename->text();
            name_where = basename->where();
        }
    }
    if (recorder.basename.empty()) {
        diagnostics.error(node.where(),
                          "a data recorder needs a name or <output><basename> (its "
                          "files are BASENAME.csv and BASENAME.jsonl)");
    } else if (const auto problem = model::output_name_problem(recorder.basename)) {
        diagnostics.error(name_where,
                          "data recorder file name " + quote(recorder.basename) + " " + *problem);
        recorder.basename.clear();
    }
    if (const auto noise = node.child("noise")) {
        model::TelemetryNoise& n = recorder.noise;
        n.where = noise->where();
        noise->warn_unknown_children(
            {"positionsigma", "velocitysigma", "orientationsigma", "angularratesigma"},
            diagnostics);
        const io::NumberRule rule = io::NumberRule::non_negative();
        n.position_m = noise->optional_double("positionsigma", diagnostics, rule);
        n.velocity_m_s = noise->optional_double("velocitysigma", diagnostics, rule);
        n.orientation_deg = noise->optional_double("orientationsigma", diagnostics, rule);
        n.angular_rate_deg_s = noise->optional_double("angularratesigma", diagnostics, rule);
    }
    return recorder;
}

}  // namespace

model::Instrument read_instrument(const io::XmlNode& node, const ReadContext& context,
                                  Diagnostics& diagnostics) {
    model::Instrument instrument;
    instrument.where = node.where();
    instrument.name = node.attribute("name").value_or("");
    bool known_type = true;
    if (const std::optional<std::string> raw = node.attribute("type")) {
        instrument.type_text = *raw;
        const std::string type = squeezed(*raw);
        if (type == "generic") {
            instrument.type = model::InstrumentType::generic;
        } else if (type == "lidar") {
            instrument.type = model::InstrumentType::lidar;
        } else if (type == "datarecorder") {
            instrument.type = model::InstrumentType::data_recorder;
        } else {
            known_type = false;
            diagnostics.error(node.where_attribute("type"),
                              "unknown instrument type \"" + *raw +
                                  "\", expected generic, lidar or datarecorder");
        }
    }
    if (const std::optional<io::XmlNode> properties = node.child("properties")) {
        instrument.properties =
            read_properties(*properties, instrument.type, known_type, diagnostics);
    } else {
        instrument.properties.where = node.where();
        if (known_type && instrument.type == model::InstrumentType::generic) {
            diagnostics.error(node.where(),
                              "missing required element <properties> (a generic instrument "
                              "needs a focal length in mm)");
        }
    }
    for (const io::XmlNode& plane : node.children("focalplane")) {
        instrument.focal_planes.push_back(read_focal_plane(plane, context, diagnostics));
    }
    const bool recorder = instrument.type == model::InstrumentType::data_recorder;
    if (recorder)
        instrument.recorder = read_data_recorder(node, instrument.name, context, diagnostics);
    const bool lidar = instrument.type == model::InstrumentType::lidar;
    if (lidar) {
        if (const auto transmitter = node.child("transmitter")) {
            instrument.transmitter = read_transmitter(*transmitter, context, diagnostics);
            check_pulse_rate(*instrument.transmitter, instrument.focal_planes, *transmitter,
                             diagnostics);
        } else {
            diagnostics.error(node.where(),
                              "a lidar instrument needs a <transmitter> (its laser: "
                              "wavelength, pulse energy and duration, beam "
                              "divergence)");
        }
    }
    static constexpr std::array<std::string_view, 8> kNotUsed = {
        "frame", "options", "clock", "datetime", "source", "transmitter", "receiver", "output"};
    for (const io::XmlNode& child : node.children()) {
        if (recorder && (child.name() == "clock" || child.name() == "output")) continue;
        if (lidar && child.name() == "transmitter") continue;
        if (std::find(kNotUsed.begin(), kNotUsed.end(), child.name()) != kNotUsed.end()) {
            warn_not_used(child, diagnostics);
        }
    }
    node.warn_unknown_children({"properties", "focalplane", "frame", "options", "clock", "datetime",
                                "source", "transmitter", "receiver", "output", "noise"},
                               diagnostics);
    if (!recorder) {
        if (const auto noise = node.child("noise")) {
            diagnostics.warning(noise->where(),
                                "<noise> is read only in a data recorder "
                                "(type=\"datarecorder\"): ignored");
        }
    }
    if (known_type && instrument.focal_planes.empty() && !recorder) {
        diagnostics.warning(node.where(), "instrument has no <focalplane>: it captures nothing");
    }
    if (recorder && !instrument.recorder.clock &&
        std::none_of(instrument.focal_planes.begin(), instrument.focal_planes.end(),
                     [](const model::FocalPlane& p) { return p.enabled; })) {
        diagnostics.warning(node.where(),
                            "data recorder \"" + instrument.name +
                                "\" has no <clock> (nor an enabled focal plane's): it records "
                                "nothing");
    }
    return instrument;
}

}  // namespace glint::dirsig::detail
