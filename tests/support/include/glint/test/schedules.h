// SPDX-License-Identifier: Apache-2.0
// A schedule from a simulation file, as glint-schedule builds one: the inputs loaded once
// (inputs::load, no atmosphere), then schedule::Schedule::build over them.
#pragma once

#include <filesystem>

#include "glint/core/diagnostics.h"
#include "glint/core/log.h"
#include "glint/inputs/load.h"
#include "glint/schedule/schedule.h"

namespace glint::test {

/// Loads `file` and builds its schedule; problems go to `diagnostics` (throws as
/// inputs::load and Schedule::build do).
inline schedule::Schedule load_schedule(const std::filesystem::path& file,
                                        const schedule::ScheduleOptions& options,
                                        Diagnostics& diagnostics,
                                        const dirsig::ReadOptions& read = {}) {
    inputs::LoadOptions load;
    load.read = read;
    load.atmosphere = false;
    const model::SimulationInputs loaded = inputs::load(file, load, Log{}, diagnostics);
    return schedule::Schedule::build(loaded, options, Log{}, diagnostics);
}

}  // namespace glint::test
