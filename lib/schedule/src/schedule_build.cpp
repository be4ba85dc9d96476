// SPDX-License-Identifier: Apache-2.0
// Schedule::build: one pose service per BasicPlatform entry of the loaded simulation, the
// sources (enabled focal planes, pixel counts scaled by --scale_resolution, trigger times as
// the loader read them), a check that no two outputs share a file name, and the tick range of
// every (source, task).
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <utility>

#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/model/output_name.h"
#include "glint/model/platform.h"
#include "glint/model/truth.h"
#include "glint/schedule/schedule.h"
#include "schedule_impl.h"

namespace glint::schedule {

namespace {

/// Largest scaled element count along one axis and of the whole array (the reader's limits).
constexpr double kMaxAxisCount = 1e6;
constexpr double kMaxElementCount = 2147483648.0;  // 2^31

std::string plugin_name(std::size_t plugin_index) {
    return "plugin_list[" + std::to_string(plugin_index) + "]";
}

std::string focal_plane_name(const ClockedFocalPlane& source) {
    return "instrument " + quote(source.instrument->name) + " focal plane " +
           quote(source.focal_plane->name);
}

/// An element count scaled by `factor`: rounded to the nearest integer, at least 1.
double scaled_count(std::size_t count, double factor) {
    return std::max(1.0, std::round(static_cast<double>(count) * factor));
}

/// Sets the source's pixel counts from its detector array and --scale_resolution; false (with
/// an error) when they exceed the reader's limits.
bool set_pixel_counts(ClockedFocalPlane& source, double factor, Diagnostics& diagnostics) {
    const model::DetectorArray& array = source.focal_plane->detector_array;
    // A raw capture writes each element's k_x × k_y sub-pixels as pixels of their own.
    const bool raw = source.focal_plane->capture_method.type == model::CaptureMethodType::raw;
    const double kx = raw ? static_cast<double>(array.x_oversample) : 1.0;
    const double ky = raw ? static_cast<double>(array.y_oversample) : 1.0;
    const double x = scaled_count(array.x_count, factor) * kx;
    const bool tdi = source.focal_plane->capture_method.temporal_integration.tdi;
    // TDI stages are not resolution: --scale_resolution leaves their count alone.
    const double y = tdi ? static_cast<double>(std::max<std::size_t>(array.y_count, 1))
                         : scaled_count(array.y_count, factor) * ky;
    if (x > kMaxAxisCount || y > kMaxAxisCount || x * y > kMaxElementCount) {
        diagnostics.error(array.where,
                          "--scale_resolution " + format_shortest(factor) +
                              (kx * ky > 1.0 ? " and the raw oversampling " + format_shortest(kx) +
                                                   "x" + format_shortest(ky) + " make the "
                                             : std::string(" makes the ")) +
                              std::to_string(array.x_count) + "x" + std::to_string(array.y_count) +
                              " detector array " + std::to_string(static_cast<std::uint64_t>(x)) +
                              "x" + std::to_string(static_cast<std::uint64_t>(y)) +
                              " elements, expected at most 1000000 per axis and 2^31 in all");
        return false;
    }
    source.x_count = static_cast<std::size_t>(x);
    source.y_count = static_cast<std::size_t>(y);
    source.tdi_stages = tdi ? source.y_count : 1;
    source.problems_per_capture = static_cast<std::uint64_t>(source.x_count) *
                                  (tdi ? 1 : static_cast<std::uint64_t>(source.y_count));
    return true;
}

/// Everything Schedule::build works with besides the Impl being filled.
struct Builder {
    const model::Simulation& simulation;
    const ScheduleOptions& options;
    const Log& log;
    Diagnostics& diagnostics;
    detail::ScheduleData& impl;

    void build_plugin(const model::PlatformInputs& inputs);
    void add_sources(std::size_t plugin_slot);
    void check_output_names();
    void compute_ticks();
};

void Builder::build_plugin(const model::PlatformInputs& inputs) {
    const std::size_t plugin_index = inputs.plugin_index;
    const model::Plugin& plugin = simulation.plugins.at(plugin_index);
    std::shared_ptr<const motion::PoseService> poses;
    try {
        poses = std::make_shared<const motion::PoseService>(
            motion::make_pose_service(inputs, options.seed, log, impl.frame, impl.targets.get()));
    } catch (const Error& error) {
        diagnostics.add(error);
        return;
    }

    const model::BasicPlatformInputs& files = *plugin.basic_platform;
    PluginSchedule entry;
    entry.plugin_index = plugin_index;
    entry.output_folder = files.output_folder.value_or(options.output_folder.value_or(""));
    entry.output_prefix = files.output_prefix.value_or(options.output_prefix.value_or(""));
    entry.platform = inputs.platform;
    entry.tasks = inputs.tasks;
    entry.poses = poses;
    for (const model::Task& task : entry.tasks.tasks) {
        if (!std::isfinite(task.start_s) || !std::isfinite(task.stop_s) ||
            task.stop_s < task.start_s) {
            diagnostics.error(task.where, "task window [" + format_shortest(task.start_s) + " s, " +
                                              format_shortest(task.stop_s) +
                                              " s] is not finite with stop >= start");
        }
    }
    impl.plugins.push_back(std::move(entry));
    add_sources(impl.plugins.size() - 1);
}

void Builder::add_sources(std::size_t plugin_slot) {
    const PluginSchedule& entry = impl.plugins[plugin_slot];
    const motion::PoseService& poses = *entry.poses;
    for (std::size_t k = 0; k < poses.instrument_count(); ++k) {
        const model::Instrument& instrument = *poses.instrument_path(k).instrument;
        // A data recorder's own <clock> makes no captures: glint-render samples its pose at
        // the ticks (docs/data-recorder.md); the reader warns about one without a clock.
        if (instrument.type == model::InstrumentType::data_recorder &&
            instrument.focal_planes.empty()) {
            continue;
        }
        for (std::size_t f = 0; f < instrument.focal_planes.size(); ++f) {
            const model::FocalPlane& plane = instrument.focal_planes[f];
            if (!plane.enabled) continue;
            ClockedFocalPlane source;
            source.plugin = plugin_slot;
            source.instrument_index = k;
            source.focal_plane_index = f;
            source.instrument = &instrument;
            source.focal_plane = &plane;
            source.integration_time_s = plane.capture_method.temporal_integration.time_s;
            if (!set_pixel_counts(source, options.scale_resolution, diagnostics)) continue;
            const model::Clock& clock = plane.detector_array.clock;
            if (clock.type == model::ClockType::external_trigger) {
                source.trigger_times_s = clock.trigger_times_s;  // read by the input loader
            }
            impl.sources.push_back(std::move(source));
        }
    }
}

void Builder::check_output_names() {
    struct Owner {
        std::size_t plugin_index;
        std::string what;
    };
    std::map<std::string, Owner> owners;
    const auto claim = [&](const ClockedFocalPlane& source, const model::ImageFile& image,
                           const std::string& what) {
        if (image.basename.empty()) return;
        const PluginSchedule& entry = impl.plugins[source.plugin];
        const std::string name = output_file(image, entry.output_folder, entry.output_prefix, 0, 0)
                                     .lexically_normal()
                                     .string();
        const auto [it, inserted] = owners.emplace(name, Owner{entry.plugin_index, what});
        if (inserted) return;
        const Owner& first = it->second;
        if (first.plugin_index != entry.plugin_index) {
            diagnostics.error(simulation.plugins[entry.plugin_index].where,
                              "output file " + quote(name) + " of " +
                                  plugin_name(entry.plugin_index) + " (" + what +
                                  ") is also written by " + plugin_name(first.plugin_index) + " (" +
                                  first.what +
                                  "): give the BasicPlatform entries different output_prefix "
                                  "or output_folder values");
        } else {
            diagnostics.error(image.where, "output file " + quote(name) + " of " + what +
                                               " is also written by " + first.what +
                                               ", expected different basenames");
        }
    };
    for (const ClockedFocalPlane& source : impl.sources) {
        const std::string plane = focal_plane_name(source);
        claim(source, source.focal_plane->capture_method.image_file, plane);
        for (const model::TruthCollection& truth : source.focal_plane->truth_collections) {
            // One without collectors writes nothing: it claims no name (GUI files leave
            // several empty collections, all named "truth").
            if (!model::writes_truth(truth)) continue;
            claim(source, truth.image_file,
                  "truth collection " + quote(truth.name) + " of " + plane);
        }
    }
}

void Builder::compute_ticks() {
    impl.ticks.resize(impl.sources.size());
    for (std::size_t s = 0; s < impl.sources.size(); ++s) {
        const ClockedFocalPlane& source = impl.sources[s];
        const PluginSchedule& entry = impl.plugins[source.plugin];
        const model::Clock& clock = source.clock();
        std::vector<ClockTicks>& ticks = impl.ticks[s];
        ticks.resize(entry.tasks.tasks.size());
        // A missing or bad trigger file was reported when it was read.
        if (clock.type == model::ClockType::external_trigger && source.trigger_times_s.empty()) {
            continue;
        }
        for (std::size_t t = 0; t < ticks.size(); ++t) {
            const model::Task& task = entry.tasks.tasks[t];
            if (!std::isfinite(task.start_s) || !std::isfinite(task.stop_s) ||
                task.stop_s < task.start_s) {
                continue;  // reported with the task
            }
            try {
                ticks[t] = ClockTicks(clock, entry.platform->clock_table, source.trigger_times_s,
                                      task.start_s, task.stop_s);
            } catch (const Error& error) {
                diagnostics.add(error);
                break;  // the clock is bad: once is enough
            }
            if (ticks[t].empty()) {
                diagnostics.warning(
                    task.where, plugin_name(entry.plugin_index) + " " + focal_plane_name(source) +
                                    " has no capture in task " + std::to_string(t) + " " +
                                    quote(task.name) + " [" + format_shortest(task.start_s) +
                                    " s, " + format_shortest(task.stop_s) + " s]");
            }
        }
    }
}

/// a + b, or an error when it overflows.
std::uint64_t checked_add(std::uint64_t a, std::uint64_t b) {
    std::uint64_t sum = 0;
    if (__builtin_add_overflow(a, b, &sum)) {
        throw runtime_error("the schedule has more than 2^64 captures or problems");
    }
    return sum;
}

std::uint64_t checked_multiply(std::uint64_t a, std::uint64_t b) {
    std::uint64_t product = 0;
    if (__builtin_mul_overflow(a, b, &product)) {
        throw runtime_error("the schedule has more than 2^64 problems");
    }
    return product;
}

}  // namespace

Schedule Schedule::build(const model::SimulationInputs& inputs, const ScheduleOptions& options,
                         const Log& log, Diagnostics& diagnostics) {
    if (!std::isfinite(options.scale_resolution) || options.scale_resolution <= 0.0) {
        throw usage_error("--scale_resolution " + format_shortest(options.scale_resolution) +
                          " is not a positive number, expected a factor > 0");
    }
    if (options.output_prefix) {
        if (const auto problem = model::output_name_problem(*options.output_prefix)) {
            throw usage_error("--output_prefix " + quote(*options.output_prefix) + " " + *problem);
        }
    }
    const model::Simulation& simulation = inputs.simulation;
    Schedule schedule;
    Impl& impl = *schedule.m_impl;
    impl.simulation_file = simulation.file;
    // The poses live in the scene's frame, and tracking mounts may point at its instances.
    const model::Scene& scene = inputs.scene;
    if (options.scene_origin) {
        impl.frame = motion::SceneFrame(*options.scene_origin);
    } else if (scene.origin) {
        impl.frame = motion::SceneFrame(scene.origin->latitude_deg, scene.origin->longitude_deg,
                                        scene.origin->altitude_m);
    }
    // Dynamic scene instances move in the time of the first BasicPlatform's tasks.
    const DateTime reference =
        inputs.platforms.empty() ? DateTime{} : inputs.platforms.front().tasks.reference;
    impl.targets = std::make_shared<const motion::SceneTargets>(scene, impl.frame, reference, log);
    Builder loader{simulation, options, log, diagnostics, impl};
    if (simulation.basic_platform_indices().empty()) {
        diagnostics.warning(ErrorContext{simulation.file, 0, ""},
                            "no BasicPlatform entry in plugin_list: the schedule is empty");
    }
    for (const model::PlatformInputs& platform : inputs.platforms) loader.build_plugin(platform);
    loader.check_output_names();
    loader.compute_ticks();
    diagnostics.throw_if_errors();

    for (std::size_t s = 0; s < impl.sources.size(); ++s) {
        for (const ClockTicks& ticks : impl.ticks[s]) {
            impl.total_captures = checked_add(impl.total_captures, ticks.size());
            impl.total_problems =
                checked_add(impl.total_problems,
                            checked_multiply(ticks.size(), impl.sources[s].problems_per_capture));
        }
    }
    return schedule;
}

}  // namespace glint::schedule
