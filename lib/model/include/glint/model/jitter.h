// SPDX-License-Identifier: Apache-2.0
// Unprogrammed motion ("jitter") as the paper describes it: each degree of freedom either
// uncorrelated (normal deviates with a mean and σ, drawn per sample time) or correlated,
// synthesised from a user power spectral density. Platform jitter has six degrees of
// freedom (location x/y/z in m, orientation x/y/z in rad); mount jitter (platform.h,
// JitterAxis) two or three, in rad.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "glint/model/common.h"

namespace glint::model {

/// A one-sided power spectral density table: frequencies strictly increasing, ≥ 0, PSD ≥ 0
/// in unit²/Hz (m²/Hz for location, rad²/Hz for orientation), optional phases in rad.
struct PsdTable {
    std::vector<double> frequency_hz;
    std::vector<double> psd;
    std::vector<double> phase_rad;  ///< empty = phases drawn from the seeded RNG
    ErrorContext where;
};

/// Jitter of one degree of freedom (unit: m for location axes, rad for orientation axes).
struct JitterSpec {
    enum class Kind { none, normal, psd };
    Kind kind = Kind::none;
    double mean = 0.0;
    double stddev = 0.0;          ///< normal
    FileRef psd_file;             ///< psd given as a file (frequency, psd[, phase] lines)
    std::optional<PsdTable> psd;  ///< psd given inline (FlexMotion `<psd>` entries)
    ErrorContext where;
};

/// Six-degree-of-freedom platform jitter (`locationjitter` / `orientationjitter`).
struct PlatformJitter {
    std::array<JitterSpec, 3> location_m;       ///< x, y, z in scene ENU
    std::array<JitterSpec, 3> orientation_rad;  ///< about x, y, z of the vehicle

    /// True when any axis has jitter.
    bool any() const {
        for (const auto& a : location_m)
            if (a.kind != JitterSpec::Kind::none) return true;
        for (const auto& a : orientation_rad)
            if (a.kind != JitterSpec::Kind::none) return true;
        return false;
    }
};

}  // namespace glint::model
