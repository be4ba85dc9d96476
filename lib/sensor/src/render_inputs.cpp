// SPDX-License-Identifier: Apache-2.0
// Loading a render's inputs: simulation, scenes, atmosphere, sun, schedule.
#include <string>
#include <utility>

#include "glint/core/diagnostics.h"
#include "glint/core/error.h"
#include "glint/legacy/readers.h"
#include "glint/legacy/simulation_inputs.h"
#include "glint/scene/geometry_scene.h"
#include "render_parts.h"

namespace glint::sensor::detail {

namespace {

void read_all(RenderInputs& in, const std::filesystem::path& simulation_file,
              const RenderOptions& options, const Context& context, Diagnostics& diagnostics) {
    std::vector<model::Simulation> simulations =
        legacy::read_simulation(simulation_file, options.read, diagnostics);
    diagnostics.throw_if_errors();
    if (simulations.size() != 1) {
        throw input_error("the file holds " + std::to_string(simulations.size()) +
                              " simulations; glint-render renders one (split the .jsim)",
                          ErrorContext{simulation_file.string(), 0, {}});
    }
    in.simulation = std::move(simulations.front());
    in.scene = legacy::read_simulation_scene(in.simulation, options.read, diagnostics);
    in.atmosphere =
        legacy::read_simulation_atmosphere(in.simulation, options.read, diagnostics, context.log);
    diagnostics.throw_if_errors();
    in.atmosphere_model = scene::make_atmosphere_model(in.atmosphere);

    schedule::ScheduleOptions schedule_options = options.schedule;
    schedule_options.scene = &in.scene;  // its origin and named targets
    in.schedule.emplace(schedule::Schedule::load(simulation_file, schedule_options, options.read,
                                                 context.log, diagnostics));
    in.frame = in.schedule->frame();
    const std::filesystem::path solar = options.data_dir / scene::SolarSpectrum::kAstmRelativePath;
    in.sun.emplace(scene::SolarSpectrum::load_astm_g173(solar, solar.string()));

    const DateTime reference = in.schedule->plugins().empty()
                                   ? DateTime{}
                                   : in.schedule->plugins().front().tasks.reference;
    in.trajectories =
        motion::make_instance_trajectories(in.scene, in.frame, reference, context.log);
    for (const model::Instance& instance : in.scene.instances) {
        in.dynamic_scene = in.dynamic_scene || instance.dynamic();
    }
}

}  // namespace

RenderInputs load_inputs(const std::filesystem::path& simulation_file, const RenderOptions& options,
                         const Context& context) {
    RenderInputs in;
    Diagnostics diagnostics;
    try {
        read_all(in, simulation_file, options, context, diagnostics);
    } catch (const Error&) {
        diagnostics.log_to(context.log);  // every problem, not only the first
        throw;
    }
    diagnostics.log_to(context.log);  // the warnings
    return in;
}

}  // namespace glint::sensor::detail
