// SPDX-License-Identifier: Apache-2.0
// FlexMotion orientation engines: velocity (forward along the velocity, up towards a
// constraint), lookat (boresight −Z at a target, +Y towards an up hint), euler and
// quaternion tables (slerp between rows, clamped outside their span) and spin (a constant
// rate about a fixed scene axis).
#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "glint/motion/euler.h"
#include "trajectory_parts.h"

namespace glint::motion::detail {

namespace {

/// The velocity, or the nearest direction of travel where it is zero.
Vec3 moving_direction(const LocationModel& location, double t_s) {
    const Vec3 v = location.velocity_m_s(t_s);
    return norm(v) > 0.0 ? v : location.travel_direction(t_s);
}

class VelocityOrientation final : public OrientationModel {
public:
    explicit VelocityOrientation(const Vec3& up) : m_up(up) {}

    Quaternion orientation(double t_s, const LocationModel& location) const override {
        return frame_from_forward_up(moving_direction(location, t_s), m_up);
    }

private:
    Vec3 m_up;
};

class LookAtOrientation final : public OrientationModel {
public:
    LookAtOrientation(std::unique_ptr<LocationModel> target, bool up_is_velocity, const Vec3& up)
        : m_target(std::move(target)), m_up_is_velocity(up_is_velocity), m_up(up) {}

    Quaternion orientation(double t_s, const LocationModel& location) const override {
        const Vec3 look = m_target->position_m(t_s) - location.position_m(t_s);
        const Vec3 up = m_up_is_velocity ? moving_direction(location, t_s) : m_up;
        return frame_from_look_up(look, up);
    }
    std::optional<TimeSpan> span() const override { return m_target->span(); }

private:
    std::unique_ptr<LocationModel> m_target;
    bool m_up_is_velocity;
    Vec3 m_up;
};

/// A table of rotations, slerped between rows.
class RotationTable final : public OrientationModel {
public:
    RotationTable(std::vector<double> times, std::vector<Quaternion> rotations, ErrorContext where,
                  std::shared_ptr<const ClampNotice> notice)
        : m_times(std::move(times)),
          m_rotations(std::move(rotations)),
          m_where(std::move(where)),
          m_notice(std::move(notice)) {}

    Quaternion orientation(double t_s, const LocationModel& /*location*/) const override {
        if (m_times.size() == 1) return m_rotations[0];
        const double t = m_notice->clamp(t_s, m_times.front(), m_times.back(), m_where,
                                         "orientation table times");
        const Segment s = find_segment(m_times, t);
        return slerp(m_rotations[s.index], m_rotations[s.index + 1], s.fraction);
    }
    std::optional<TimeSpan> span() const override {
        return TimeSpan{m_times.front(), m_times.back()};
    }

private:
    std::vector<double> m_times;
    std::vector<Quaternion> m_rotations;
    ErrorContext m_where;
    std::shared_ptr<const ClampNotice> m_notice;
};

class SpinOrientation final : public OrientationModel {
public:
    SpinOrientation(const Vec3& axis, double rate_rad_s, double phase_rad)
        : m_axis(axis), m_rate_rad_s(rate_rad_s), m_phase_rad(phase_rad) {}

    Quaternion orientation(double t_s, const LocationModel& /*location*/) const override {
        return quaternion_from_axis_angle(m_axis, m_phase_rad + m_rate_rad_s * t_s);
    }

private:
    Vec3 m_axis;
    double m_rate_rad_s;
    double m_phase_rad;
};

std::unique_ptr<OrientationModel> make_table(const model::OrientationEngine& engine,
                                             std::shared_ptr<const ClampNotice> notice) {
    if (engine.table.empty()) {
        throw input_error("the orientation table is empty, expected at least one row",
                          engine.where);
    }
    std::optional<EulerOrder> order;
    if (engine.type == model::OrientationEngineType::euler) {
        order = parse_euler_order(engine.rotation_order);
        if (!order) {
            throw input_error(
                "rotationorder \"" + engine.rotation_order + "\" is not a permutation of xyz",
                engine.where);
        }
    }
    std::vector<double> times;
    std::vector<Quaternion> rotations;
    for (const model::MotionTableRow& row : engine.table) {
        const ErrorContext where{engine.where.file, row.line, engine.where.element};
        if (!times.empty() && !(row.time_s > times.back())) {
            throw input_error("orientation time " + seconds_text(row.time_s) + " does not follow " +
                                  seconds_text(times.back()) +
                                  ", expected strictly increasing times",
                              where);
        }
        times.push_back(row.time_s);
        if (order) {
            const Vec3 triple{row.values[0], row.values[1], row.values[2]};
            rotations.push_back(quaternion_from_matrix(
                vehicle_to_scene_rotation(to_vehicle_attitude(triple), *order)));
        } else {
            const Quaternion q{row.values[0], row.values[1], row.values[2], row.values[3]};
            if (!(norm(q) > 0.0)) {
                throw input_error("quaternion is zero, expected a rotation", where);
            }
            rotations.push_back(normalized(q));
        }
    }
    return std::make_unique<RotationTable>(std::move(times), std::move(rotations), engine.where,
                                           std::move(notice));
}

}  // namespace

std::unique_ptr<OrientationModel> make_orientation_model(
    const model::OrientationEngine& engine, const SceneFrame& scene, const DateTime& reference_utc,
    std::shared_ptr<const ClampNotice> notice) {
    switch (engine.type) {
        case model::OrientationEngineType::velocity:
            return std::make_unique<VelocityOrientation>(hint_to_scene(engine.up, scene));
        case model::OrientationEngineType::lookat: {
            if (!engine.target) {
                throw input_error("the look-at engine has no target", engine.where);
            }
            auto target = make_location_model(*engine.target, scene, reference_utc, notice);
            return std::make_unique<LookAtOrientation>(
                std::move(target), engine.up.type == model::DirectionType::velocity,
                hint_to_scene(engine.up, scene));
        }
        case model::OrientationEngineType::euler:
        case model::OrientationEngineType::quaternions:
            return make_table(engine, std::move(notice));
        case model::OrientationEngineType::spin: {
            const Vec3 axis = to_vec3(engine.spin_axis);
            if (!(norm(axis) > 0.0)) {
                throw input_error("the spin axis is zero, expected a direction", engine.where);
            }
            return std::make_unique<SpinOrientation>(axis, engine.spin_rate_rad_s,
                                                     engine.spin_phase_rad);
        }
    }
    throw internal_error("unknown orientation engine type");
}

}  // namespace glint::motion::detail
