// SPDX-License-Identifier: Apache-2.0
// Poses and sun angles of a capture for the schedule JSON: the pose service's vehicle and
// instrument poses at mid-window expressed in scene ENU, ECEF and WGS84 geodetic
// coordinates, and NREL SPA's sun zenith and azimuth at the scene origin.
#include "pose_json.h"

#include "glint/motion/euler.h"
#include "glint/motion/rigid.h"
#include "glint/motion/sun.h"

namespace glint::app_schedule::internal {
namespace {

Json vec3_json(const motion::Vec3& v) { return Json::array({v.x, v.y, v.z}); }

/// Position and orientation of a frame whose origin is `position_enu_m` and whose axes are
/// rotated into the scene by `orientation`.
Json placement_json(const motion::Vec3& position_enu_m, const motion::Quaternion& orientation,
                    const motion::SceneFrame& frame) {
    const motion::Geodetic geodetic = frame.enu_to_geodetic(position_enu_m);
    const motion::Vec3 euler_deg =
        motion::euler_rad_to_deg(motion::quaternion_to_euler(orientation, motion::EulerOrder::xyz));
    Json j;
    j["position_enu_m"] = vec3_json(position_enu_m);
    j["position_ecef_m"] = vec3_json(frame.enu_to_ecef(position_enu_m));
    j["geodetic"] = Json{{"latitude_deg", geodetic.latitude_deg},
                         {"longitude_deg", geodetic.longitude_deg},
                         {"altitude_m", geodetic.altitude_m}};
    j["orientation_wxyz"] =
        Json::array({orientation.w, orientation.x, orientation.y, orientation.z});
    j["euler_xyz_deg"] = vec3_json(euler_deg);
    return j;
}

}  // namespace

Json pose_json(const schedule::PluginSchedule& plugin, std::size_t instrument_index, double t_s,
               const motion::SceneFrame& frame) {
    const motion::PoseService& poses = *plugin.poses;
    const motion::Pose vehicle = poses.vehicle_pose(t_s);
    const motion::Rigid instrument = poses.instrument_to_scene(instrument_index, t_s);
    Json j;
    j["time_s"] = t_s;
    j["platform"] = placement_json(vehicle.position_m, vehicle.orientation, frame);
    Json placed = placement_json(instrument.translation_m, instrument.rotation, frame);
    placed["boresight_enu"] =
        vec3_json(motion::apply_direction(instrument, motion::kInstrumentBoresight));
    j["instrument"] = std::move(placed);
    return j;
}

Json sun_json(const DateTime& utc, const motion::SceneFrame& frame) {
    const motion::SunPosition sun = motion::sun_position(utc, frame);
    Json j;
    j["zenith_deg"] = sun.zenith_deg;
    j["azimuth_deg"] = sun.azimuth_deg;
    j["direction_enu"] = vec3_json(sun.direction_enu);
    return j;
}

}  // namespace glint::app_schedule::internal
