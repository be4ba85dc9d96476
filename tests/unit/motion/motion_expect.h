// SPDX-License-Identifier: Apache-2.0
// gtest expectations shared by the motion tests: vectors, matrices and rotations compared
// component by component within a tolerance; the glint::Error a callable throws; warnings
// collected from a Log.
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <mutex>
#include <string>
#include <vector>

#include "glint/core/error.h"
#include "glint/core/log.h"
#include "glint/motion/geometry.h"

namespace glint::motion {

inline void expect_near(const Vec3& a, const Vec3& b, double tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance) << "x";
    EXPECT_NEAR(a.y, b.y, tolerance) << "y";
    EXPECT_NEAR(a.z, b.z, tolerance) << "z";
}

inline void expect_near(const Mat3& a, const Mat3& b, double tolerance) {
    for (std::size_t i = 0; i < 3; ++i) {
        for (std::size_t j = 0; j < 3; ++j) {
            EXPECT_NEAR(a(i, j), b(i, j), tolerance) << i << "," << j;
        }
    }
}

/// q and r are the same rotation (q = ±r).
inline void expect_same_rotation(const Quaternion& q, const Quaternion& r, double tolerance) {
    const double sign = dot(q, r) < 0.0 ? -1.0 : 1.0;
    EXPECT_NEAR(q.w, sign * r.w, tolerance);
    EXPECT_NEAR(q.x, sign * r.x, tolerance);
    EXPECT_NEAR(q.y, sign * r.y, tolerance);
    EXPECT_NEAR(q.z, sign * r.z, tolerance);
}

/// The glint::Error thrown by `f` (fails the test when none is).
template <typename F>
Error thrown(F&& f) {
    try {
        f();
    } catch (const Error& error) {
        return error;
    }
    ADD_FAILURE() << "no glint::Error thrown";
    return internal_error("none");
}

/// Warnings collected from a Log (thread-safe).
struct Warnings {
    std::mutex mutex;
    std::vector<std::string> items;

    Log log() {
        return Log(
            [this](LogLevel, const std::string& message) {
                const std::lock_guard<std::mutex> lock(mutex);
                items.push_back(message);
            },
            LogLevel::warning);
    }
};

}  // namespace glint::motion
