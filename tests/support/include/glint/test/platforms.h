// SPDX-License-Identifier: Apache-2.0
// Small platforms built in code for the pose-service tests (motion, sensor).
#pragma once

#include <array>
#include <memory>

#include "glint/model/platform.h"

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

}  // namespace glint::test
