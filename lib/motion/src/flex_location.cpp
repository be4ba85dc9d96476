// SPDX-License-Identifier: Apache-2.0
// FlexMotion location engines: waypoints (piecewise-linear in scene ENU, clamped outside
// their span), straight (constant velocity along a compass heading), fixed, and sgp4 (a
// two-line element set propagated by SGP4, TEME → ECEF with GMST taking UT1 as UTC, then
// scene ENU).
#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "glint/motion/sgp4.h"
#include "glint/motion/teme.h"
#include "glint/motion/tle.h"
#include "trajectory_parts.h"

namespace glint::motion::detail {

namespace {

class WaypointsModel final : public LocationModel {
public:
    WaypointsModel(std::vector<double> times, std::vector<Vec3> positions, ErrorContext where,
                   std::shared_ptr<const ClampNotice> notice)
        : m_times(std::move(times)),
          m_positions(std::move(positions)),
          m_where(std::move(where)),
          m_notice(std::move(notice)) {}

    Vec3 position_m(double t_s) const override {
        if (m_times.size() == 1) return m_positions[0];
        const Segment s = segment(t_s);
        return m_positions[s.index] +
               s.fraction * (m_positions[s.index + 1] - m_positions[s.index]);
    }

    Vec3 velocity_m_s(double t_s) const override {
        if (m_times.size() == 1) return {};
        return segment_velocity(segment(t_s).index);
    }

    Vec3 travel_direction(double t_s) const override {
        if (m_times.size() == 1) return {};
        const std::size_t i = segment(t_s).index;
        const std::size_t n = m_times.size() - 1;  // segments
        for (std::size_t k = 0; k < n; ++k) {
            if (i >= k) {
                const Vec3 v = segment_velocity(i - k);
                if (norm(v) > 0.0) return v;
            }
            if (i + k < n) {
                const Vec3 v = segment_velocity(i + k);
                if (norm(v) > 0.0) return v;
            }
        }
        return {};
    }

    std::optional<TimeSpan> span() const override {
        return TimeSpan{m_times.front(), m_times.back()};
    }

private:
    Segment segment(double t_s) const {
        const double t =
            m_notice->clamp(t_s, m_times.front(), m_times.back(), m_where, "waypoint times");
        return find_segment(m_times, t);
    }
    Vec3 segment_velocity(std::size_t i) const {
        return (m_positions[i + 1] - m_positions[i]) / (m_times[i + 1] - m_times[i]);
    }

    std::vector<double> m_times;
    std::vector<Vec3> m_positions;
    ErrorContext m_where;
    std::shared_ptr<const ClampNotice> m_notice;
};

/// Constant velocity from a start position (t = 0); a fixed location when the speed is 0.
class LinearModel final : public LocationModel {
public:
    LinearModel(const Vec3& start_m, const Vec3& velocity_m_s)
        : m_start_m(start_m), m_velocity_m_s(velocity_m_s) {}

    Vec3 position_m(double t_s) const override { return m_start_m + t_s * m_velocity_m_s; }
    Vec3 velocity_m_s(double /*t_s*/) const override { return m_velocity_m_s; }

private:
    Vec3 m_start_m;
    Vec3 m_velocity_m_s;
};

class Sgp4Model final : public LocationModel {
public:
    Sgp4Model(Sgp4 satellite, const SceneFrame& scene, const DateTime& reference_utc,
              ErrorContext where)
        : m_satellite(std::move(satellite)),
          m_scene(scene),
          m_minutes_at_reference(m_satellite.minutes_since_epoch(reference_utc)),
          m_jd_at_reference(julian_date_utc(reference_utc)),
          m_where(std::move(where)) {}

    /// The scene ENU position and velocity at `t_s`, or the propagation error.
    Sgp4Error state(double t_s, Vec3& position_m, Vec3& velocity_m_s) const {
        const Sgp4State s = m_satellite.propagate_minutes(m_minutes_at_reference + t_s / 60.0);
        if (!s.ok()) return s.error;
        const PositionVelocity ecef =
            teme_to_ecef(s.position_km, s.velocity_km_s, m_jd_at_reference + t_s / 86400.0);
        position_m = m_scene.ecef_to_enu(ecef.position_km * 1000.0);
        velocity_m_s = m_scene.ecef_direction_to_enu(ecef.velocity_km_s * 1000.0);
        return Sgp4Error::none;
    }

    Vec3 position_m(double t_s) const override { return checked(t_s).first; }
    Vec3 velocity_m_s(double t_s) const override { return checked(t_s).second; }

private:
    std::pair<Vec3, Vec3> checked(double t_s) const {
        std::pair<Vec3, Vec3> out;
        const Sgp4Error error = state(t_s, out.first, out.second);
        if (error != Sgp4Error::none) {
            throw Error(ErrorCategory::runtime,
                        "satellite " + std::to_string(m_satellite.tle().satellite_number) +
                            " cannot be propagated to t = " + seconds_text(t_s) + ": " +
                            std::string(describe(error)),
                        m_where);
        }
        return out;
    }

    Sgp4 m_satellite;
    SceneFrame m_scene;
    double m_minutes_at_reference;
    double m_jd_at_reference;
    ErrorContext m_where;
};

std::unique_ptr<LocationModel> make_sgp4(const model::LocationEngine& engine,
                                         const SceneFrame& scene, const DateTime& reference_utc) {
    // Tle::parse reports its own errors at tle_where (line 2 at the next line).
    const Tle tle = Tle::parse(engine.tle1, engine.tle2, engine.tle_where);
    std::optional<Sgp4> satellite;
    try {
        satellite.emplace(tle);
    } catch (const Error& error) {
        throw input_error(error.message(), engine.tle_where);
    }
    auto model = std::make_unique<Sgp4Model>(*satellite, scene, reference_utc, engine.tle_where);
    Vec3 position;
    Vec3 velocity;
    if (const Sgp4Error error = model->state(0.0, position, velocity); error != Sgp4Error::none) {
        throw input_error("the element set of satellite " + std::to_string(tle.satellite_number) +
                              " cannot be propagated to the reference time " +
                              format_iso8601_utc(reference_utc, 3) + ": " +
                              std::string(describe(error)),
                          engine.tle_where);
    }
    return model;
}

}  // namespace

std::unique_ptr<LocationModel> make_location_model(const model::LocationEngine& engine,
                                                   const SceneFrame& scene,
                                                   const DateTime& reference_utc,
                                                   std::shared_ptr<const ClampNotice> notice) {
    switch (engine.type) {
        case model::LocationEngineType::waypoints: {
            if (engine.waypoints.empty()) {
                throw input_error("the waypoint table is empty, expected at least one row",
                                  engine.where);
            }
            std::vector<double> times;
            std::vector<Vec3> positions;
            for (const model::MotionTableRow& row : engine.waypoints) {
                const ErrorContext where{engine.where.file, row.line, engine.where.element};
                if (!times.empty() && !(row.time_s > times.back())) {
                    throw input_error("waypoint time " + seconds_text(row.time_s) +
                                          " does not follow " + seconds_text(times.back()) +
                                          ", expected strictly increasing times",
                                      where);
                }
                model::Location location;
                location.frame = engine.waypoint_frame;
                location.where = where;
                if (engine.waypoint_frame == model::LocationFrame::geodetic) {
                    location.latitude_deg = row.values[0];
                    location.longitude_deg = row.values[1];
                    location.altitude_m = row.values[2];
                } else {
                    location.xyz_m = {row.values[0], row.values[1], row.values[2]};
                }
                times.push_back(row.time_s);
                positions.push_back(location_to_scene(location, scene));
            }
            return std::make_unique<WaypointsModel>(std::move(times), std::move(positions),
                                                    engine.where, std::move(notice));
        }
        case model::LocationEngineType::straight: {
            // Heading clockwise from north: north = +Y, east = +X.
            const Vec3 direction{std::sin(engine.heading_rad), std::cos(engine.heading_rad), 0.0};
            return std::make_unique<LinearModel>(location_to_scene(engine.location, scene),
                                                 engine.speed_m_s * direction);
        }
        case model::LocationEngineType::fixed:
            return std::make_unique<LinearModel>(location_to_scene(engine.location, scene), Vec3{});
        case model::LocationEngineType::sgp4:
            return make_sgp4(engine, scene, reference_utc);
    }
    throw internal_error("unknown location engine type");
}

}  // namespace glint::motion::detail
