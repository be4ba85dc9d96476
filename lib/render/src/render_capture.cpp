// SPDX-License-Identifier: Apache-2.0
// One capture: DIRSIG's console block, the environment at the capture's time, one problem
// per pixel through the path tracer, the output units, the lines appended to the file.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <future>
#include <memory>
#include <string>
#include <vector>

#include "glint/core/datetime.h"
#include "glint/core/text.h"
#include "render_parts.h"

namespace glint::render::detail {
namespace {

std::string bandpass_line(const SpectralGrid& grid) {
    char text[160];
    const double delta = grid.size() > 1 ? grid.wavelength_um(1) - grid.wavelength_um(0) : 0.0;
    std::snprintf(text, sizeof text, "Bandpass = %.6f - %.6f @ %.6f microns (%zu samples)",
                  grid.min_um(), grid.max_um(), delta, grid.size());
    return text;
}

/// The sun's and the moon's state at the run's first capture, as DIRSIG's console shows it
/// before its first capture (its "declination" column is the zenith angle;
/// docs/tools/glint-render.md).
void log_ephemeris(const DateTime& when, const radiometry::Illumination& light,
                   const Context& context) {
    const motion::SunPosition sun = light.sun_at(when);
    const motion::MoonPosition moon = light.moon_at(when);
    char line[128];
    context.log.info("Solar state update notification from 'glint ephemeris (NREL SPA)'");
    std::snprintf(line, sizeof line,
                  "    %.3f [degrees, declination], %.3f [degrees, East of North]", sun.zenith_deg,
                  sun.azimuth_deg);
    context.log.info(line);
    context.log.info("Lunar state update notification from 'glint ephemeris (Meeus)'");
    std::snprintf(line, sizeof line,
                  "    %.3f [degrees, declination], %.3f [degrees, East of North]", moon.zenith_deg,
                  moon.azimuth_deg);
    context.log.info(line);
    std::snprintf(line, sizeof line, "    %.3f [phase fraction]", moon.phase_fraction);
    context.log.info(line);
}

void log_capture_start(const PlannedCapture& p, const schedule::ClockedFocalPlane& source,
                       const FocalPlaneState& state, const DateTime& reference,
                       const radiometry::Illumination& light, const Context& context) {
    if (!context.log.enabled(LogLevel::info)) return;
    if (p.event_number == 1) log_ephemeris(add_seconds(reference, p.capture.t0_s), light, context);
    char relative[64];
    std::snprintf(relative, sizeof relative, "%e", p.capture.t0_s);
    context.log.info("Starting capture: Task #" + std::to_string(p.capture.task_index + 1) +
                     ", Capture #" + std::to_string(p.capture.capture_index + 1) + ", Event #" +
                     std::to_string(p.event_number) + " of " + std::to_string(p.event_count));
    context.log.info(
        "    Date/Time = " + format_iso8601_local(add_seconds(reference, p.capture.t0_s), 4) +
        ", relative time = " + relative);
    context.log.info("    " + source.instrument->name + " -> " + source.focal_plane->name);
    context.log.info("        " + bandpass_line(state.grid));
    context.log.info("        Array size = " + std::to_string(source.x_count) + " x " +
                     std::to_string(source.y_count));
}

/// Turns one pixel's solved radiance into its channel values in `out` (units.channels()
/// values): every channel for the focal plane's one state, its own channel for a split state.
/// A masked element's radiance is its mean sensitivity's share (active_area.h). `radiance`
/// is the solving thread's buffer, scaled in place.
/// `nonzero`: the bands outside of which `radiance` is 0 (ascending; empty: any band).
void store_channels(const FocalPlaneState& state, const SpectralState& spectral,
                    std::span<double> radiance, std::span<const std::uint32_t> nonzero,
                    std::span<double> out) {
    const double share = state.mask ? state.mask->mean_sensitivity() : 1.0;
    if (share != 1.0) {
        if (nonzero.empty()) {
            for (double& value : radiance) value *= share;
        } else {
            for (const std::uint32_t b : nonzero) radiance[b] *= share;
        }
    }
    if (spectral.channel) {
        out[*spectral.channel] =
            state.units.channel_value(*spectral.channel, spectral.bands.first, radiance);
    } else {
        state.units.apply(radiance, nonzero, out);
    }
}

}  // namespace

double capture_sensor_height_m(const RenderInputs& in, const schedule::Capture& capture,
                               const schedule::ClockedFocalPlane& source) {
    const schedule::PluginSchedule& plugin = in.schedule->plugins()[source.plugin];
    const double mid = 0.5 * (capture.t0_s + capture.t1_s);
    return plugin.poses->instrument_to_scene(source.instrument_index, mid).translation_m.z;
}

radiometry::Environment capture_environment(const RenderInputs& in, const SpectralGrid& grid,
                                            const schedule::Capture& capture,
                                            const schedule::ClockedFocalPlane& source,
                                            const scene::GeometryScene& geometry,
                                            radiometry::SensorPathCache& cache, unsigned threads) {
    const schedule::PluginSchedule& plugin = in.schedule->plugins()[source.plugin];
    return in.light->environment(grid, {plugin.tasks.reference, capture.t0_s, capture.t1_s},
                                 capture_sensor_height_m(in, capture, source),
                                 radiometry::altitude_levels(geometry), threads, &cache);
}

CaptureReport render_capture(const RenderPlan& plan, ImageOutputs& outputs, const PlannedCapture& p,
                             const scene::GeometryScene& geometry,
                             radiometry::SensorPathCache& path_cache, const RenderOptions& options,
                             const Context& context, std::vector<double>& image) {
    const RenderInputs& in = plan.inputs;
    Context quiet = context;  // solve() reports nothing: progress is per pixel over captures
    quiet.progress = Progress{};
    const auto started = std::chrono::steady_clock::now();
    const schedule::Capture& capture = p.capture;
    const schedule::ClockedFocalPlane& source = in.schedule->sources()[capture.source];
    const schedule::PluginSchedule& plugin = in.schedule->plugins()[source.plugin];
    const FocalPlaneState& state = plan.states.at(capture.source);
    log_capture_start(p, source, state, plugin.tasks.reference, *in.light, context);

    // The light of the capture: the sun or moon through the atmosphere, the point sources.
    const radiometry::Environment environment =
        capture_environment(in, state.grid, capture, source, geometry, path_cache, context.threads);
    // Point sources sit where they are at mid-window (docs/physics.md, "Point sources").
    const radiometry::PointLights lights =
        in.light->point_lights_at(in.scene, state.grid, 0.5 * (capture.t0_s + capture.t1_s));
    // What the camera sees: its rays, the pixels to hypersample, the sources seen, truth.
    sensor::CaptureTiming timing{capture.t0_s, capture.t1_s,
                                 source.rolling_line_time_s().value_or(0.0), source.tdi_stages};
    const sensor::PixelRaySource rays(state.camera, *plugin.poses, source.instrument_index, timing,
                                      state.psf ? &*state.psf : nullptr,
                                      state.mask ? &*state.mask : nullptr);
    // Refraction: each spectral state's view rays bent at its reference band's wavelength
    // (a split render's channels each their own; docs/physics.md, "Refraction in the
    // renderer").
    const double sensor_z_m = capture_sensor_height_m(in, capture, source);
    std::vector<std::shared_ptr<const radiometry::ViewRefraction>> views;
    std::vector<std::unique_ptr<const radiometry::RefractedRaySource>> bent_rays;
    for (const SpectralState& spectral : state.spectral_states) {
        views.push_back(in.light->view_refraction(state.grid.wavelength_um(spectral.reference_band),
                                                  sensor_z_m, &path_cache));
        bent_rays.push_back(views.back() ? std::make_unique<const radiometry::RefractedRaySource>(
                                               rays, *views.back())
                                         : nullptr);
    }
    radiometry::ProblemBatch batch;
    // The capture's global schedule index: unique per focal plane and capture, so focal
    // planes imaging at the same moment draw independent numbers.
    batch.key = {options.schedule.seed, plugin.plugin_index, capture.task_index, capture.index,
                 std::nullopt};
    batch.source = &rays;
    batch.convergence = state.convergence;
    // Only the capture's lines first_line … end_line − 1 (--rows): the problems keep their
    // indices in the capture, so their random streams are those of the whole render.
    batch.first_problem = p.first_problem(source);
    batch.count = p.problems(source);
    const double multiplier =
        source.focal_plane->capture_method.sample_strategy.hypersampling_multiplier;
    std::vector<std::uint8_t> important;
    if (multiplier > 1.0) {
        important = sensor::hypersampled_pixels(in.scene, geometry, state.camera, *plugin.poses,
                                                source.instrument_index, timing,
                                                state.psf ? state.psf->reach_px() : 0.0);
        if (!important.empty()) {  // empty: nothing important in view
            batch.hypersampled = std::span<const std::uint8_t>(important).subspan(
                static_cast<std::size_t>(batch.first_problem),
                static_cast<std::size_t>(batch.count));
        }
        batch.hypersampling_multiplier = multiplier;
    }
    const std::size_t channels = state.units.channels();
    const sensor::TruthContext truth_context{
        &in.scene,    &state.materials,     &in.frame,
        &state.units, state.reference_band, state.mask ? state.mask->mean_sensitivity() : 1.0};
    // What the pixels see of the sources themselves (a source is a point: no ray hits it).
    const sensor::SeenPointSources seen = sensor::seen_point_sources(
        state.camera, *plugin.poses, source.instrument_index, timing,
        state.psf ? &*state.psf : nullptr, state.mask ? &*state.mask : nullptr, lights, geometry,
        environment);
    std::vector<radiometry::PathTracer> tracers;
    tracers.reserve(state.spectral_states.size());
    for (const SpectralState& spectral : state.spectral_states) {
        tracers.emplace_back(geometry, state.materials, environment, options.tracer, spectral.bands,
                             lights.empty() ? nullptr : &lights);
    }
    const CaptureStamp stamp{capture.task_index,
                             capture.capture_index,
                             capture.t0_s,
                             capture.t1_s,
                             format_iso8601_utc(add_seconds(plugin.tasks.reference, capture.t0_s)),
                             capture.index};
    // The capture is solved, reduced and written a band of lines at a time (about
    // kBlockPixels pixels): a pixel's spectrum lives only while its thread reduces it to
    // channels, and only two bands' channels and truth are held, whatever the frame's size:
    // one band is detected and written on a thread of its own while the next is solved.
    const std::uint64_t per_line = source.problems_per_capture / source.lines_per_capture();
    const std::uint64_t band_lines = block_lines(source);
    const radiometry::ProblemBatch capture_batch = batch;
    CaptureReport stats;
    std::uint64_t least = UINT64_MAX;
    std::uint64_t most = 0;
    double total = 0.0;
    std::vector<std::uint64_t> samples;  // per pixel of the band, over the states
    std::vector<double> truth;
    // The band being detected and written while the next is solved: its values and truth,
    // the detection's output, and the job (declared after the buffers it uses, so that an
    // error unwinding from a solve waits for the job before they go).
    std::vector<double> out_image;
    std::vector<double> out_truth;
    std::vector<double> detected;
    std::future<void> writing;
    const auto write_band = [&](std::uint64_t first, std::uint64_t lines) {
        if (state.detection) {
            // Detection line by line, keyed like glint-detect: (capture index, line in
            // capture).
            const detect::DetectionChain& chain = *state.detection;
            detected.assign(chain.output_values_per_line() * lines, 0.0);
            for (std::size_t line = 0; line < lines; ++line) {
                chain.process_line(
                    {capture.index, first + line},
                    std::span<const double>(out_image).subspan(line * chain.input_values_per_line(),
                                                               chain.input_values_per_line()),
                    std::span<double>(detected).subspan(line * chain.output_values_per_line(),
                                                        chain.output_values_per_line()));
            }
        }
        outputs.write_lines(p.file, state.detection ? detected : out_image);
        for (std::size_t t = 0; t < p.truth_files.size(); ++t) {
            outputs.write_lines(
                p.truth_files[t],
                sensor::truth_file_values(state.truth, state.truth.files[t], out_truth));
        }
    };
    for (std::uint64_t first = p.first_line; first < p.end_line; first += band_lines) {
        const std::uint64_t lines = std::min(band_lines, p.end_line - first);
        batch.first_problem = first * per_line;
        batch.count = lines * per_line;
        if (!capture_batch.hypersampled.empty()) {
            batch.hypersampled = capture_batch.hypersampled.subspan(
                static_cast<std::size_t>(batch.first_problem - capture_batch.first_problem),
                static_cast<std::size_t>(batch.count));
        }
        image.assign(batch.count * channels, 0.0);
        samples.assign(batch.count, 0);
        // Truth, from the same samples: the first state's first hits, each state's errors.
        truth.assign(state.truth.empty() ? 0 : batch.count * state.truth.bands.size(), 0.0);
        for (std::size_t k = 0; k < state.spectral_states.size(); ++k) {
            const SpectralState& spectral = state.spectral_states[k];
            batch.key.spectral_state = spectral.channel;
            batch.source = bent_rays[k]
                               ? static_cast<const radiometry::RaySource*>(bent_rays[k].get())
                               : &rays;
            batch.reference_band = spectral.reference_band - spectral.bands.first;
            std::optional<sensor::TruthObserver> observer;
            if (!state.truth.empty()) {
                observer.emplace(state.truth, truth_context, spectral.bands, spectral.channel,
                                 k == 0, batch.first_problem, truth);
            }
            batch.observer = observer ? &*observer : nullptr;
            // Each pixel is reduced to its channels as soon as it is solved, on its thread.
            stats.rays += radiometry::solve_each(
                tracers[k], batch, quiet,
                [&](std::uint64_t i, std::span<double> radiance,
                    std::span<const std::uint32_t> nonzero, std::uint64_t n, double) {
                    // A seen source reaches every band: the pixel is then integrated whole.
                    if (seen.add_to(batch.first_problem + i, spectral.bands.first, radiance)) {
                        nonzero = {};
                    }
                    store_channels(state, spectral, radiance, nonzero,
                                   std::span<double>(image).subspan(i * channels, channels));
                    samples[i] += n;
                });
        }
        for (const std::uint64_t n : samples) {
            least = std::min(least, n);
            most = std::max(most, n);
            total += static_cast<double>(n);
        }
        // The previous band's write must be done (its error, if any, surfaces here) before
        // this band takes its buffers.
        if (writing.valid()) writing.get();
        image.swap(out_image);
        truth.swap(out_truth);
        if (first + lines >= p.end_line) {
            write_band(first, lines);  // the last band: nothing left to overlap with
        } else {
            writing = std::async(std::launch::async, write_band, first, lines);
        }
    }
    if (writing.valid()) writing.get();
    outputs.end_capture(p.file, stamp);
    for (const auto& file : p.truth_files) outputs.end_capture(file, stamp);
    stats.index = capture.index;
    stats.pixels = p.problems(source);
    if (stats.pixels > 0) {
        stats.min_samples = least;
        stats.max_samples = most;
        stats.mean_samples = total / static_cast<double>(stats.pixels);
    }
    stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    context.log.info("    Samples per pixel (min/mean/max) = " + std::to_string(stats.min_samples) +
                     " / " + format_shortest(stats.mean_samples) + " / " +
                     std::to_string(stats.max_samples));
    char took[96];
    std::snprintf(took, sizeof took, "    Rendered in %.3f s (%llu rays)", stats.seconds,
                  static_cast<unsigned long long>(stats.rays));
    context.log.info(took);
    return stats;
}

}  // namespace glint::render::detail
