// SPDX-License-Identifier: Apache-2.0
// Small platforms built in code for the pose-service tests (motion, sensor).
#pragma once

#include <array>
#include <memory>

#include "glint/model/platform.h"
#include "glint/motion/euler.h"
#include "glint/motion/trajectory.h"

namespace glint::test {

/// attachment > static mount "Mount" (rotation in rad, xyz) > attachment > instrument "Cam".
inline std::shared_ptr<model::Platform> one_mount_platform(
    std::array<double, 3> mount_rotation_rad = {}) {
    auto platform = std::make_shared<model::Platform>();
    model::Instrument cam;
    cam.name = "Cam";
    model::Attachment inner;
    inner.instruments.push_back(cam);
    model::Mount mount;
    mount.name = "Mount";
    mount.rotation_rad = mount_rotation_rad;
    mount.attachments.push_back(inner);
    model::Attachment outer;
    outer.mounts.push_back(mount);
    platform->attachments.push_back(outer);
    return platform;
}

/// A vehicle hovering level at (0, 0, height_m) in scene ENU: with one_mount_platform, a
/// nadir camera.
class HoverTrajectory : public motion::Trajectory {
public:
    explicit HoverTrajectory(double height_m) : m_height_m(height_m) {}
    motion::Pose pose_at(double) const override {
        return {{0, 0, m_height_m}, motion::euler_to_quaternion({}, motion::EulerOrder::xyz)};
    }
    motion::Vec3 velocity_m_s(double) const override { return {}; }
    std::optional<motion::TimeSpan> span() const override { return std::nullopt; }

private:
    double m_height_m;
};

}  // namespace glint::test
