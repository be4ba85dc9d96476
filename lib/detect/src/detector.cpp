// SPDX-License-Identifier: Apache-2.0
// resolve_detection: the settings of a focal plane's detection from the model and the
// overrides, with every requirement and range checked before any pixel is processed.
#include "glint/detect/detector.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/core/units.h"
#include "glint/detect/noise.h"

namespace glint::detect {
namespace {

/// The longest integration time accepted: 1e9 s (32 years); longer is a typing error, and
/// with any dark current it would exceed the electron counts glint can draw.
constexpr double kMaxIntegrationTime_s = 1e9;

std::string quoted_list(const std::vector<std::string>& names) {
    std::string text;
    for (std::size_t i = 0; i < names.size(); ++i) {
        text += (i ? ", \"" : "\"") + names[i] + "\"";
    }
    return text;
}

/// A value from the model or its override, with the name to give in messages.
struct Source {
    double value = 0.0;
    std::string name;  ///< "--qe" or "<quantumefficiency>"
    ErrorContext where;
};

Source pick(const std::optional<double>& override_value, const char* option, double model_value,
            const char* element, const ErrorContext& where) {
    if (override_value) return {*override_value, option, {}};
    return {model_value, element, where};
}

/// A bad value: a usage error when it came from a command-line override (named "--..."),
/// else an input error at the model element.
Error value_error(bool from_option, const std::string& message, const ErrorContext& where) {
    if (from_option) return usage_error(message);
    return input_error(message, where);
}

[[noreturn]] void bad(const Source& s, const std::string& expected) {
    throw value_error(s.name.starts_with("--"),
                      s.name + " " + format_shortest(s.value) + " is invalid, expected " + expected,
                      s.where);
}

void check_range(const Source& s, double low, double high, const std::string& expected) {
    if (!(std::isfinite(s.value) && s.value >= low && s.value <= high)) bad(s, expected);
}

/// An element size divided as the camera divides it under --scale_resolution.
double scaled_size(double size_m, std::size_t count, double factor) {
    const double scaled = std::max(1.0, std::round(static_cast<double>(count) * factor));
    return size_m * static_cast<double>(count) / scaled;
}

DetectorModelSettings resolve_model(const model::FocalPlane& fp,
                                    const model::InstrumentProperties& properties,
                                    const DetectorOverrides& o) {
    const model::CaptureMethod& method = fp.capture_method;
    const std::optional<model::DetectorModel>& m = method.detector_model;
    const model::DetectorModel base = m.value_or(model::DetectorModel{});
    if (!m) {
        std::vector<std::string> missing;
        if (!o.quantum_efficiency) missing.push_back("--qe");
        if (!o.min_electrons) missing.push_back("--min-electrons");
        if (!o.max_electrons) missing.push_back("--max-electrons");
        if (!o.bit_depth) missing.push_back("--bit-depth");
        if (!missing.empty()) {
            std::string list;
            for (std::size_t i = 0; i < missing.size(); ++i) list += (i ? ", " : "") + missing[i];
            throw input_error("focal plane \"" + fp.name +
                                  "\" has no <detectormodel>: add one to the .platform or give " +
                                  list,
                              method.where);
        }
    }
    if (method.type != model::CaptureMethodType::simple) {
        throw input_error(
            "the detector model needs a capture method of type simple (the manual's "
            "requirement; raw captures are for external detector modelling)",
            method.where);
    }
    if (!properties.aperture_diameter_m) {
        throw input_error("the detector model of focal plane \"" + fp.name +
                              "\" needs <aperturediameter> in the instrument's <properties> "
                              "(photons reach the detectors through the aperture)",
                          properties.where);
    }
    const ErrorContext where = m ? m->where : method.where;
    DetectorModelSettings d;
    const Source qe =
        pick(o.quantum_efficiency, "--qe", base.quantum_efficiency, "<quantumefficiency>", where);
    check_range(qe, 0.0, 1.0, "a number in [0, 1]");
    const Source read =
        pick(o.read_noise_e, "--read-noise", base.read_noise_e, "<readnoise>", where);
    check_range(read, 0.0, 1e12, "a number of electrons from 0 to 1e12");
    const Source dark = pick(o.dark_current_density_a_per_m2, "--dark-current-density",
                             base.dark_current_density_a_per_m2, "<darkcurrentdensity>", where);
    check_range(dark, 0.0, 1e12, "a density from 0 to 1e12 A/m2");
    const Source min_e =
        pick(o.min_electrons, "--min-electrons", base.min_electrons, "<minelectrons>", where);
    const Source max_e =
        pick(o.max_electrons, "--max-electrons", base.max_electrons, "<maxelectrons>", where);
    // 1e15: the largest electron count glint draws (kMaxPoissonMean).
    check_range(min_e, -kMaxPoissonMean, kMaxPoissonMean, "a number of electrons from -1e15 to 1e15");
    check_range(max_e, -kMaxPoissonMean, kMaxPoissonMean, "a number of electrons from -1e15 to 1e15");
    if (!(min_e.value < max_e.value)) {
        throw value_error(o.min_electrons || o.max_electrons,
                          "the ADC range is empty: " + min_e.name + " " +
                              format_shortest(min_e.value) + " must be less than " + max_e.name +
                              " " + format_shortest(max_e.value),
                          where);
    }
    const int bits = o.bit_depth.value_or(base.bit_depth);
    if (bits < 1 || bits > 32) {
        throw value_error(o.bit_depth.has_value(),
                          std::string(o.bit_depth ? "--bit-depth " : "<bitdepth> ") +
                              std::to_string(bits) + " is invalid, expected 1 to 32 bits",
                          where);
    }
    const model::TemporalIntegration& ti = method.temporal_integration;
    const Source time =
        pick(o.integration_time_s, "--integration-time", ti.time_s, "<time>", ti.where);
    if (!(std::isfinite(time.value) && time.value > 0.0)) {
        throw value_error(o.integration_time_s.has_value(),
                          "the detector model of focal plane \"" + fp.name +
                              "\" needs a non-zero integration time (" + time.name + " is " +
                              format_shortest(time.value) +
                              "; set <temporalintegration><time> in seconds)",
                          time.where);
    }
    check_range(time, 0.0, kMaxIntegrationTime_s, "a number of seconds from 0 to 1e9");
    const model::DetectorArray& array = fp.detector_array;
    const double x_m = scaled_size(array.x_size_m, array.x_count, o.scale_resolution);
    // TDI stages are not resolution: --scale_resolution leaves their size alone.
    const double y_m = method.temporal_integration.tdi
                           ? array.y_size_m
                           : scaled_size(array.y_size_m, array.y_count, o.scale_resolution);
    if (!(x_m > 0.0 && y_m > 0.0 && std::isfinite(x_m * y_m))) {
        throw input_error(
            "the detector array's element size must be > 0 (the pixel area sets "
            "the photons each detector collects)",
            array.where);
    }
    d.quantum_efficiency = qe.value;
    d.read_noise_e = read.value;
    d.dark_current_density_a_per_m2 = dark.value;
    d.min_electrons = min_e.value;
    d.max_electrons = max_e.value;
    d.bit_depth = bits;
    d.integration_time_s = time.value;
    d.pixel_area_m2 = x_m * y_m;
    return d;
}

/// The channel named after `filter`: equal name first, else the only name containing it.
std::optional<int> channel_named_after(const std::vector<std::string>& names, CfaFilter filter) {
    const std::string wanted = cfa_filter_name(filter);
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (to_lower(names[i]) == wanted) return static_cast<int>(i);
    }
    std::optional<int> found;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (to_lower(names[i]).find(wanted) != std::string::npos) {
            if (found) return std::nullopt;
            found = static_cast<int>(i);
        }
    }
    return found;
}

std::optional<CfaSettings> resolve_cfa(const model::FocalPlane& fp,
                                       const std::vector<std::string>& names,
                                       const DetectorOverrides& o) {
    const std::optional<model::ChannelPattern>& pattern =
        fp.capture_method.spectral_response.pattern;
    std::optional<CfaPattern> kind;
    switch (o.mosaic) {
        case MosaicChoice::none:
            return std::nullopt;
        case MosaicChoice::bayer:
            kind = CfaPattern::bayer;
            break;
        case MosaicChoice::truesense:
            kind = CfaPattern::truesense;
            break;
        case MosaicChoice::from_focal_plane:
            if (!pattern) return std::nullopt;
            kind = pattern->kind == model::ChannelPatternKind::bayer ? CfaPattern::bayer
                                                                     : CfaPattern::truesense;
            break;
    }
    CfaSettings cfa;
    cfa.pattern = *kind;
    cfa.phase = o.bayer_phase.value_or(BayerPhase::rggb);
    const bool from_model = pattern && (pattern->kind == model::ChannelPatternKind::bayer) ==
                                           (*kind == CfaPattern::bayer);
    for (CfaFilter filter : cfa_filters(*kind)) {
        const std::string filter_name = cfa_filter_name(filter);
        std::optional<int> channel;
        if (from_model) {
            const std::optional<std::string> mapped = pattern->channel_for(filter_name);
            if (!mapped) {
                throw input_error("the " + std::string(cfa_pattern_name(*kind)) +
                                      " pattern has no "
                                      "<mapping> for its " +
                                      filter_name + " filter",
                                  pattern->where);
            }
            const auto it = std::find(names.begin(), names.end(), *mapped);
            if (it == names.end()) {
                throw input_error("the " + filter_name + " filter maps to channel \"" + *mapped +
                                      "\", which focal plane \"" + fp.name +
                                      "\" does not have (channels: " + quoted_list(names) + ")",
                                  pattern->where);
            }
            channel = static_cast<int>(it - names.begin());
        } else {
            channel = channel_named_after(names, filter);
            if (!channel) {
                throw input_error("--mosaic " + std::string(cfa_pattern_name(*kind)) +
                                      ": no channel "
                                      "of focal plane \"" +
                                      fp.name + "\" is named after the " + filter_name +
                                      " filter (channels: " + quoted_list(names) +
                                      "); map the filters with a <channelpattern> in the .platform",
                                  fp.capture_method.spectral_response.bandpass.where);
            }
        }
        cfa.channel_of_filter[static_cast<std::size_t>(filter)] = *channel;
    }
    return cfa;
}

}  // namespace

io::EnviDataType image_data_type(const model::ImageFile& image) {
    const std::optional<io::EnviDataType> type = io::envi_type_from_code(image.datatype);
    if (!type || *type == io::EnviDataType::complex64 || *type == io::EnviDataType::complex128) {
        throw input_error("<datatype> " + std::to_string(image.datatype) +
                              " is not a real ENVI data type (1, 2, 3, 4, 5, 12, 13, 14, 15)",
                          image.where);
    }
    return *type;
}

const char* tdi_mode_name(TdiMode mode) { return mode == TdiMode::charge ? "charge" : "digital"; }

double DetectorModelSettings::dark_electrons(std::size_t stages) const {
    return dark_current_density_a_per_m2 * pixel_area_m2 * integration_time_s *
           static_cast<double>(stages) / kElementaryChargeC;
}

double DetectorModelSettings::gain_dn_per_e() const {
    return max_count() / (max_electrons - min_electrons);
}

double DetectorModelSettings::max_count() const { return std::ldexp(1.0, bit_depth) - 1.0; }

DetectionSettings resolve_detection(const model::FocalPlane& fp,
                                    const model::InstrumentProperties& properties,
                                    const DetectorOverrides& o, std::uint64_t seed) {
    const model::CaptureMethod& method = fp.capture_method;
    DetectionSettings s;
    s.focal_plane = fp.name;
    s.seed = seed;
    for (const model::Channel& channel : method.spectral_response.channels) {
        s.channel_names.push_back(channel.name);
    }
    if (s.channel_names.empty()) {
        throw input_error("focal plane \"" + fp.name + "\" has no channels", method.where);
    }
    if (!(std::isfinite(o.scale_resolution) && o.scale_resolution > 0.0)) {
        throw input_error("scale resolution " + format_shortest(o.scale_resolution) +
                          " is invalid, expected a number > 0");
    }
    const bool model_asked = method.detector_model || o.quantum_efficiency || o.read_noise_e ||
                             o.dark_current_density_a_per_m2 || o.min_electrons ||
                             o.max_electrons || o.bit_depth;
    if (model_asked) s.detector = resolve_model(fp, properties, o);
    const model::TemporalIntegration& ti = method.temporal_integration;
    if (ti.tdi) {
        s.tdi_stages = fp.detector_array.y_count;
        if (s.tdi_stages < 2) {
            throw input_error("a TDI focal plane needs <yelementcount> > 1 (its stages)",
                              fp.detector_array.where);
        }
        if (!(ti.time_s > 0.0) && !o.integration_time_s) {
            throw input_error("a TDI focal plane needs a non-zero integration time", ti.where);
        }
    }
    s.tdi_mode = o.tdi_mode.value_or(TdiMode::charge);
    s.cfa = resolve_cfa(fp, s.channel_names, o);
    if (!s.active()) {
        throw input_error("focal plane \"" + fp.name +
                              "\" has nothing to detect: no <detectormodel>, no TDI and no "
                              "<channelpattern> (give detector values or --mosaic to add them)",
                          fp.where);
    }
    if (!s.detector && (o.no_noise || o.electrons)) {
        throw input_error(std::string(o.electrons ? "--electrons" : "--no-noise") +
                              " needs a detector model, which focal plane \"" + fp.name +
                              "\" does not have",
                          method.where);
    }
    s.noise = !o.no_noise;
    s.output = o.electrons ? DetectOutput::electrons : DetectOutput::counts;
    if (o.data_type) {
        s.data_type = *o.data_type;
    } else if (s.detector && s.output == DetectOutput::electrons) {
        s.data_type = io::EnviDataType::float64;
    } else {
        s.data_type = image_data_type(method.image_file);
    }
    if (s.data_type == io::EnviDataType::complex64 || s.data_type == io::EnviDataType::complex128) {
        throw input_error("complex data types cannot hold detector output");
    }
    return s;
}

}  // namespace glint::detect
