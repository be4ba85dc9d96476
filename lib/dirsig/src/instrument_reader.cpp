#include "glint/core/text.h"
// SPDX-License-Identifier: Apache-2.0
#include "glint/core/text.h"
// Instruments of a `.platform`: type and optical properties (focal length mm → m, aperture,
#include "glint/core/text.h"
// throughput, focus distance, Brown distortion), focal planes (capture method via
#include "glint/core/text.h"
// capture_reader.cpp, detector array, capture extras) and truth collections. Elements that
#include "glint/core/text.h"
// real files carry but glint does not model yet are warned about, never fatal.
#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "glint/core/text.h"
#include "platform_tree.h"
namespace glint::dirsig::detail {
#include "glint/core/text.h"
namespace {
#include "glint/core/text.h"
/// Lower case with '_', '-' and blanks removed ("Data_Recorder" → "datarecorder").
#include "glint/core/text.h"
std::string squeezed(std::string_view text) {
#include "glint/core/text.h"
    std::string out;
#include "glint/core/text.h"
    for (char c : lower_trimmed(text)) {
#include "glint/core/text.h"
        if (c != '_' && c != '-' && c != ' ') out += c;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    return out;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
/// `<properties>`; the focal length is required of a generic instrument (`known_type`: the
#include "glint/core/text.h"
/// instrument's type was readable, so its requirements apply).
#include "glint/core/text.h"
model::InstrumentProperties read_properties(const io::XmlNode& node, model::InstrumentType type,
#include "glint/core/text.h"
                                            bool known_type, Diagnostics& diagnostics) {
#include "glint/core/text.h"
    model::InstrumentProperties properties;
#include "glint/core/text.h"
    properties.where = node.where();
#include "glint/core/text.h"
    if (const std::optional<std::string> units = node.attribute("spatialunits")) {
#include "glint/core/text.h"
        const std::string value = lower_trimmed(*units);
#include "glint/core/text.h"
        if (value != "millimeters" && value != "mm") {
#include "glint/core/text.h"
            diagnostics.warning(node.where_attribute("spatialunits"),
#include "glint/core/text.h"
                                "spatialunits=\"" + *units +
#include "glint/core/text.h"
                                    "\" ignored: focallength is read in mm, aperturediameter and "
#include "glint/core/text.h"
                                    "focusdistance in m");
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (const auto focal =
#include "glint/core/text.h"
            node.optional_double("focallength", diagnostics, io::NumberRule::positive())) {
#include "glint/core/text.h"
        properties.focal_length_m = *focal * 1e-3;
#include "glint/core/text.h"
    } else if (!node.child("focallength") && known_type && type == model::InstrumentType::generic) {
#include "glint/core/text.h"
        diagnostics.error(node.where(),
#include "glint/core/text.h"
                          "missing required element <focallength> (a generic instrument needs "
#include "glint/core/text.h"
                          "a focal length in mm)");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    properties.aperture_diameter_m =
#include "glint/core/text.h"
        node.optional_double("aperturediameter", diagnostics, io::NumberRule::positive());
#include "glint/core/text.h"
    properties.aperture_throughput =
#include "glint/core/text.h"
        node.optional_double("aperturethroughput", diagnostics, {0.0, 1.0, true, false})
#include "glint/core/text.h"
            .value_or(1.0);
#include "glint/core/text.h"
    properties.focus_distance_m =
#include "glint/core/text.h"
        node.optional_double("focusdistance", diagnostics, io::NumberRule::positive());
#include "glint/core/text.h"
    if (node.child("focusdistance") && !node.child("aperturediameter")) {
#include "glint/core/text.h"
        diagnostics.error(node.child("focusdistance")->where(),
#include "glint/core/text.h"
                          "<focusdistance> given without <aperturediameter>, expected an "
#include "glint/core/text.h"
                          "aperture (a finite focus needs one to sample)");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (const std::optional<io::XmlNode> distortion = node.child("distortion")) {
#include "glint/core/text.h"
        model::Distortion d;
#include "glint/core/text.h"
        d.k1 = distortion->optional_double("k1", diagnostics).value_or(0.0);
#include "glint/core/text.h"
        d.k2 = distortion->optional_double("k2", diagnostics).value_or(0.0);
#include "glint/core/text.h"
        d.k3 = distortion->optional_double("k3", diagnostics).value_or(0.0);
#include "glint/core/text.h"
        d.p1 = distortion->optional_double("p1", diagnostics).value_or(0.0);
#include "glint/core/text.h"
        d.p2 = distortion->optional_double("p2", diagnostics).value_or(0.0);
#include "glint/core/text.h"
        distortion->warn_unknown_children({"k1", "k2", "k3", "p1", "p2"}, diagnostics);
#include "glint/core/text.h"
        properties.distortion = d;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    static constexpr std::array<std::string_view, 6> kNotUsed = {
#include "glint/core/text.h"
        "magnification",      "telecentricity", "receiverradius",
#include "glint/core/text.h"
        "receiverthroughput", "signalgate",     "dynamicgateinfo"};
#include "glint/core/text.h"
    for (const io::XmlNode& child : node.children()) {
#include "glint/core/text.h"
        if (std::find(kNotUsed.begin(), kNotUsed.end(), child.name()) != kNotUsed.end()) {
#include "glint/core/text.h"
            warn_not_used(child, diagnostics);
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    node.warn_unknown_children(
#include "glint/core/text.h"
        {"focallength", "aperturediameter", "aperturethroughput", "focusdistance", "distortion",
#include "glint/core/text.h"
         "magnification", "telecentricity", "receiverradius", "receiverthroughput", "signalgate",
#include "glint/core/text.h"
         "dynamicgateinfo"},
#include "glint/core/text.h"
        diagnostics);
#include "glint/core/text.h"
    return properties;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
model::TruthCollector read_collector(const io::XmlNode& node, Diagnostics& diagnostics) {
#include "glint/core/text.h"
    model::TruthCollector collector;
#include "glint/core/text.h"
    collector.where = node.where();
#include "glint/core/text.h"
    collector.name = node.required_text("name", diagnostics);
#include "glint/core/text.h"
    const std::optional<std::string> materials = node.optional_text("materials");
#include "glint/core/text.h"
    const std::optional<std::string> tags = node.optional_text("tags");
#include "glint/core/text.h"
    if (materials) collector.materials = split_list(*materials);
#include "glint/core/text.h"
    if (tags) collector.tags = split_list(*tags);
#include "glint/core/text.h"
    const bool abundance = lower_trimmed(collector.name) == "abundance";
#include "glint/core/text.h"
    if (materials && tags) {
#include "glint/core/text.h"
        diagnostics.error(node.child("tags")->where(),
#include "glint/core/text.h"
                          "both <materials> and <tags> given, expected one of the two");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (abundance && collector.materials.empty() && collector.tags.empty()) {
#include "glint/core/text.h"
        diagnostics.error(node.where(),
#include "glint/core/text.h"
                          "the Abundance collector needs <materials> (comma-separated material "
#include "glint/core/text.h"
                          "ids) or <tags> (comma-separated geometry tags)");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (!abundance && !collector.name.empty()) {
#include "glint/core/text.h"
        for (std::string_view name : {"materials", "tags"}) {
#include "glint/core/text.h"
            if (const auto child = node.child(name)) {
#include "glint/core/text.h"
                diagnostics.warning(child->where(), "<" + std::string(name) +
#include "glint/core/text.h"
                                                        "> ignored: only the Abundance "
#include "glint/core/text.h"
                                                        "collector uses it");
#include "glint/core/text.h"
            }
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    node.warn_unknown_children({"name", "materials", "tags"}, diagnostics);
#include "glint/core/text.h"
    return collector;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
model::TruthCollection read_truth_collection(const io::XmlNode& node, Diagnostics& diagnostics) {
#include "glint/core/text.h"
    model::TruthCollection truth;
#include "glint/core/text.h"
    truth.where = node.where();
#include "glint/core/text.h"
    truth.image_file.where = node.where();
#include "glint/core/text.h"
    if (node.children().empty()) {
#include "glint/core/text.h"
        // Read as disabled: an empty element names no file and no collector.
#include "glint/core/text.h"
        truth.enabled = false;
#include "glint/core/text.h"
        diagnostics.warning(node.where(), "empty <truthcollection>: nothing to collect");
#include "glint/core/text.h"
        return truth;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    truth.enabled = node.optional_bool("enabled", diagnostics).value_or(true);
#include "glint/core/text.h"
    truth.name = node.optional_text("name").value_or("");
#include "glint/core/text.h"
    if (const std::optional<io::XmlNode> image = node.child("imagefile")) {
#include "glint/core/text.h"
        truth.image_file = read_image_file(*image, false, diagnostics);
#include "glint/core/text.h"
    } else if (truth.enabled) {
#include "glint/core/text.h"
        diagnostics.error(node.where(), "missing required element <imagefile>");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (const std::optional<io::XmlNode> list = node.child("collectorlist")) {
#include "glint/core/text.h"
        for (const io::XmlNode& collector : list->children("collector")) {
#include "glint/core/text.h"
            truth.collectors.push_back(read_collector(collector, diagnostics));
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
        list->warn_unknown_children({"collector"}, diagnostics);
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (truth.enabled && truth.collectors.empty()) {
#include "glint/core/text.h"
        diagnostics.warning(node.where(),
#include "glint/core/text.h"
                            "truth collection has no <collector>: nothing to collect");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    node.warn_unknown_children({"enabled", "name", "imagefile", "collectorlist"}, diagnostics);
#include "glint/core/text.h"
    return truth;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
model::FocalPlane read_focal_plane(const io::XmlNode& node, const ReadContext& context,
#include "glint/core/text.h"
                                   Diagnostics& diagnostics) {
#include "glint/core/text.h"
    model::FocalPlane plane;
#include "glint/core/text.h"
    plane.where = node.where();
#include "glint/core/text.h"
    plane.enabled = node.attribute_bool("enabled", diagnostics).value_or(true);
#include "glint/core/text.h"
    plane.name = node.attribute("name").value_or("");
#include "glint/core/text.h"
    const std::optional<io::XmlNode> capture = node.child("capturemethod");
#include "glint/core/text.h"
    if (capture) {
#include "glint/core/text.h"
        plane.capture_method = read_capture_method(*capture, context, diagnostics);
#include "glint/core/text.h"
    } else {
#include "glint/core/text.h"
        diagnostics.error(node.where(), "missing required element <capturemethod>");
#include "glint/core/text.h"
        plane.capture_method.where = node.where();
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    read_focal_plane_extras(node, plane.capture_method, context, diagnostics);
#include "glint/core/text.h"
    const std::optional<io::XmlNode> array = node.child("detectorarray");
#include "glint/core/text.h"
    if (array) {
#include "glint/core/text.h"
        plane.detector_array = read_detector_array(*array, context, diagnostics);
#include "glint/core/text.h"
    } else {
#include "glint/core/text.h"
        diagnostics.error(node.where(), "missing required element <detectorarray>");
#include "glint/core/text.h"
        plane.detector_array.where = node.where();
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    for (const io::XmlNode& truth : node.children("truthcollection")) {
#include "glint/core/text.h"
        plane.truth_collections.push_back(read_truth_collection(truth, diagnostics));
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    node.warn_unknown_children({"capturemethod", "detectorarray", "truthcollection", "psf",
#include "glint/core/text.h"
                                "activearea", "convergence", "processing", "detectormodel"},
#include "glint/core/text.h"
                               diagnostics);
#include "glint/core/text.h"
    if (capture && array) check_focal_plane(plane, diagnostics);
#include "glint/core/text.h"
    return plane;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
}  // namespace
#include "glint/core/text.h"
model::Instrument read_instrument(const io::XmlNode& node, const ReadContext& context,
#include "glint/core/text.h"
                                  Diagnostics& diagnostics) {
#include "glint/core/text.h"
    model::Instrument instrument;
#include "glint/core/text.h"
    instrument.where = node.where();
#include "glint/core/text.h"
    instrument.name = node.attribute("name").value_or("");
#include "glint/core/text.h"
    bool known_type = true;
#include "glint/core/text.h"
    if (const std::optional<std::string> raw = node.attribute("type")) {
#include "glint/core/text.h"
        instrument.type_text = *raw;
#include "glint/core/text.h"
        const std::string type = squeezed(*raw);
#include "glint/core/text.h"
        if (type == "generic") {
#include "glint/core/text.h"
            instrument.type = model::InstrumentType::generic;
#include "glint/core/text.h"
        } else if (type == "lidar") {
#include "glint/core/text.h"
            instrument.type = model::InstrumentType::lidar;
#include "glint/core/text.h"
        } else if (type == "datarecorder") {
#include "glint/core/text.h"
            instrument.type = model::InstrumentType::data_recorder;
#include "glint/core/text.h"
        } else {
#include "glint/core/text.h"
            known_type = false;
#include "glint/core/text.h"
            diagnostics.error(node.where_attribute("type"),
#include "glint/core/text.h"
                              "unknown instrument type \"" + *raw +
#include "glint/core/text.h"
                                  "\", expected generic, lidar or datarecorder");
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (const std::optional<io::XmlNode> properties = node.child("properties")) {
#include "glint/core/text.h"
        instrument.properties =
#include "glint/core/text.h"
            read_properties(*properties, instrument.type, known_type, diagnostics);
#include "glint/core/text.h"
    } else {
#include "glint/core/text.h"
        instrument.properties.where = node.where();
#include "glint/core/text.h"
        if (known_type && instrument.type == model::InstrumentType::generic) {
#include "glint/core/text.h"
            diagnostics.error(node.where(),
#include "glint/core/text.h"
                              "missing required element <properties> (a generic instrument "
#include "glint/core/text.h"
                              "needs a focal length in mm)");
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    for (const io::XmlNode& plane : node.children("focalplane")) {
#include "glint/core/text.h"
        instrument.focal_planes.push_back(read_focal_plane(plane, context, diagnostics));
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    static constexpr std::array<std::string_view, 8> kNotUsed = {
#include "glint/core/text.h"
        "frame", "options", "clock", "datetime", "source", "transmitter", "receiver", "output"};
#include "glint/core/text.h"
    for (const io::XmlNode& child : node.children()) {
#include "glint/core/text.h"
        if (std::find(kNotUsed.begin(), kNotUsed.end(), child.name()) != kNotUsed.end()) {
#include "glint/core/text.h"
            warn_not_used(child, diagnostics);
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    node.warn_unknown_children({"properties", "focalplane", "frame", "options", "clock", "datetime",
#include "glint/core/text.h"
                                "source", "transmitter", "receiver", "output"},
#include "glint/core/text.h"
                               diagnostics);
#include "glint/core/text.h"
    if (known_type && instrument.focal_planes.empty() &&
#include "glint/core/text.h"
        instrument.type != model::InstrumentType::data_recorder) {
#include "glint/core/text.h"
        diagnostics.warning(node.where(), "instrument has no <focalplane>: it captures nothing");
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    return instrument;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
}  // namespace glint::dirsig::detail
