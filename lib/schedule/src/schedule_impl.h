// SPDX-License-Identifier: Apache-2.0
// What a loaded Schedule holds (private to lib/schedule): the plugins, the sources, and the
// tick range of every (source, task), computed once at load so that counts are O(1) and the
// generator only reads them.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include "glint/schedule/clock_ticks.h"
#include "glint/motion/scene_instances.h"
#include "glint/schedule/schedule.h"

namespace glint::schedule {

namespace detail {

/// The data of Schedule::Impl, in a type code outside the class may name.
struct ScheduleData {
    std::filesystem::path simulation_file;
    motion::SceneFrame frame;  ///< where the poses are placed
    /// Named targets of tracking mounts (the scene's instances); the pose services point at it.
    std::shared_ptr<const motion::SceneTargets> targets;
    std::vector<PluginSchedule> plugins;
    std::vector<ClockedFocalPlane> sources;
    /// ticks[source][task]: the source's clock in task `task` of its plugin. The trigger lists
    /// they point into live in `sources` (filled before these are built, never resized after).
    std::vector<std::vector<ClockTicks>> ticks;
    std::uint64_t total_captures = 0;
    std::uint64_t total_problems = 0;
};

}  // namespace detail

struct Schedule::Impl : detail::ScheduleData {};

}  // namespace glint::schedule
