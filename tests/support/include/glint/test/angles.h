// SPDX-License-Identifier: Apache-2.0
// π and the degree for tests, one definition for every test file (test files are compiled
// together in unity builds, where two file-local kPi would collide).
#pragma once

#include <numbers>

namespace glint::test {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kDeg = kPi / 180.0;  ///< radians per degree

}  // namespace glint::test
