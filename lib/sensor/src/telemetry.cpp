// SPDX-License-Identifier: Apache-2.0
// Data-recorder telemetry (glint/sensor/telemetry.h): sample times from the recorder's clock,
// poses from the pose service, central differences for velocity and body rates, seeded
// Gaussian noise, and the CSV and JSON-lines writers.
#include "glint/sensor/telemetry.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "glint/core/rng.h"
#include "glint/core/text.h"
#include "glint/schedule/clock_ticks.h"

namespace glint::sensor {
namespace {

using motion::Quaternion;
using motion::Vec3;

/// Half the central-difference step of velocities and body rates (s).
constexpr double kDifferenceStep_s = 1e-3;
/// Salt of the telemetry noise streams (ASCII "tele").
constexpr std::uint64_t kTelemetryStream = 0x74656c65;

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

/// The quaternion of the same rotation with w ≥ 0.
Quaternion canonical(const Quaternion& q) {
    return q.w < 0.0 ? Quaternion{-q.w, -q.x, -q.y, -q.z} : q;
}

/// Body angular velocity (rad/s, frame of the rotations) taking q0 to q1 over dt.
Vec3 body_rate_rad_s(const Quaternion& q0, const Quaternion& q1, double dt_s) {
    const Quaternion d = canonical(motion::normalized(motion::conjugate(q0) * q1));
    const double s = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    if (s == 0.0) return {0.0, 0.0, 0.0};
    const double angle = 2.0 * std::atan2(s, d.w);
    return Vec3{d.x / s, d.y / s, d.z / s} * (angle / dt_s);
}

std::string number(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

std::string noise_text(const model::TelemetryNoise& n) {
    std::string text;
    auto add = [&](const char* what, const std::optional<double>& sigma, const char* unit) {
        if (!sigma) return;
        if (!text.empty()) text += ", ";
        text += std::string(what) + " " + number(*sigma) + " " + unit;
    };
    add("position", n.position_m, "m");
    add("velocity", n.velocity_m_s, "m/s");
    add("orientation", n.orientation_deg, "deg");
    add("angular rate", n.angular_rate_deg_s, "deg/s");
    return text.empty() ? "none" : "Gaussian, sigma per component: " + text;
}

std::string order_text(motion::EulerOrder order) { return std::string(motion::to_string(order)); }

}  // namespace

const model::Clock* recorder_clock(const model::Instrument& recorder) {
    if (recorder.recorder.clock) return &*recorder.recorder.clock;
    for (const model::FocalPlane& plane : recorder.focal_planes) {
        if (plane.enabled) return &plane.detector_array.clock;
    }
    return nullptr;
}

std::vector<std::pair<std::uint64_t, double>> recorder_times_s(const model::Instrument& recorder,
                                                                const model::Platform& platform,
                                                                const model::TaskList& tasks) {
    const model::Clock* clock = recorder_clock(recorder);
    std::vector<std::pair<std::uint64_t, double>> times;
    if (clock == nullptr) return times;
    for (std::size_t t = 0; t < tasks.tasks.size(); ++t) {
        const schedule::ClockTicks ticks(*clock, platform.clock_table, clock->trigger_times_s,
                                         tasks.tasks[t].start_s, tasks.tasks[t].stop_s);
        for (std::uint64_t i = 0; i < ticks.size(); ++i) times.emplace_back(t, ticks.time_s(i));
    }
    return times;
}

TelemetryRecord record_sample(const motion::PoseService& poses, std::size_t instrument,
                              std::uint64_t task, double t, std::uint64_t index,
                              const motion::SceneFrame& frame, const model::TelemetryNoise& noise,
                              std::uint64_t seed, std::uint64_t plugin_index) {
    const motion::EulerOrder order = poses.platform_rotation_order();
    const motion::Rigid pose = poses.instrument_to_scene(instrument, t);
    const motion::Rigid before = poses.instrument_to_scene(instrument, t - kDifferenceStep_s);
    const motion::Rigid after = poses.instrument_to_scene(instrument, t + kDifferenceStep_s);
    TelemetryRecord r;
    r.task = task;
    r.time_s = t;
    r.position_enu_m = pose.translation_m;
    r.velocity_enu_m_s = (after.translation_m - before.translation_m) * (0.5 / kDifferenceStep_s);
    r.orientation = canonical(motion::normalized(pose.rotation));
    Vec3 euler_rad = motion::quaternion_to_euler(r.orientation, order);
    Vec3 rate_rad_s = body_rate_rad_s(before.rotation, after.rotation, 2 * kDifferenceStep_s);
    // Noise: one stream per sample, components drawn in a fixed order.
    RandomStream rng(seed, {kTelemetryStream, plugin_index, instrument, index});
    auto jitter = [&](Vec3& v, const std::optional<double>& sigma, double scale) {
        const Vec3 n{rng.normal(), rng.normal(), rng.normal()};
        if (sigma && *sigma > 0.0) v = v + n * (*sigma * scale);
    };
    jitter(r.position_enu_m, noise.position_m, 1.0);
    jitter(r.velocity_enu_m_s, noise.velocity_m_s, 1.0);
    jitter(euler_rad, noise.orientation_deg, 1.0 / kDegPerRad);
    jitter(rate_rad_s, noise.angular_rate_deg_s, 1.0 / kDegPerRad);
    if (noise.orientation_deg && *noise.orientation_deg > 0.0) {
        r.orientation = canonical(motion::euler_to_quaternion(euler_rad, order));
    }
    r.euler_deg = euler_rad * kDegPerRad;
    r.angular_rate_deg_s = rate_rad_s * kDegPerRad;
    r.position_ecef_m = frame.enu_to_ecef(r.position_enu_m);
    r.geodetic = frame.enu_to_geodetic(r.position_enu_m);
    return r;
}

std::vector<TelemetryRecord> record_telemetry(
    const motion::PoseService& poses, std::size_t instrument,
    const std::vector<std::pair<std::uint64_t, double>>& times, const motion::SceneFrame& frame,
    const model::TelemetryNoise& noise, std::uint64_t seed, std::uint64_t plugin_index) {
    std::vector<TelemetryRecord> records;
    records.reserve(times.size());
    for (std::size_t i = 0; i < times.size(); ++i) {
        records.push_back(record_sample(poses, instrument, times[i].first, times[i].second, i,
                                        frame, noise, seed, plugin_index));
    }
    return records;
}

std::string telemetry_csv_head(const TelemetryHeader& h) {
    const std::string order = order_text(h.order);
    std::ostringstream out;
    out << "# glint data recorder telemetry, format glint-telemetry version 1\n"
        << "# instrument " << quote(h.instrument) << " of " << h.platform_file << " (plugin_list["
        << h.plugin_index << "]); " << h.tool << " " << h.version << ", seed " << h.seed << "\n"
        << "# time_s: seconds after the tasks reference time "
        << format_iso8601_utc(h.reference) << "; datetime_utc: the same as UTC\n"
        << "# east/north/up_m: scene East-North-Up about latitude " << number(h.scene_origin.latitude_deg)
        << " deg, longitude " << number(h.scene_origin.longitude_deg) << " deg, altitude "
        << number(h.scene_origin.altitude_m) << " m (WGS84); ecef_*_m: WGS84 Earth-centred "
        << "Earth-fixed; latitude/longitude_deg, altitude_m: WGS84 geodetic\n"
        << "# velocity_*_m_s: scene ENU; q_w..q_z: the instrument frame -> scene ENU rotation; "
        << "euler_*_deg: the same rotation as Euler angles about x, y, z applied in the "
        << "platform's order " << order << "; rate_*_deg_s: angular velocity in the instrument "
        << "frame\n"
        << "# noise: " << noise_text(h.noise) << "\n"
        << "task,time_s,datetime_utc,east_m,north_m,up_m,ecef_x_m,ecef_y_m,ecef_z_m,"
           "latitude_deg,longitude_deg,altitude_m,velocity_east_m_s,velocity_north_m_s,"
           "velocity_up_m_s,q_w,q_x,q_y,q_z,euler_x_deg,euler_y_deg,euler_z_deg,rate_x_deg_s,"
           "rate_y_deg_s,rate_z_deg_s\n";
    return out.str();
}

std::string telemetry_csv_row(const TelemetryHeader& h, const TelemetryRecord& r) {
    std::ostringstream out;
    out << r.task << "," << number(r.time_s) << ","
        << format_iso8601_utc(add_seconds(h.reference, r.time_s), 9);
    for (const double v :
         {r.position_enu_m.x, r.position_enu_m.y, r.position_enu_m.z, r.position_ecef_m.x,
          r.position_ecef_m.y, r.position_ecef_m.z, r.geodetic.latitude_deg,
          r.geodetic.longitude_deg, r.geodetic.altitude_m, r.velocity_enu_m_s.x,
          r.velocity_enu_m_s.y, r.velocity_enu_m_s.z, r.orientation.w, r.orientation.x,
          r.orientation.y, r.orientation.z, r.euler_deg.x, r.euler_deg.y, r.euler_deg.z,
          r.angular_rate_deg_s.x, r.angular_rate_deg_s.y, r.angular_rate_deg_s.z}) {
        out << "," << number(v);
    }
    out << "\n";
    return out.str();
}

std::string telemetry_csv(const TelemetryHeader& h, const std::vector<TelemetryRecord>& records) {
    std::string out = telemetry_csv_head(h);
    for (const TelemetryRecord& r : records) out += telemetry_csv_row(h, r);
    return out;
}

std::string telemetry_jsonl_head(const TelemetryHeader& h) {
    using nlohmann::json;
    auto noise = [](const std::optional<double>& v) { return v ? json(*v) : json(nullptr); };
    json header = {
        {"format", "glint-telemetry"},
        {"version", 1},
        {"instrument", h.instrument},
        {"platform", h.platform_file},
        {"plugin_index", h.plugin_index},
        {"reference_utc", format_iso8601_utc(h.reference)},
        {"scene_origin",
         {{"latitude_deg", h.scene_origin.latitude_deg},
          {"longitude_deg", h.scene_origin.longitude_deg},
          {"altitude_m", h.scene_origin.altitude_m}}},
        {"rotation_order", order_text(h.order)},
        {"units",
         {{"time_s", "s after reference_utc"},
          {"position_enu_m", "m"},
          {"position_ecef_m", "m"},
          {"geodetic", "deg, deg, m"},
          {"velocity_enu_m_s", "m/s"},
          {"orientation_wxyz", "unit quaternion"},
          {"euler_deg", "deg"},
          {"angular_rate_deg_s", "deg/s"}}},
        {"frames",
         {{"position_enu_m", "scene East-North-Up about scene_origin"},
          {"position_ecef_m", "WGS84 Earth-centred Earth-fixed"},
          {"geodetic", "WGS84"},
          {"velocity_enu_m_s", "scene East-North-Up"},
          {"orientation_wxyz", "instrument frame to scene ENU"},
          {"euler_deg", "instrument frame to scene ENU, angles about x, y, z in rotation_order"},
          {"angular_rate_deg_s", "instrument frame"}}},
        {"noise_sigma",
         {{"position_m", noise(h.noise.position_m)},
          {"velocity_m_s", noise(h.noise.velocity_m_s)},
          {"orientation_deg", noise(h.noise.orientation_deg)},
          {"angular_rate_deg_s", noise(h.noise.angular_rate_deg_s)}}},
        {"provenance",
         {{"tool", h.tool}, {"version", h.version}, {"command_line", h.command_line},
          {"seed", h.seed}}}};
    return header.dump() + "\n";
}

std::string telemetry_jsonl_row(const TelemetryHeader& h, const TelemetryRecord& r) {
    using nlohmann::json;
    auto v3 = [](const Vec3& v) { return json::array({v.x, v.y, v.z}); };
    const json row = {
        {"task", r.task},
        {"time_s", r.time_s},
        {"datetime_utc", format_iso8601_utc(add_seconds(h.reference, r.time_s), 9)},
        {"position_enu_m", v3(r.position_enu_m)},
        {"position_ecef_m", v3(r.position_ecef_m)},
        {"geodetic", json::array({r.geodetic.latitude_deg, r.geodetic.longitude_deg,
                                  r.geodetic.altitude_m})},
        {"velocity_enu_m_s", v3(r.velocity_enu_m_s)},
        {"orientation_wxyz",
         json::array({r.orientation.w, r.orientation.x, r.orientation.y, r.orientation.z})},
        {"euler_deg", v3(r.euler_deg)},
        {"angular_rate_deg_s", v3(r.angular_rate_deg_s)}};
    return row.dump() + "\n";
}

std::string telemetry_jsonl(const TelemetryHeader& h, const std::vector<TelemetryRecord>& records) {
    std::string out = telemetry_jsonl_head(h);
    for (const TelemetryRecord& r : records) out += telemetry_jsonl_row(h, r);
    return out;
}

}  // namespace glint::sensor
