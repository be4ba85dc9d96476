// SPDX-License-Identifier: Apache-2.0
// The platform and instrument pose and the sun of one capture, as the schedule JSON gives
// them (docs/tools/glint-schedule.md, "pose" and "sun").
#pragma once

#include <cstddef>

#include "glint/core/datetime.h"
#include "glint/motion/frames.h"
#include "glint/schedule/schedule.h"
#include "writers.h"

namespace glint::app_schedule::internal {

/// {"time_s", "datetime_utc", "platform": {...}, "instrument": {...}}: the vehicle pose
/// (PoseService::vehicle_pose) and the instrument pose (instrument_to_scene) at `t_s`, each
/// as scene ENU, ECEF and geodetic position, quaternion and xyz Euler angles; the instrument
/// also with its boresight direction in ENU.
Json pose_json(const schedule::PluginSchedule& plugin, std::size_t instrument_index, double t_s,
               const motion::SceneFrame& frame);

/// {"zenith_deg", "azimuth_deg", "direction_enu"}: the sun at `utc` seen from the origin
/// of `frame` (NREL SPA, no refraction).
Json sun_json(const DateTime& utc, const motion::SceneFrame& frame);

}  // namespace glint::app_schedule::internal
