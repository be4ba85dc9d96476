// SPDX-License-Identifier: Apache-2.0
// Lidar receivers (docs/lidar.md): the state built once per receiver, the BIN file planned
// with its headers, and one pulse per clock tick — the passive photon rate through the path
// tracer on the receiver's band, the time-resolved returns through the lidar tracer — written
// pixel after pixel in DIRSIG's order (x slowest: io::bin_pixel_index), each pixel's passive
// rate then its time samples.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "glint/core/datetime.h"
#include "glint/core/error.h"
#include "glint/core/spectral.h"
#include "glint/core/text.h"
#include "glint/model/derived.h"
#include "glint/motion/euler.h"
#include "render_parts.h"

namespace glint::render::detail {
namespace {

/// The stream id of the returns' samples (the spectral-state slot of the key; the passive
/// term uses the unsplit key), ASCII "lidar".
constexpr std::uint64_t kReturnsStream = 0x6C69646172;

/// "YYYYMMDDThhmmss" (UTC) of a time, the BIN headers' date-time fields.
std::string bin_datetime(const DateTime& reference, double seconds) {
    const std::string iso = format_iso8601_utc(add_seconds(reference, seconds), 0);
    // "YYYY-MM-DDThh:mm:ssZ" → "YYYYMMDDThhmmss"
    std::string out;
    for (const char c : iso) {
        if (c != '-' && c != ':' && c != 'Z') out += c;
    }
    return out.substr(0, 15);
}

/// Row-major 4 × 4 of a rigid transform (child → parent).
io::Affine16 affine_of(const motion::Rigid& r) {
    const motion::Mat3 m = motion::rotation_matrix(r);
    return {
        m(0, 0), m(0, 1), m(0, 2), r.translation_m.x, m(1, 0), m(1, 1), m(1, 2), r.translation_m.y,
        m(2, 0), m(2, 1), m(2, 2), r.translation_m.z, 0,       0,       0,       1};
}

/// The pulse shape of a transmitter: its table, or a Gaussian of its duration.
radiometry::PulseShape pulse_shape_of(const model::Transmitter& t) {
    if (t.pulse_shape_file.empty()) return radiometry::PulseShape::gaussian(t.pulse_duration_s);
    try {
        return radiometry::PulseShape::tabulated(t.pulse_shape.time_s, t.pulse_shape.power);
    } catch (const Error& e) {
        throw input_error(e.message(),
                          t.pulse_shape.where.file.empty() ? t.where : t.pulse_shape.where);
    }
}

/// The transmitter's pulse rate for a task's header: <pulserate>, an independent clock's
/// rate, else the task's mean tick rate (0 for one pulse).
double pulse_rate_hz(const model::Transmitter& t, const schedule::ClockedFocalPlane& source,
                     const std::vector<const PlannedCapture*>& pulses) {
    if (t.pulse_rate_hz) return *t.pulse_rate_hz;
    if (source.clock().type == model::ClockType::independent) return source.clock().rate_hz;
    if (pulses.size() < 2) return 0.0;
    const double span = pulses.back()->capture.t0_s - pulses.front()->capture.t0_s;
    return span > 0.0 ? static_cast<double>(pulses.size() - 1) / span : 0.0;
}

}  // namespace

LidarState make_lidar_state(const schedule::ClockedFocalPlane& source, const model::Scene& scene,
                            const sensor::CameraModel& camera,
                            const radiometry::Convergence& convergence, const Context& context) {
    const model::Instrument& instrument = *source.instrument;
    const model::FocalPlane& fp = *source.focal_plane;
    if (!instrument.transmitter) {
        throw input_error("a lidar instrument needs a <transmitter>", instrument.where);
    }
    const model::Transmitter& t = *instrument.transmitter;
    const std::optional<double> g_number = model::g_number(instrument.properties);
    if (!g_number) {
        throw input_error("lidar receiver \"" + fp.name +
                              "\" needs a collecting aperture: give <focallength> (mm) and "
                              "<aperturediameter> (m) in the instrument's <properties>",
                          instrument.properties.where);
    }
    if (!fp.truth_collections.empty()) {
        throw input_error(
            "glint collects no truth for a lidar receiver: remove the "
            "<truthcollection> of \"" +
                fp.name + "\"",
            fp.truth_collections.front().where);
    }
    const model::CaptureMethod& method = fp.capture_method;
    if (!method.signal_gate)
        throw input_error("a lidar capture needs a <signalgate>", method.where);
    const model::SignalGate& g = *method.signal_gate;
    const std::uint64_t bins = g.bin_count();
    radiometry::TimeGate gate{g.start_s, g.bin_width_s / g.samples_per_bin,
                              static_cast<std::size_t>(bins * g.samples_per_bin)};
    SpectralGrid laser_grid({t.wavelength_um}, t.where);
    radiometry::MaterialTable laser_materials(scene.materials, laser_grid, context.log);
    const double qe = method.detector_model ? method.detector_model->quantum_efficiency : 1.0;
    const double element_cm2 = camera.element_size_m()[0] * camera.element_size_m()[1] * 1e4;
    return LidarState{&t,
                      pulse_shape_of(t),
                      gate,
                      g,
                      std::move(laser_grid),
                      std::move(laser_materials),
                      element_cm2 / *g_number * qe * photons_per_joule(t.wavelength_um),
                      element_cm2 * qe,
                      convergence.max_samples};
}

void plan_bin_file(const RenderInputs& inputs, const FocalPlaneState& state,
                   std::size_t source_index, const std::filesystem::path& path,
                   const std::vector<const PlannedCapture*>& captures, const RenderOptions& options,
                   ImageOutputs& outputs) {
    const schedule::ClockedFocalPlane& source = inputs.schedule->sources()[source_index];
    const schedule::PluginSchedule& plugin = inputs.schedule->plugins()[source.plugin];
    const model::Transmitter& t = *state.lidar->transmitter;
    const model::InstrumentPath& chain = plugin.poses->instrument_path(source.instrument_index);
    const std::string mount = chain.mounts.empty() ? "static" : chain.mounts.back()->type_text;
    io::BinFileHeader h;
    h.created = bin_datetime(plugin.tasks.reference, captures.front()->capture.t0_s);
    h.dirsig_version = "glint " + options.version;
    h.description = "glint-render lidar capture of " + source.instrument->name + " -> " +
                    source.focal_plane->name;
    const motion::Geodetic& origin = inputs.frame.origin();
    h.origin_latitude_deg = origin.latitude_deg;
    h.origin_longitude_deg = origin.longitude_deg;
    h.origin_height_m = origin.altitude_m;
    h.transmitter_mount = mount;
    h.receiver_mount = mount;
    h.x_count = static_cast<std::uint32_t>(source.x_count);
    h.y_count = static_cast<std::uint32_t>(source.y_count);
    h.x_pitch_m = state.camera.pitch_m()[0];
    h.y_pitch_m = state.camera.pitch_m()[1];
    h.x_offset_m = source.focal_plane->detector_array.x_offset_m;
    h.y_offset_m = source.focal_plane->detector_array.y_offset_m;
    if (const auto& d = source.instrument->properties.distortion) {
        h.k1 = d->k1;
        h.k2 = d->k2;
    }
    h.focal_plane_id = static_cast<std::uint16_t>(source.focal_plane_index);
    // One task header per task of the file's pulses, in order.
    std::vector<std::pair<io::BinTaskHeader, std::uint32_t>> tasks;
    for (std::size_t i = 0; i < captures.size();) {
        std::size_t j = i;
        while (j < captures.size() &&
               captures[j]->capture.task_index == captures[i]->capture.task_index) {
            ++j;
        }
        const std::vector<const PlannedCapture*> pulses(captures.begin() + i, captures.begin() + j);
        const model::Task& task = plugin.tasks.tasks[captures[i]->capture.task_index];
        io::BinTaskHeader th;
        th.description = task.name.empty()
                             ? "task " + std::to_string(captures[i]->capture.task_index + 1)
                             : task.name;
        th.start = bin_datetime(plugin.tasks.reference, task.start_s);
        th.stop = bin_datetime(plugin.tasks.reference, task.stop_s);
        th.focal_length_mm = source.instrument->properties.focal_length_m.value_or(0.0) * 1e3;
        th.pulse_rate_hz = pulse_rate_hz(t, source, pulses);
        th.pulse_duration_s = t.pulse_duration_s;
        th.pulse_energy_j = t.pulse_energy_j;
        th.laser_center_um = t.wavelength_um;
        th.laser_width_um = t.spectral_width_um;
        tasks.emplace_back(th, static_cast<std::uint32_t>(pulses.size()));
        i = j;
    }
    outputs.plan_bin(path, h, std::move(tasks));
}

CaptureReport render_pulse(const RenderPlan& plan, ImageOutputs& outputs, const PlannedCapture& p,
                           const scene::GeometryScene& geometry,
                           radiometry::SensorPathCache& path_cache,
                           radiometry::SensorPathCache& laser_cache, const RenderOptions& options,
                           const Context& context) {
    const RenderInputs& in = plan.inputs;
    Context quiet = context;
    quiet.progress = Progress{};
    const auto started = std::chrono::steady_clock::now();
    schedule::Capture capture = p.capture;
    capture.t1_s = capture.t0_s;  // a pulse is an instant; the passive term a rate at it
    const schedule::ClockedFocalPlane& source = in.schedule->sources()[capture.source];
    const schedule::PluginSchedule& plugin = in.schedule->plugins()[source.plugin];
    const FocalPlaneState& state = plan.states.at(capture.source);
    const LidarState& lidar = *state.lidar;
    const motion::PoseService& poses = *plugin.poses;
    if (context.log.enabled(LogLevel::info)) {
        context.log.info("Starting pulse: Task #" + std::to_string(capture.task_index + 1) +
                         ", Pulse #" + std::to_string(capture.capture_index + 1) + ", Event #" +
                         std::to_string(p.event_number) + " of " + std::to_string(p.event_count));
        context.log.info("    " + source.instrument->name + " -> " + source.focal_plane->name +
                         ", relative time = " + format_shortest(capture.t0_s) + " s");
    }
    const std::size_t pixels = source.problems_per_capture;
    const std::size_t values = 1 + lidar.gate.samples;
    // Problem i is pixel (i mod x_count, i div x_count), row after row; the file holds x slowest.
    const auto offset = [&](std::size_t i) {
        return io::bin_pixel_index(i % source.x_count, i / source.x_count, source.y_count) * values;
    };
    io::BinPulse pulse;
    pulse.data.assign(pixels * values, 0.0);
    CaptureReport stats;

    const sensor::CaptureTiming timing{capture.t0_s, capture.t0_s, 0.0, 1};
    const sensor::PixelRaySource rays(state.camera, poses, source.instrument_index, timing,
                                      state.psf ? &*state.psf : nullptr,
                                      state.mask ? &*state.mask : nullptr);
    const double share = state.mask ? state.mask->mean_sensitivity() : 1.0;
    const radiometry::StreamKey key{options.schedule.seed, plugin.plugin_index, capture.task_index,
                                    capture.index, std::nullopt};

    // The passive term: photons/s per pixel in the receiver's band.
    {
        const radiometry::Environment environment = capture_environment(
            in, state.grid, capture, source, geometry, path_cache, context.threads);
        const radiometry::PointLights lights =
            in.light->point_lights_at(in.scene, state.grid, capture.t0_s);
        const radiometry::PathTracer tracer(geometry, state.materials, environment, options.tracer,
                                            lights.empty() ? nullptr : &lights);
        radiometry::ProblemBatch batch;
        batch.key = key;
        batch.source = &rays;
        batch.convergence = state.convergence;
        batch.reference_band = state.reference_band;
        batch.count = pixels;
        const radiometry::Solutions solutions = radiometry::solve(tracer, batch, quiet);
        const sensor::SeenPointSources seen = sensor::seen_point_sources(
            state.camera, poses, source.instrument_index, timing, state.psf ? &*state.psf : nullptr,
            state.mask ? &*state.mask : nullptr, lights, geometry, environment);
        std::vector<double> rate(state.units.channels());
        std::vector<double> radiance(state.grid.size());
        for (std::size_t i = 0; i < pixels; ++i) {
            const std::span<const double> solved = solutions.radiance(i);
            radiance.assign(solved.begin(), solved.end());
            seen.add_to(i, 0, radiance);  // the sources the pixel sees, as in an image
            state.units.apply(radiance, rate);
            pulse.data[offset(i)] = rate.front() * share * lidar.passive_per_focal_plane_rate;
        }
        stats.rays += solutions.rays;
    }

    // The returns: the laser fires from the instrument's origin along its boresight.
    const motion::Rigid instrument =
        poses.instrument_to_scene(source.instrument_index, capture.t0_s);
    radiometry::LaserPulse laser;
    laser.position_m = instrument.translation_m;
    laser.axis = motion::normalized(motion::apply_direction(instrument, {0.0, 0.0, -1.0}));
    laser.divergence_rad = lidar.transmitter->beam_divergence_rad;
    laser.energy_j = lidar.transmitter->pulse_energy_j;
    // The atmosphere both ways at the laser line, along the boresight.
    const radiometry::Environment laser_environment = capture_environment(
        in, lidar.laser_grid, capture, source, geometry, laser_cache, context.threads);
    double two_way = 1.0;
    if (laser_environment.has_sensor_path()) {
        std::vector<double> transmittance(1);
        std::vector<double> path_radiance(1);
        laser_environment.sensor_path(-laser.axis, capture.t0_s, transmittance, path_radiance);
        two_way = transmittance[0] * transmittance[0];
    }
    const radiometry::LidarTracer tracer(geometry, lidar.laser_materials, options.tracer,
                                         lidar.shape, lidar.gate);
    radiometry::ReturnBatch batch;
    batch.key = key;
    batch.key.spectral_state = kReturnsStream;
    batch.source = &rays;
    batch.count = pixels;
    batch.samples = lidar.samples_per_pixel;
    const radiometry::Returns returns = radiometry::solve_returns(tracer, laser, batch, quiet);
    const double factor = lidar.photons_per_energy_radiance * two_way * share;
    for (std::size_t i = 0; i < pixels; ++i) {
        for (std::size_t j = 0; j < lidar.gate.samples; ++j) {
            pulse.data[offset(i) + 1 + j] =
                returns.energy_j_per_cm2_sr[i * lidar.gate.samples + j] * factor;
        }
    }
    stats.rays += returns.rays;

    // The pulse header: where everything was at the pulse.
    const motion::Pose vehicle = poses.vehicle_pose(capture.t0_s);
    pulse.time_s = capture.t0_s;
    pulse.gate_start_s = lidar.signal_gate.start_s;
    pulse.gate_stop_s = lidar.signal_gate.stop_s;
    pulse.bin_count = static_cast<std::uint32_t>(lidar.signal_gate.bin_count());
    pulse.samples_per_bin = lidar.signal_gate.samples_per_bin;
    pulse.platform_location = motion::to_array(vehicle.position_m);
    pulse.platform_rotation = motion::to_array(
        motion::quaternion_to_euler(vehicle.orientation, poses.platform_rotation_order()));
    const io::Affine16 to_platform =
        affine_of(poses.instrument_to_vehicle(source.instrument_index, capture.t0_s));
    pulse.transmitter_mount_to_platform = to_platform;
    pulse.receiver_mount_to_platform = to_platform;
    pulse.pulse_index = static_cast<std::uint32_t>(capture.capture_index);
    outputs.write_pulse(p.file, pulse);

    stats.index = capture.index;
    stats.pixels = pixels;
    stats.min_samples = lidar.samples_per_pixel;
    stats.max_samples = lidar.samples_per_pixel;
    stats.mean_samples = static_cast<double>(lidar.samples_per_pixel);
    stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return stats;
}

}  // namespace glint::render::detail
