// SPDX-License-Identifier: Apache-2.0
// Per-focal-plane render state: spectral grid, materials on it, camera, output units,
// convergence and the ENVI header template.
#include <cmath>
#include <string>

#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/detect/header_keys.h"
#include "glint/model/derived.h"
#include "glint/model/names.h"
#include "render_parts.h"

namespace glint::render::detail {

bool renders(const schedule::ClockedFocalPlane& source, std::string& why) {
    const model::Instrument& instrument = *source.instrument;
    const model::FocalPlane& fp = *source.focal_plane;
    if (instrument.type == model::InstrumentType::data_recorder) {
        why = "focal plane \"" + fp.name + "\" of data recorder \"" + instrument.name +
              "\" makes no image (its capture method is read, not applied): the recorder "
              "records its pose at its clock's ticks (docs/data-recorder.md)";
        return false;
    }
    if (instrument.type != model::InstrumentType::generic &&
        instrument.type != model::InstrumentType::lidar) {
        why = "instrument \"" + instrument.name + "\" is a " + instrument.type_text +
              " instrument; glint-render renders generic (camera) instruments";
        return false;
    }
    if (!fp.enabled) {
        why = "focal plane \"" + fp.name + "\" is disabled";
        return false;
    }
    if (fp.capture_method.image_file.basename.empty()) {
        why = "focal plane \"" + fp.name + "\" has no <imagefile>";
        return false;
    }
    return true;
}

bool splits_channels(const RenderInputs& inputs, std::size_t plugin_index,
                     const RenderOptions& options) {
    const std::vector<model::Plugin>& plugins = inputs.simulation.plugins;
    if (plugin_index < plugins.size() && plugins[plugin_index].basic_platform) {
        if (const std::optional<bool> entry =
                plugins[plugin_index].basic_platform->split_channels) {
            return *entry;
        }
    }
    return options.split_channels;
}

namespace {

radiometry::Convergence convergence_of(const model::FocalPlane& fp, const RenderOptions& options) {
    if (const auto& c = fp.capture_method.convergence) {
        if (c->minimum_samples < 1 || c->maximum_samples < c->minimum_samples) {
            throw input_error("<convergence> needs 1 <= minimumsamples <= maximumsamples",
                              c->where);
        }
        return {static_cast<std::uint64_t>(c->minimum_samples),
                static_cast<std::uint64_t>(c->maximum_samples), c->threshold};
    }
    return options.convergence.value_or(kDefaultConvergence);
}

io::EnviHeader header_of(const schedule::ClockedFocalPlane& source,
                         const sensor::OutputUnits& units,
                         const radiometry::Convergence& convergence, const RenderOptions& options,
                         const RenderInputs& inputs, const Context& context) {
    const model::FocalPlane& fp = *source.focal_plane;
    const model::CaptureMethod& method = fp.capture_method;
    io::EnviHeader h;
    h.description = std::string("glint-render ") + model::name_of(method.type) + " capture of " +
                    source.instrument->name + " -> " + fp.name;
    h.samples = source.x_count;
    h.bands = units.channels();
    // With a detector model the file holds the photon product detection starts from:
    // float64 always, <datatype> is for the counts.
    h.data_type = method.detector_model ? io::EnviDataType::float64
                                        : detect::image_data_type(method.image_file);
    h.wavelength_units = "Micrometers";
    h.wavelength = units.centers_um();
    h.fwhm = units.fwhm_um();
    h.band_names = units.band_names();
    h.data_units = units.description().data_units;
    h.set_extra("glint version", options.version);
    h.set_extra("glint command line", context.command_line());
    h.set_extra("glint seed", std::to_string(options.schedule.seed));
    h.set_extra("glint simulation", inputs.schedule->simulation_file().string());
    h.set_extra("glint plugin index",
                std::to_string(inputs.schedule->plugins()[source.plugin].plugin_index));
    const schedule::PluginSchedule& plugin = inputs.schedule->plugins()[source.plugin];
    if (plugin.platform) h.set_extra("glint platform", plugin.platform->file);
    h.set_extra("glint instrument", source.instrument->name);
    h.set_extra("glint focal plane", fp.name);
    h.set_extra("glint convergence", std::to_string(convergence.min_samples) + " " +
                                         std::to_string(convergence.max_samples) + " " +
                                         format_shortest(convergence.threshold_w_per_cm2_sr_um));
    h.set_extra("glint scale resolution", format_shortest(options.schedule.scale_resolution));
    if (source.tdi_stages > 1) h.set_extra("glint tdi stages", std::to_string(source.tdi_stages));
    if (fp.capture_method.type == model::CaptureMethodType::raw) {
        // Each detector element's sub-pixels, columns then lines (docs/units.md, "Raw capture").
        h.set_extra("glint raw oversampling",
                    io::envi_brace_list({std::to_string(fp.detector_array.x_oversample),
                                         std::to_string(fp.detector_array.y_oversample)}));
    }
    h.set_extra("glint split channels",
                splits_channels(inputs, plugin.plugin_index, options) ? "true" : "false");
    h.set_extra("glint atmosphere", model::to_string(inputs.atmosphere.kind));
    h.set_extra("glint refraction", inputs.light && inputs.light->refracts() ? "on" : "off");
    // Which atmosphere: the file that defined it, the option, or glint's default.
    h.set_extra("glint atmosphere source", inputs.atmosphere.source);
    const auto& per_channel = units.description().per_channel_units;
    if (!per_channel.empty()) h.set_extra("glint channel units", io::envi_brace_list(per_channel));
    return h;
}

/// The capture method whose units the output takes: with a detector model the <imagefile>'s
/// fluxunits and areaunits are ignored (as the DIRSIG5 BasicPlatform manual says) for the
/// photon product at the focal plane, per cm², channels integrated and not normalized, that
/// detection needs. A TDI pixel's integration time is that of all its stages.
model::CaptureMethod units_method(const schedule::ClockedFocalPlane& source) {
    const model::FocalPlane& fp = *source.focal_plane;
    model::CaptureMethod method = fp.capture_method;
    // A TDI pixel integrates over all its stages: stages × the stage time.
    method.temporal_integration.time_s *= static_cast<double>(source.tdi_stages);
    if (!method.detector_model) return method;
    method.image_file.flux_units = model::FluxUnits::photons_per_second;
    method.image_file.area_units = model::AreaUnits::cm2;
    // normalize does not apply (the reader warned at the channel).
    for (model::Channel& channel : method.spectral_response.channels) channel.normalize = false;
    return method;
}

/// A lidar receiver's passive units: photons/s per cm² at the focal plane (the aperture's
/// G#), no temporal integration, one channel: its filter (the capture's one <channel>), else
/// a flat response over its bandpass; without a <spectralresponse>, a 1 nm band (3 samples)
/// centred on the laser line.
model::CaptureMethod lidar_units_method(const schedule::ClockedFocalPlane& source) {
    model::CaptureMethod method = source.focal_plane->capture_method;
    model::Bandpass& bandpass = method.spectral_response.bandpass;
    if (bandpass.count == 0 && source.instrument->transmitter) {
        const double centre = source.instrument->transmitter->wavelength_um;
        bandpass.min_um = centre - 0.0005;
        bandpass.max_um = centre + 0.0005;
        bandpass.delta_um = 0.0005;
        bandpass.count = 3;
        bandpass.where = method.where;
    }
    method.image_file.flux_units = model::FluxUnits::photons_per_second;
    method.image_file.area_units = model::AreaUnits::cm2;
    method.temporal_integration.time_s = 0.0;
    method.detector_model.reset();
    if (method.spectral_response.channels.size() > 1) {
        throw input_error("a lidar receiver has one <channel> (its filter), found " +
                              std::to_string(method.spectral_response.channels.size()),
                          method.spectral_response.channels[1].where);
    }
    if (method.spectral_response.channels.empty()) {
        model::Channel flat;
        flat.name = "receiver";
        flat.shape = model::ChannelShape::tophat;
        flat.center_um = 0.5 * (bandpass.min_um + bandpass.max_um);
        // Wider than the bandpass by a sample either side: every sample weighs 1.
        flat.width_um = bandpass.max_um - bandpass.min_um + 4.0 * bandpass.delta_um;
        flat.where = method.where;
        method.spectral_response.channels.push_back(flat);
    }
    method.spectral_response.channels.front().normalize = false;
    return method;
}

/// The focal plane's spectral states: one over the whole grid, or, split, one per channel
/// over the bands its response covers, each converging at the band nearest its centre.
std::vector<SpectralState> spectral_states(const SpectralGrid& grid,
                                           const sensor::OutputUnits& units, bool split) {
    const auto centre_band = [&](BandRange r) {
        const double lo = grid.wavelength_um(r.first);
        const double hi = grid.wavelength_um(r.first + r.count - 1);
        return radiometry::nearest_band(grid, 0.5 * (lo + hi));
    };
    const BandRange all{0, grid.size()};
    if (!split) return {SpectralState{all, centre_band(all), std::nullopt}};
    std::vector<SpectralState> states;
    for (std::size_t c = 0; c < units.channels(); ++c) {
        const BandRange bands = units.support(c);
        // A channel that weighs no band (OutputUnits refuses one without response; a zero
        // gain) is its bias alone: one band traced, weighed by nothing.
        const BandRange traced = bands.count > 0 ? bands : BandRange{0, 1};
        states.push_back(SpectralState{traced, centre_band(traced), c});
    }
    return states;
}

/// The header of detected output: counts (or a mosaic), glint-detect's keys.
void add_detection_header(io::EnviHeader& h, const detect::DetectionSettings& settings) {
    h.data_units = detect::output_data_units(settings, h.data_units);
    h.data_type = settings.data_type;
    h.bands = settings.output_bands();
    if (settings.cfa) {
        h.band_names = detect::output_band_names(settings);
        h.wavelength.clear();
        h.fwhm.clear();
        h.wavelength_units.clear();
    }
    for (const auto& [key, value] : detect::detection_header_keys(settings)) {
        h.set_extra(key, value);
    }
}

}  // namespace

FocalPlaneState make_focal_plane_state(const RenderInputs& inputs, std::size_t source_index,
                                       const RenderOptions& options, const Context& context) {
    const schedule::ClockedFocalPlane& source = inputs.schedule->sources()[source_index];
    const model::FocalPlane& fp = *source.focal_plane;
    // What the focal plane's elements ask for and glint does not apply (a rolling readout on
    // a TDI array, <temporalintegration><samples>, normalize with a detector model) was
    // warned about once by the reader, at the element, for --check and the render alike.
    const bool lidar = source.instrument->type == model::InstrumentType::lidar;
    const model::CaptureMethod method = lidar ? lidar_units_method(source) : units_method(source);
    SpectralGrid grid = model::bandpass_grid(method.spectral_response.bandpass);
    // radiometry: the materials on the focal plane's grid, the convergence of its pixels and
    // the band that watches it.
    radiometry::MaterialTable materials(inputs.scene.materials, grid, context.log);
    const radiometry::Convergence convergence = convergence_of(fp, options);
    const std::size_t reference_band =
        radiometry::nearest_band(grid, 0.5 * (grid.min_um() + grid.max_um()));
    // sensor: the camera, the output units and their spectral states, then the truth, the PSF
    // and the mask.
    sensor::CameraModel camera(source.instrument->properties, fp.detector_array, source.x_count,
                               source.y_count);
    sensor::OutputUnits units(method, source.instrument->properties, grid);
    std::vector<SpectralState> states = spectral_states(
        grid, units,
        splits_channels(inputs, inputs.schedule->plugins()[source.plugin].plugin_index, options));
    io::EnviHeader header = header_of(source, units, convergence, options, inputs, context);
    FocalPlaneState state{std::move(grid),   std::move(states),     std::move(materials),
                          std::move(camera), std::move(units),      convergence,
                          std::move(header), std::nullopt,          std::nullopt,
                          std::nullopt,      sensor::TruthLayout{}, reference_band,
                          std::nullopt};
    if (lidar) {
        state.lidar.emplace(
            make_lidar_state(source, inputs.scene, state.camera, convergence, context));
    } else {
        state.truth = sensor::make_truth_layout(fp, inputs.scene, state.units, context.log);
    }
    if (const std::optional<model::Psf>& psf = fp.capture_method.psf) {
        state.psf = sensor::PsfSampler::from_model(*psf);
        state.header.set_extra("glint psf", state.psf->description());
    }
    if (const std::optional<sensor::ThinLens>& lens = state.camera.thin_lens()) {
        state.header.set_extra(
            "glint focus", "distance " + format_shortest(lens->focus_distance_m) + " m, aperture " +
                               format_shortest(lens->aperture_diameter_m) + " m");
    }
    if (!fp.capture_method.active_area_image.empty()) {
        state.mask = sensor::ActiveArea::from_model(fp.capture_method.active_area_image,
                                                    fp.capture_method.active_area);
        state.header.set_extra("glint active area", state.mask->description());
    }
    if (lidar) return state;  // its detector model gives the QE alone (make_lidar_state)
    const bool detects = fp.capture_method.detector_model.has_value() ||
                         fp.capture_method.spectral_response.pattern.has_value() ||
                         source.tdi_stages > 1;
    if (detects && !options.radiance_only) {
        detect::DetectorOverrides overrides;
        overrides.scale_resolution = options.schedule.scale_resolution;
        detect::DetectionSettings settings = detect::resolve_detection(
            fp, source.instrument->properties, overrides, options.schedule.seed);
        add_detection_header(state.header, settings);
        state.detection.emplace(std::move(settings), source.x_count);
    }
    return state;
}

}  // namespace glint::render::detail
