// SPDX-License-Identifier: Apache-2.0
// Small motions built in code for the tests of what moves in a scene (motion, radiometry).
#pragma once

#include "glint/model/motion.h"

namespace glint::test {

/// A GenericMotion ("drive.ppd") from (10, 0, 0) m at 0 s to (50, 0, 0) m at 4 s: due east
/// at 10 m/s, at (10 + 10 t, 0, 0) m in between.
inline model::PlatformMotion driving_east() {
    model::GenericMotion generic;
    generic.entries.resize(2);
    generic.entries[0].time_s = 0.0;
    generic.entries[0].location.xyz_m = {10.0, 0.0, 0.0};
    generic.entries[1].time_s = 4.0;
    generic.entries[1].location.xyz_m = {50.0, 0.0, 0.0};
    model::PlatformMotion motion;
    motion.file = "drive.ppd";
    motion.generic = generic;
    return motion;
}

}  // namespace glint::test
