// SPDX-License-Identifier: Apache-2.0
// A simulation with every file it names already read: what the input loader (glint/inputs)
// returns and the layers below take — the schedule, the pose services and the renderer read
// no file themselves. PSD jitter tables and trigger times are filled in (JitterSpec::psd,
// JitterSpec::psd, Clock::trigger_times_s).
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "glint/model/atmosphere.h"
#include "glint/model/motion.h"
#include "glint/model/platform.h"
#include "glint/model/scene.h"
#include "glint/model/simulation.h"
#include "glint/model/tasks.h"
#include "glint/model/weather.h"

namespace glint::model {

/// One BasicPlatform entry of the simulation's plugin_list, with its three files read.
struct PlatformInputs {
    std::size_t plugin_index = 0;              ///< index in Simulation::plugins
    std::shared_ptr<const Platform> platform;  ///< shared: sources and poses point into it
    PlatformMotion motion;
    TaskList tasks;
};

/// A simulation and everything it references.
struct SimulationInputs {
    Simulation simulation;
    /// Every scene_list entry, merged (empty: no origin, no objects).
    Scene scene;
    /// The first BasicAtmosphere's file, or the default (parametric) atmosphere.
    Atmosphere atmosphere;
    /// The weather history the simulation names (glint/inputs/weather.h); empty: none.
    Weather weather;
    /// One entry per BasicPlatform plugin, in plugin_list order.
    std::vector<PlatformInputs> platforms;
};

}  // namespace glint::model
