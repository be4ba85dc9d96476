// SPDX-License-Identifier: Apache-2.0
// The capture loop (glint/render/render.h): dry_run() stops after planning; render() builds the
// Embree scene (once, or per capture when something moves) and renders the captures in
// schedule order (render_capture.cpp).
#include "glint/render/render.h"

#include <cmath>
#include <map>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <utility>

#include "glint/core/error.h"
#include "render_parts.h"

namespace glint::render {

RenderReport dry_run(model::SimulationInputs inputs, const RenderOptions& options,
                     const Context& context) {
    detail::PlannedRender planned = detail::plan_render(std::move(inputs), options, context);
    const detail::RenderPlan& plan = *planned.plan;
    RenderReport report = plan.report;
    planned.outputs.lock_folders();  // a second run into these folders fails here
    for (const detail::PlannedCapture& p : plan.captures) {
        CaptureReport c;
        c.index = p.capture.index;
        c.pixels = p.problems(plan.inputs.schedule->sources()[p.capture.source]);
        report.captures.push_back(c);
    }
    report.events = detail::plan_events(plan).in_order();
    detail::write_log_info(plan, options, context);
    return report;
}

namespace {

std::string mebibytes(double bytes) {
    return std::to_string(static_cast<long long>(std::ceil(bytes / (1024.0 * 1024.0)))) + " MiB";
}

/// The message for a capture whose buffers could not be allocated: what it holds, what the
/// whole render needs, and what to do about it.
std::string out_of_memory(const detail::RenderPlan& plan, const detail::PlannedCapture& p) {
    const schedule::ClockedFocalPlane& source = plan.inputs.schedule->sources()[p.capture.source];
    const detail::FocalPlaneState& state = plan.states.at(p.capture.source);
    const std::uint64_t lines =
        std::min<std::uint64_t>(detail::block_lines(source), source.lines_per_capture());
    const std::uint64_t values = detail::band_values(state);
    const bool two = detail::bands_held(source) == 2;
    return "out of memory in capture " + std::to_string(p.capture.index) + " of focal plane \"" +
           source.focal_plane->name +
           "\": " + (two ? "two bands (one written while the next is solved)" : "a band") + " of " +
           std::to_string(lines) + " of its " + std::to_string(source.lines_per_capture()) +
           " lines of " + std::to_string(source.problems_per_capture / source.lines_per_capture()) +
           " pixels x " + std::to_string(values) + " values x 8 bytes " + (two ? "need" : "needs") +
           " about " + mebibytes(static_cast<double>(detail::band_bytes(source, state))) +
           ", and the render as planned about " +
           mebibytes(static_cast<double>(plan.report.memory_estimate_bytes)) +
           " (glint-render --dry-run shows the plan; --scale_resolution lowers the pixel counts)";
}

/// One warning when an atmosphere of one geometry (a tabulated one: its numbers hold for the
/// height it was computed for) lights surfaces spread over more than one level of height: it
/// is applied at every height as written.
}  // namespace

RenderReport render(model::SimulationInputs inputs, const RenderOptions& options,
                    const Context& context, RenderObserver* observer) {
    detail::PlannedRender planned = detail::plan_render(std::move(inputs), options, context);
    const detail::RenderPlan& plan = *planned.plan;
    const detail::RenderInputs& in = plan.inputs;
    RenderReport report = plan.report;
    const detail::EventPlan events = detail::plan_events(plan);
    report.events = events.in_order();
    if (observer != nullptr) observer->on_plan(report.events);
    auto fire = [&](const std::vector<model::ProcessingEvent>& list) {
        if (observer == nullptr) return;
        for (const model::ProcessingEvent& e : list) {
            context.cancel.throw_if_cancelled();
            observer->on_event(e);
        }
    };
    std::optional<scene::GeometryScene> static_scene;
    std::shared_ptr<const scene::FacetTemperatures> therm;  // THERM's cells, when it runs
    if (!in.scene_motion->moves()) {
        static_scene.emplace(in.scene_motion->build(
            in.scene, detail::build_options(options, 0.0, 0.0), context.log));
        report.device = static_scene->device();
        in.light->warn_if_one_geometry(*static_scene, context.log);
        therm = detail::solve_therm(plan, *static_scene, context);
        static_scene->set_facet_temperatures(therm);
    } else if (detail::uses_therm(in.scene)) {
        // Where something moves, THERM solves the instances that stay put, their shadow
        // history traced in a scene without the moving ones (docs/thermal.md).
        scene::BuildOptions still = detail::build_options(options, 0.0, 0.0);
        still.static_only = true;
        therm = detail::solve_therm(plan, in.scene_motion->build(in.scene, still, context.log),
                                    context);
    }
    detail::write_telemetry(plan, options, context);                  // complete before any capture
    std::map<std::size_t, radiometry::SensorPathCache> path_caches;   // per focal plane
    std::map<std::size_t, radiometry::SensorPathCache> laser_caches;  // per lidar receiver
    std::vector<double> image;
    std::uint64_t pixels_done = 0;
    for (std::size_t i = 0; i < plan.captures.size(); ++i) {
        const detail::PlannedCapture& p = plan.captures[i];
        context.cancel.throw_if_cancelled();
        fire(events.before[i]);
        std::optional<scene::GeometryScene> moving;
        if (in.scene_motion->moves()) {
            moving.emplace(in.scene_motion->build(
                in.scene, detail::build_options(options, p.capture.t0_s, p.capture.t1_s),
                context.log));
            report.device = moving->device();
            moving->set_facet_temperatures(therm);
            if (i == 0) in.light->warn_if_one_geometry(*moving, context.log);
        }
        CaptureReport stats;
        const scene::GeometryScene& geometry = moving ? *moving : *static_scene;
        try {
            if (plan.states.at(p.capture.source).lidar) {
                stats = detail::render_pulse(plan, planned.outputs, p, geometry,
                                             path_caches[p.capture.source],
                                             laser_caches[p.capture.source], options, context);
            } else {
                stats =
                    detail::render_capture(plan, planned.outputs, p, geometry,
                                           path_caches[p.capture.source], options, context, image);
            }
        } catch (const std::bad_alloc&) {
            throw runtime_error(out_of_memory(plan, p));
        }
        report.captures.push_back(stats);
        pixels_done += stats.pixels;
        context.progress.update("pixels", pixels_done, report.pixels);
        fire(events.after[i]);
    }
    context.progress.finish("pixels", report.pixels);
    detail::write_log_info(plan, options, context);
    report.files = planned.outputs.published();
    std::vector<std::filesystem::path> telemetry;  // written first
    for (const detail::PlannedTelemetry& t : plan.telemetry) {
        telemetry.push_back(t.csv);
        telemetry.push_back(t.jsonl);
    }
    report.files.insert(report.files.begin(), telemetry.begin(), telemetry.end());
    return report;
}

}  // namespace glint::render
