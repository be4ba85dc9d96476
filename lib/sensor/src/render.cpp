// SPDX-License-Identifier: Apache-2.0
// The capture loop (glint/sensor/render.h).
#include "glint/sensor/render.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <sstream>
#include <string>

#include "glint/core/atomic_file.h"
#include "glint/core/datetime.h"
#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/motion/sun.h"
#include "glint/radiometry/environment.h"
#include "glint/schedule/capture_list.h"
#include "glint/sensor/image_outputs.h"
#include "render_parts.h"

namespace glint::sensor {
namespace {

using detail::FocalPlaneState;
using detail::RenderInputs;

/// A capture of the selection with what the loop needs about it.
struct PlannedCapture {
    schedule::Capture capture;
    std::filesystem::path file;
    std::uint64_t event_number = 0;
    std::uint64_t event_count = 0;
};

/// The selected captures in schedule order, skipping (with one info line each) the sources
/// glint-render does not render.
std::vector<PlannedCapture> select_captures(const RenderInputs& in, const RenderOptions& options,
                                            const Context& context) {
    const schedule::Schedule& schedule = *in.schedule;
    const auto& sources = schedule.sources();
    std::vector<bool> skip(sources.size(), false);
    for (std::size_t s = 0; s < sources.size(); ++s) {
        std::string why;
        if (!detail::renders(sources[s], why)) {
            skip[s] = true;
            context.log.warning(why + ": not rendered");
        }
    }
    std::map<std::pair<std::size_t, std::size_t>, std::uint64_t> events;  // (plugin, task)
    std::map<std::pair<std::size_t, std::size_t>, std::uint64_t> event_counts;
    for (std::size_t s = 0; s < sources.size(); ++s) {
        const std::size_t tasks = schedule.plugins()[sources[s].plugin].tasks.tasks.size();
        for (std::size_t t = 0; t < tasks; ++t) {
            event_counts[{sources[s].plugin, t}] += schedule.count(s, t);
        }
    }
    std::vector<PlannedCapture> out;
    schedule::Schedule::Generator generator = schedule.captures();
    while (const std::optional<schedule::Capture> capture = generator.next()) {
        if ((capture->index & 0x3FF) == 0) context.cancel.throw_if_cancelled();
        const std::pair key{sources[capture->source].plugin, capture->task_index};
        const std::uint64_t event = ++events[key];
        if (skip[capture->source]) continue;
        if (!options.only_captures.empty() && !options.only_captures.contains(capture->index)) {
            continue;
        }
        out.push_back({*capture, schedule.image_file(*capture), event, event_counts[key]});
    }
    if (!options.only_captures.empty()) {
        std::set<std::uint64_t> found;
        for (const PlannedCapture& p : out) found.insert(p.capture.index);
        for (std::uint64_t wanted : options.only_captures) {
            if (!found.contains(wanted)) {
                throw input_error("capture " + std::to_string(wanted) +
                                  " of the --schedule selection is not a rendered capture of " +
                                  schedule.simulation_file().string());
            }
        }
    }
    return out;
}

std::string bandpass_line(const SpectralGrid& grid) {
    char text[160];
    const double delta = grid.size() > 1 ? grid.wavelength_um(1) - grid.wavelength_um(0) : 0.0;
    std::snprintf(text, sizeof text, "Bandpass = %.6f - %.6f @ %.6f microns (%zu samples)",
                  grid.min_um(), grid.max_um(), delta, grid.size());
    return text;
}

void log_capture_start(const PlannedCapture& p, const schedule::Source& source,
                       const FocalPlaneState& state, const DateTime& reference,
                       const Context& context) {
    if (!context.log.enabled(LogLevel::info)) return;
    char relative[64];
    std::snprintf(relative, sizeof relative, "%e", p.capture.t0_s);
    context.log.info("Starting capture: Task #" + std::to_string(p.capture.task_index + 1) +
                     ", Capture #" + std::to_string(p.capture.capture_index + 1) + ", Event #" +
                     std::to_string(p.event_number) + " of " + std::to_string(p.event_count));
    context.log.info("    Date/Time = " +
                     format_iso8601_local(add_seconds(reference, p.capture.t0_s), 4) +
                     ", relative time = " + relative);
    context.log.info("    " + source.instrument->name + " -> " + source.focal_plane->name);
    context.log.info("        " + bandpass_line(state.grid));
    context.log.info("        Array size = " + std::to_string(source.x_count) + " x " +
                     std::to_string(source.y_count));
}

/// The environment of one capture: sun at both ends of the window seen from the scene
/// origin, sensor altitude from the instrument's position at mid-window.
radiometry::Environment capture_environment(const RenderInputs& in, const FocalPlaneState& state,
                                            const schedule::Capture& capture,
                                            const schedule::Source& source,
                                            radiometry::SensorPathCache& cache) {
    const schedule::PluginSchedule& plugin = in.schedule->plugins()[source.plugin];
    const DateTime& reference = plugin.tasks.reference;
    const motion::SunPosition sun0 =
        motion::sun_position(add_seconds(reference, capture.t0_s), in.frame);
    const motion::SunPosition sun1 =
        motion::sun_position(add_seconds(reference, capture.t1_s), in.frame);
    const double mid = 0.5 * (capture.t0_s + capture.t1_s);
    const motion::Rigid pose = plugin.poses->instrument_to_scene(source.instrument_index, mid);
    radiometry::EnvironmentInputs env;
    env.sun_direction_begin = sun0.direction_enu;
    env.sun_direction_end = sun1.direction_enu;
    env.window_begin_s = capture.t0_s;
    env.window_end_s = capture.t1_s;
    env.sun_distance_au = sun0.distance_au;
    env.surface_altitude_m = in.frame.origin().altitude_m;
    env.sensor_altitude_m = in.frame.origin().altitude_m + pose.translation_m.z;
    return radiometry::Environment::make(state.grid, *in.atmosphere_model, *in.sun, env, &cache);
}

scene::BuildOptions build_options(const RenderOptions& options, double t0_s, double t1_s) {
    scene::BuildOptions b;
    b.device = options.device;
    b.window = {t0_s, t1_s};
    return b;
}

/// Plans every output file with its header and capture count.
void plan_outputs(const RenderInputs& in, const std::vector<PlannedCapture>& captures,
                  std::map<std::size_t, FocalPlaneState>& states, const RenderOptions& options,
                  const Context& context, ImageOutputs& outputs) {
    std::map<std::filesystem::path, std::pair<std::size_t, std::uint64_t>> files;
    for (const PlannedCapture& p : captures) {
        auto& entry = files[p.file];
        entry.first = p.capture.source;
        ++entry.second;
    }
    for (const auto& [path, entry] : files) {
        const std::size_t source = entry.first;
        if (!states.contains(source)) {
            states.emplace(source, detail::make_focal_plane_state(in, source, options, context));
        }
        const schedule::Source& s = in.schedule->sources()[source];
        outputs.plan(path, states.at(source).header, s.y_count, entry.second);
    }
}

RenderReport prepare(const std::filesystem::path& simulation_file, const RenderOptions& options,
                     const Context& context, RenderInputs& in,
                     std::vector<PlannedCapture>& captures,
                     std::map<std::size_t, FocalPlaneState>& states, ImageOutputs& outputs) {
    in = detail::load_inputs(simulation_file, options, context);
    captures = select_captures(in, options, context);
    plan_outputs(in, captures, states, options, context, outputs);
    RenderReport report;
    report.files = outputs.planned();
    std::uint64_t triangles = 0;
    for (const model::Instance& instance : in.scene.instances) {
        triangles += in.scene.objects[instance.object_index].mesh.triangles.size();
    }
    std::uint64_t largest = 0;
    for (const PlannedCapture& p : captures) {
        const schedule::Source& s = in.schedule->sources()[p.capture.source];
        report.pixels += s.problems_per_capture;
        const std::uint64_t bands = states.at(p.capture.source).grid.size() +
                                    states.at(p.capture.source).units.channels();
        largest = std::max<std::uint64_t>(largest, s.problems_per_capture * bands * 8);
    }
    report.memory_estimate_bytes = triangles * 85 + largest;
    return report;
}

/// Writes the capture list of the run (--log_info_filename), atomically.
void write_log_info(const RenderInputs& in, const std::vector<PlannedCapture>& captures,
                    const RenderOptions& options) {
    if (options.log_info_file.empty()) return;
    std::ostringstream text;
    schedule::CaptureListWriter list(
        text, *in.schedule,
        schedule::CaptureListProvenance{"glint-render", options.arguments, options.schedule.seed});
    list.begin();
    for (const PlannedCapture& p : captures) {
        list.add(p.capture, p.file, in.schedule->truth_files(p.capture));
    }
    list.end();
    write_file_atomically(options.log_info_file, text.str());
}

}  // namespace

RenderReport plan(const std::filesystem::path& simulation_file, const RenderOptions& options,
                  const Context& context) {
    RenderInputs in;
    std::vector<PlannedCapture> captures;
    std::map<std::size_t, FocalPlaneState> states;
    ImageOutputs outputs;
    RenderReport report = prepare(simulation_file, options, context, in, captures, states, outputs);
    for (const PlannedCapture& p : captures) {
        CaptureReport c;
        c.index = p.capture.index;
        c.pixels = in.schedule->sources()[p.capture.source].problems_per_capture;
        report.captures.push_back(c);
    }
    write_log_info(in, captures, options);
    return report;
}

RenderReport render(const std::filesystem::path& simulation_file, const RenderOptions& options,
                    const Context& context) {
    RenderInputs in;
    std::vector<PlannedCapture> captures;
    std::map<std::size_t, FocalPlaneState> states;
    ImageOutputs outputs;
    RenderReport report = prepare(simulation_file, options, context, in, captures, states, outputs);

    std::optional<scene::GeometryScene> static_scene;
    if (!in.dynamic_scene) {
        static_scene.emplace(scene::GeometryScene::build(in.scene, in.trajectories,
                                                         build_options(options, 0.0, 0.0),
                                                         context.log));
        report.device = static_scene->device();
    }
    Context quiet = context;  // solve() reports nothing: progress is per pixel over captures
    quiet.progress = Progress{};
    std::uint64_t pixels_done = 0;
    std::vector<double> image;
    std::map<std::size_t, radiometry::SensorPathCache> path_caches;  // per focal plane
    for (const PlannedCapture& p : captures) {
        context.cancel.throw_if_cancelled();
        const auto started = std::chrono::steady_clock::now();
        const schedule::Capture& capture = p.capture;
        const schedule::Source& source = in.schedule->sources()[capture.source];
        const schedule::PluginSchedule& plugin = in.schedule->plugins()[source.plugin];
        const FocalPlaneState& state = states.at(capture.source);
        log_capture_start(p, source, state, plugin.tasks.reference, context);

        std::optional<scene::GeometryScene> moving;
        if (in.dynamic_scene) {
            moving.emplace(scene::GeometryScene::build(
                in.scene, in.trajectories, build_options(options, capture.t0_s, capture.t1_s),
                context.log));
            report.device = moving->device();
        }
        const scene::GeometryScene& geometry = moving ? *moving : *static_scene;
        const radiometry::Environment environment =
            capture_environment(in, state, capture, source, path_caches[capture.source]);
        const radiometry::PathTracer tracer(geometry, state.materials, environment,
                                            options.tracer);
        CaptureTiming timing{capture.t0_s, capture.t1_s,
                             source.focal_plane->detector_array.rolling_line_time_s.value_or(0.0)};
        const PixelRaySource rays(state.camera, *plugin.poses, source.instrument_index, timing);
        radiometry::ProblemBatch batch;
        // The capture's global schedule index: unique per focal plane and capture, so focal
        // planes imaging at the same moment draw independent numbers.
        batch.key = {options.schedule.seed, plugin.plugin_index, capture.task_index,
                     capture.index};
        batch.source = &rays;
        batch.convergence = state.convergence;
        batch.reference_band = state.reference_band;
        batch.count = source.problems_per_capture;
        const double multiplier =
            source.focal_plane->capture_method.sample_strategy.hypersampling_multiplier;
        std::vector<std::uint8_t> important;
        if (multiplier > 1.0) {
            important = detail::hypersampled_pixels(in.scene, geometry, state.camera, *plugin.poses,
                                                    source.instrument_index, timing);
            batch.hypersampled = important;
            batch.hypersampling_multiplier = multiplier;
        }
        const radiometry::Solutions solutions = radiometry::solve(tracer, batch, quiet);

        const std::size_t channels = state.units.channels();
        image.assign(batch.count * channels, 0.0);
        CaptureReport stats;
        stats.index = capture.index;
        stats.pixels = batch.count;
        stats.min_samples = batch.count ? solutions.samples.front() : 0;
        std::uint64_t total_samples = 0;
        for (std::uint64_t i = 0; i < batch.count; ++i) {
            state.units.apply(solutions.radiance(i),
                              std::span<double>(image.data() + i * channels, channels));
            stats.min_samples = std::min(stats.min_samples, solutions.samples[i]);
            stats.max_samples = std::max(stats.max_samples, solutions.samples[i]);
            total_samples += solutions.samples[i];
        }
        stats.mean_samples =
            batch.count ? static_cast<double>(total_samples) / static_cast<double>(batch.count)
                        : 0.0;
        stats.rays = solutions.rays;
        CaptureStamp stamp{capture.task_index, capture.capture_index, capture.t0_s, capture.t1_s,
                           format_iso8601_utc(add_seconds(plugin.tasks.reference, capture.t0_s))};
        outputs.write_capture(p.file, image, stamp);
        stats.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        context.log.info("    Samples per pixel (min/mean/max) = " +
                         std::to_string(stats.min_samples) + " / " +
                         format_shortest(stats.mean_samples) + " / " +
                         std::to_string(stats.max_samples));
        report.captures.push_back(stats);
        pixels_done += batch.count;
        context.progress.update("pixels", pixels_done, report.pixels);
    }
    context.progress.finish("pixels", report.pixels);
    write_log_info(in, captures, options);
    report.files = outputs.published();
    return report;
}

}  // namespace glint::sensor
