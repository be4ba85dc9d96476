// SPDX-License-Identifier: Apache-2.0
// The capture loop (glint/sensor/render.h): plan() stops after planning; render() builds the
// Embree scene (once, or per capture when something moves) and renders the captures in
// schedule order (render_capture.cpp).
#include "glint/sensor/render.h"

#include <map>
#include <memory>
#include <optional>
#include <utility>

#include "render_parts.h"

namespace glint::sensor {

RenderReport plan(model::SimulationInputs inputs, const RenderOptions& options,
                  const Context& context) {
    const std::unique_ptr<detail::Prepared> prepared =
        detail::prepare(std::move(inputs), options, context);
    RenderReport report = prepared->report;
    for (const detail::PlannedCapture& p : prepared->captures) {
        CaptureReport c;
        c.index = p.capture.index;
        c.pixels = prepared->inputs.schedule->sources()[p.capture.source].problems_per_capture;
        report.captures.push_back(c);
    }
    detail::write_log_info(*prepared, options, context);
    return report;
}

RenderReport render(model::SimulationInputs inputs, const RenderOptions& options,
                    const Context& context) {
    const std::unique_ptr<detail::Prepared> prepared =
        detail::prepare(std::move(inputs), options, context);
    const detail::RenderInputs& in = prepared->inputs;
    RenderReport report = prepared->report;
    std::optional<scene::GeometryScene> static_scene;
    if (!in.dynamic_scene) {
        static_scene.emplace(scene::GeometryScene::build(
            in.scene, in.trajectories, detail::build_options(options, 0.0, 0.0), context.log));
        report.device = static_scene->device();
    }
    std::map<std::size_t, radiometry::SensorPathCache> path_caches;  // per focal plane
    std::vector<double> image;
    std::uint64_t pixels_done = 0;
    for (const detail::PlannedCapture& p : prepared->captures) {
        context.cancel.throw_if_cancelled();
        std::optional<scene::GeometryScene> moving;
        if (in.dynamic_scene) {
            moving.emplace(scene::GeometryScene::build(
                in.scene, in.trajectories,
                detail::build_options(options, p.capture.t0_s, p.capture.t1_s), context.log));
            report.device = moving->device();
        }
        const CaptureReport stats =
            detail::render_capture(*prepared, p, moving ? *moving : *static_scene,
                                   path_caches[p.capture.source], options, context, image);
        report.captures.push_back(stats);
        pixels_done += stats.pixels;
        context.progress.update("pixels", pixels_done, report.pixels);
    }
    context.progress.finish("pixels", report.pixels);
    detail::write_log_info(*prepared, options, context);
    report.files = prepared->outputs.published();
    return report;
}

}  // namespace glint::sensor
