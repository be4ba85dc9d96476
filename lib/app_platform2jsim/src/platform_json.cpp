// SPDX-License-Identifier: Apache-2.0
// The normalized platform JSON ("glint-platform" version 1, docs/formats.md): a walk over the
// model writing every field, with enumerations in their XML spelling and the derived
// quantities of glint/model/derived.h.
#include "glint/app_platform2jsim/platform_json.h"

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>

#include "glint/core/error.h"
#include "glint/core/json_text.h"
#include "glint/model/derived.h"
#include "glint/model/names.h"

namespace glint::app_platform2jsim {
namespace {

using Json = nlohmann::ordered_json;
using namespace glint::model;

// ---- small values -------------------------------------------------------------------------

template <typename T>
Json optional_value(const std::optional<T>& value) {
    return value ? Json(*value) : Json(nullptr);
}

template <std::size_t N>
Json array_of(const std::array<double, N>& values) {
    Json out = Json::array();
    for (double v : values) out.push_back(v);
    return out;
}

Json file_ref(const FileRef& ref) {
    if (ref.empty()) return nullptr;
    return Json{{"text", ref.text}, {"resolved", ref.resolved.string()}};
}

Json strings(const std::vector<std::string>& values) {
    Json out = Json::array();
    for (const std::string& v : values) out.push_back(v);
    return out;
}

// ---- platform tree ------------------------------------------------------------------------

/// Index of each instrument in list_instruments() order, by address.
using InstrumentIndex = std::map<const Instrument*, std::size_t>;

Json transform_json(const AffineTransform& t) {
    Json j;
    j["identity"] = t.is_identity();
    j["translation_m"] = array_of(t.translation_m);
    j["rotation_rad"] = array_of(t.rotation_rad);
    j["rotation_order"] = t.rotation_order;
    j["matrix"] = t.matrix ? array_of(*t.matrix) : Json(nullptr);
    return j;
}

Json deviates_json(const RotationDeviates& deviates) {
    static constexpr const char* kAxisNames[3] = {"x", "y", "z"};
    Json axes = Json::array();
    for (std::size_t i = 0; i < deviates.axes.size(); ++i) {
        const JitterSpec& a = deviates.axes[i];
        axes.push_back(Json{{"axis", kAxisNames[i]},
                            {"kind", name_of(a.kind)},
                            {"mean_rad", a.mean},
                            {"stddev_rad", a.stddev},
                            {"psd_file", file_ref(a.psd_file)}});
    }
    return Json{{"any", deviates.any()}, {"axes", std::move(axes)}};
}

Json attachment_json(const Attachment& attachment, const InstrumentIndex& index);

Json mount_json(const Mount& m, const InstrumentIndex& index) {
    Json j;
    j["name"] = m.name;
    j["type"] = name_of(m.type);
    j["type_text"] = m.type_text;
    j["rotation_order"] = m.rotation_order;
    j["rotation_rad"] = array_of(m.rotation_rad);
    Json entries = Json::array();
    for (const MountEntry& e : m.entries) {
        entries.push_back(Json{{"time_s", e.time_s},
                               {"rotation_rad", array_of(e.rotation_rad)},
                               {"translation_m", array_of(e.translation_m)}});
    }
    j["entries"] = std::move(entries);
    j["period_s"] = optional_value(m.period_s);
    if (m.whisk) {
        j["whisk"] = Json{
            {"axis", name_of(m.whisk->axis)},          {"min_angle_rad", m.whisk->min_angle_rad},
            {"max_angle_rad", m.whisk->max_angle_rad}, {"rate_hz", m.whisk->rate_hz},
            {"phase_rad", m.whisk->phase_rad},         {"sinusoidal", m.whisk->sinusoidal}};
    } else {
        j["whisk"] = nullptr;
    }
    if (m.tracking) {
        j["tracking"] =
            Json{{"name", m.tracking->name},
                 {"offset_m", array_of(m.tracking->offset_m)},
                 {"point_m", m.tracking->point_m ? array_of(*m.tracking->point_m) : Json(nullptr)}};
    } else {
        j["tracking"] = nullptr;
    }
    j["rotation_deviates"] = deviates_json(m.deviates);
    Json attachments = Json::array();
    for (const Attachment& a : m.attachments) attachments.push_back(attachment_json(a, index));
    j["attachments"] = std::move(attachments);
    return j;
}

Json attachment_json(const Attachment& attachment, const InstrumentIndex& index) {
    Json j;
    j["transform"] = transform_json(attachment.transform);
    Json instruments = Json::array();
    for (const Instrument& instrument : attachment.instruments) {
        const auto found = index.find(&instrument);
        instruments.push_back(
            Json{{"index", found == index.end() ? Json(nullptr) : Json(found->second)},
                 {"name", instrument.name}});
    }
    j["instruments"] = std::move(instruments);
    Json mounts = Json::array();
    for (const Mount& m : attachment.mounts) mounts.push_back(mount_json(m, index));
    j["mounts"] = std::move(mounts);
    return j;
}

// ---- focal planes -------------------------------------------------------------------------

Json image_file_json(const ImageFile& f) {
    return Json{{"basename", f.basename},
                {"extension", f.extension},
                {"schedule", name_of(f.schedule)},
                {"datatype", f.datatype},
                {"area_units", name_of(f.area_units)},
                {"flux_units", name_of(f.flux_units)}};
}

Json capture_json(const CaptureMethod& c) {
    Json j;
    j["type"] = name_of(c.type);
    j["name"] = c.name;
    j["sample_strategy"] =
        Json{{"type", c.sample_strategy.type},
             {"hypersampling_multiplier", c.sample_strategy.hypersampling_multiplier}};
    j["image_file"] = image_file_json(c.image_file);
    if (c.spatial_response) {
        const SpatialResponse& r = *c.spatial_response;
        Json entries = Json::array();
        for (const SpatialResponseEntry& e : r.entries) {
            entries.push_back(Json{{"type", e.type},
                                   {"spectral_point", e.spectral_point},
                                   {"x_width", e.x_width},
                                   {"y_width", e.y_width},
                                   {"total_weight", e.total_weight}});
        }
        j["spatial_response"] = Json{{"spatial_sampling", r.spatial_sampling},
                                     {"spectral_units", r.spectral_units},
                                     {"x_sub_elements", r.x_sub_elements},
                                     {"y_sub_elements", r.y_sub_elements},
                                     {"entries", std::move(entries)}};
    } else {
        j["spatial_response"] = nullptr;
    }
    j["temporal_integration"] = Json{{"time_s", c.temporal_integration.time_s},
                                     {"samples", c.temporal_integration.samples},
                                     {"tdi", c.temporal_integration.tdi}};
    if (c.detector_model) {
        const DetectorModel& d = *c.detector_model;
        j["detector_model"] =
            Json{{"quantum_efficiency", d.quantum_efficiency},
                 {"read_noise_e", d.read_noise_e},
                 {"dark_current_density_a_per_m2", d.dark_current_density_a_per_m2},
                 {"min_electrons", d.min_electrons},
                 {"max_electrons", d.max_electrons},
                 {"bit_depth", d.bit_depth}};
    } else {
        j["detector_model"] = nullptr;
    }
    if (c.convergence) {
        j["convergence"] = Json{{"minimum_samples", c.convergence->minimum_samples},
                                {"maximum_samples", c.convergence->maximum_samples},
                                {"threshold_w_per_cm2_sr_um", c.convergence->threshold}};
    } else {
        j["convergence"] = nullptr;
    }
    if (c.psf) {
        j["psf"] = Json{{"width_px", optional_value(c.psf->width_px)},
                        {"image", file_ref(c.psf->image)},
                        {"scale_px", c.psf->scale_px}};
    } else {
        j["psf"] = nullptr;
    }
    j["active_area_image"] = file_ref(c.active_area_image);
    Json processing = Json::array();
    for (const ProcessingTask& t : c.processing) {
        processing.push_back(Json{{"schedule", name_of(t.schedule)},
                                  {"message", t.message},
                                  {"program", t.program},
                                  {"arguments", strings(t.arguments)},
                                  {"remove_file", t.remove_file}});
    }
    j["processing"] = std::move(processing);
    j["signal_gate"] = Json();  // lidar captures only
    if (c.signal_gate) {
        const SignalGate& g = *c.signal_gate;
        j["signal_gate"] = Json{{"start_s", g.start_s},
                                {"stop_s", g.stop_s},
                                {"bin_width_s", g.bin_width_s},
                                {"bin_count", g.bin_count()},
                                {"samples_per_bin", g.samples_per_bin}};
    }
    return j;
}

Json channel_json(std::size_t index, const Channel& c, const std::optional<SpectralGrid>& grid) {
    const bool tabulated = c.shape == ChannelShape::tabulated;
    Json j;
    j["index"] = index;
    j["name"] = c.name;
    j["shape"] = name_of(c.shape);
    j["normalize"] = c.normalize;
    j["gain"] = c.gain;
    j["bias"] = c.bias;
    j["center_um"] = tabulated ? Json(nullptr) : Json(c.center_um);
    j["width_um"] = tabulated ? Json(nullptr) : Json(c.width_um);
    Json wavelengths = Json::array();
    for (double w : c.table_wavelength_um) wavelengths.push_back(w);
    Json values = Json::array();
    for (double v : c.table_value) values.push_back(v);
    j["table"] = Json{{"wavelength_um", std::move(wavelengths)}, {"value", std::move(values)}};
    j["polarizer"] = c.polarizer;
    j["data_output"] = c.data_output;
    Json integral = nullptr;
    if (grid) {
        try {
            integral = channel_integral_um(c, *grid);
        } catch (const Error&) {
            integral = nullptr;  // an invalid channel: the reader has reported it
        }
    }
    j["integral_um"] = std::move(integral);
    return j;
}

Json spectral_json(const SpectralResponse& s) {
    std::optional<SpectralGrid> grid;
    try {
        grid = bandpass_grid(s.bandpass);
    } catch (const Error&) {
        grid.reset();  // an invalid bandpass: the reader has reported it
    }
    Json j;
    j["bandpass"] = Json{{"min_um", s.bandpass.min_um},
                         {"max_um", s.bandpass.max_um},
                         {"delta_um", s.bandpass.delta_um},
                         {"count", s.bandpass.count},
                         {"spectral_units", s.bandpass.spectral_units}};
    Json channels = Json::array();
    for (std::size_t i = 0; i < s.channels.size(); ++i) {
        channels.push_back(channel_json(i, s.channels[i], grid));
    }
    j["channels"] = std::move(channels);
    if (s.pattern) {
        Json mappings = Json::array();
        for (const auto& [filter, channel] : s.pattern->mappings) {
            mappings.push_back(Json{{"filter", filter}, {"channel", channel}});
        }
        j["pattern"] = Json{{"name", name_of(s.pattern->kind)}, {"mappings", std::move(mappings)}};
    } else {
        j["pattern"] = nullptr;
    }
    return j;
}

Json clock_json(const Clock& c) {
    return Json{{"type", name_of(c.type)},
                {"temporal_units", c.temporal_units},
                {"rate_hz", c.rate_hz},
                {"offset_s", c.offset_s},
                {"master", c.master},
                {"divider", c.divider},
                {"offset_count", c.offset_count},
                {"trigger_file", file_ref(c.trigger_file)}};
}

Json detector_json(const DetectorArray& a) {
    Json j;
    j["spatial_units"] = a.spatial_units;
    j["x_count"] = a.x_count;
    j["y_count"] = a.y_count;
    j["x_size_m"] = a.x_size_m;
    j["y_size_m"] = a.y_size_m;
    j["x_spacing_m"] = a.x_spacing_m;
    j["y_spacing_m"] = a.y_spacing_m;
    j["x_offset_m"] = a.x_offset_m;
    j["y_offset_m"] = a.y_offset_m;
    j["x_flip"] = a.x_flip;
    j["y_flip"] = a.y_flip;
    j["rolling_line_time_s"] = optional_value(a.rolling_line_time_s);
    j["x_oversample"] = a.x_oversample;
    j["y_oversample"] = a.y_oversample;
    j["clock"] = clock_json(a.clock);
    return j;
}

Json truth_json(std::size_t index, const TruthCollection& t) {
    Json collectors = Json::array();
    for (const TruthCollector& c : t.collectors) {
        collectors.push_back(
            Json{{"name", c.name}, {"materials", strings(c.materials)}, {"tags", strings(c.tags)}});
    }
    return Json{{"index", index},
                {"enabled", t.enabled},
                {"name", t.name},
                {"image_file", image_file_json(t.image_file)},
                {"collectors", std::move(collectors)}};
}

/// Pixel IFOV and full field of view (2 atan(extent / 2f), extent = count × pitch).
Json focal_plane_derived(const InstrumentProperties& properties, const DetectorArray& array) {
    const auto ifov = pixel_ifov_rad(properties, array);
    Json j;
    j["pixel_ifov_rad"] = ifov ? array_of(*ifov) : Json(nullptr);
    if (ifov) {
        const double f = *properties.focal_length_m;
        const double x_extent = static_cast<double>(array.x_count) * array.x_spacing_m;
        const double y_extent = static_cast<double>(array.y_count) * array.y_spacing_m;
        j["field_of_view_rad"] =
            Json::array({2.0 * std::atan(0.5 * x_extent / f), 2.0 * std::atan(0.5 * y_extent / f)});
    } else {
        j["field_of_view_rad"] = nullptr;
    }
    return j;
}

Json focal_plane_json(std::size_t index, const FocalPlane& fp,
                      const InstrumentProperties& properties) {
    Json j;
    j["index"] = index;
    j["name"] = fp.name;
    j["enabled"] = fp.enabled;
    j["capture_method"] = capture_json(fp.capture_method);
    j["spectral_response"] = spectral_json(fp.capture_method.spectral_response);
    j["detector_array"] = detector_json(fp.detector_array);
    Json truth = Json::array();
    for (std::size_t i = 0; i < fp.truth_collections.size(); ++i) {
        truth.push_back(truth_json(i, fp.truth_collections[i]));
    }
    j["truth_collections"] = std::move(truth);
    j["derived"] = focal_plane_derived(properties, fp.detector_array);
    return j;
}

Json instrument_json(std::size_t index, const InstrumentPath& path) {
    const Instrument& instrument = *path.instrument;
    const InstrumentProperties& p = instrument.properties;
    Json j;
    j["index"] = index;
    j["name"] = instrument.name;
    j["type"] = name_of(instrument.type);
    j["type_text"] = instrument.type_text;
    Json mounts = Json::array();
    for (const Mount* m : path.mounts) mounts.push_back(m->name);
    j["path"] = std::move(mounts);
    const Distortion distortion = p.distortion.value_or(Distortion{});
    j["properties"] = Json{{"focal_length_m", optional_value(p.focal_length_m)},
                           {"aperture_diameter_m", optional_value(p.aperture_diameter_m)},
                           {"aperture_throughput", p.aperture_throughput},
                           {"focus_distance_m", optional_value(p.focus_distance_m)},
                           {"distortion", Json{{"k1", distortion.k1},
                                               {"k2", distortion.k2},
                                               {"k3", distortion.k3},
                                               {"p1", distortion.p1},
                                               {"p2", distortion.p2}}}};
    j["derived"] = Json{{"f_number", optional_value(f_number(p))},
                        {"g_number_per_sr", optional_value(g_number(p))}};
    Json planes = Json::array();
    for (std::size_t i = 0; i < instrument.focal_planes.size(); ++i) {
        planes.push_back(focal_plane_json(i, instrument.focal_planes[i], p));
    }
    j["focal_planes"] = std::move(planes);
    j["transmitter"] = Json();  // null but for lidar instruments
    if (instrument.transmitter) {
        const Transmitter& t = *instrument.transmitter;
        j["transmitter"] = Json{{"wavelength_um", t.wavelength_um},
                                {"spectral_width_um", t.spectral_width_um},
                                {"pulse_energy_j", t.pulse_energy_j},
                                {"pulse_duration_s", t.pulse_duration_s},
                                {"pulse_shape_file", file_ref(t.pulse_shape_file)},
                                {"beam_divergence_rad", t.beam_divergence_rad},
                                {"pulse_rate_hz", optional_value(t.pulse_rate_hz)}};
    }
    j["recorder"] = Json();  // null but for data recorders: every key is always written
    if (instrument.type == InstrumentType::data_recorder) {
        const DataRecorder& r = instrument.recorder;
        const TelemetryNoise& n = r.noise;
        j["recorder"] = Json{
            {"clock", r.clock ? clock_json(*r.clock) : Json()},
            {"basename", r.basename},
            {"noise_sigma", Json{{"position_m", optional_value(n.position_m)},
                                 {"velocity_m_s", optional_value(n.velocity_m_s)},
                                 {"orientation_deg", optional_value(n.orientation_deg)},
                                 {"angular_rate_deg_s", optional_value(n.angular_rate_deg_s)}}}};
    }
    return j;
}

}  // namespace

std::string platform_to_json(const model::Platform& platform, int indent) {
    const std::vector<InstrumentPath> paths = list_instruments(platform);
    InstrumentIndex index;
    for (std::size_t i = 0; i < paths.size(); ++i) index.emplace(paths[i].instrument, i);

    Json j;
    j["format"] = kPlatformJsonFormat;
    j["version"] = kPlatformJsonVersion;
    j["file"] = platform.file;
    Json metadata = Json::array();
    for (const auto& [name, value] : platform.metadata.entries) {
        metadata.push_back(Json{{"name", name}, {"value", value}});
    }
    j["metadata"] = std::move(metadata);
    Json clocks = Json::array();
    for (const MasterClock& c : platform.clock_table) {
        clocks.push_back(Json{{"name", c.name}, {"rate_hz", c.rate_hz}, {"offset_s", c.offset_s}});
    }
    j["clock_table"] = std::move(clocks);
    Json attachments = Json::array();
    for (const Attachment& a : platform.attachments)
        attachments.push_back(attachment_json(a, index));
    j["attachments"] = std::move(attachments);
    Json instruments = Json::array();
    for (std::size_t i = 0; i < paths.size(); ++i)
        instruments.push_back(instrument_json(i, paths[i]));
    j["instruments"] = std::move(instruments);
    // Invalid UTF-8 in a name must not make the dump fail: replace it.
    return json_text(j, indent < 0 ? -1 : indent);
}

}  // namespace glint::app_platform2jsim
