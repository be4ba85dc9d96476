// SPDX-License-Identifier: Apache-2.0
// Unprogrammed motion ("jitter") as S. D. Brown and A. A. Goodenough describe it in
// "Plugin-driven sensor modeling of remote sensing imaging systems", IGARSS 2017
// (docs/references.md): each degree of freedom either uncorrelated (normal deviates with a
// mean and σ, drawn per sample time) or correlated, synthesised from a user power spectral
// density. Platform jitter has six degrees of freedom (location x/y/z in m, orientation x/y/z
// in rad); mount jitter (platform.h, JitterSpec) two or three, in rad.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/diagnostics.h"
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
    double stddev = 0.0;  ///< normal
    FileRef psd_file;     ///< psd given as a file (frequency, psd[, phase] lines)
    /// The PSD: given inline (FlexMotion `<psd>` entries), or psd_file's table as the input
    /// loader (glint/inputs) read it.
    std::optional<PsdTable> psd;
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

/// The value rules of one PSD row, given the frequency of the last good row before it
/// (frequency finite, ≥ 0 and greater than the previous one; PSD finite and ≥ 0); `report`
/// receives each problem's message.
void check_psd_row(double frequency_hz, double psd, std::optional<double> previous_frequency_hz,
                   const std::function<void(const std::string&)>& report);

/// Checks a whole table by the rules of the PSD file format: equal column lengths (phases
/// empty or one per row), at least 2 rows, check_psd_row on every row, finite phases. Each
/// problem is an error at `table.where`, naming the 1-based row.
void validate_psd_table(const PsdTable& table, Diagnostics& diagnostics);

}  // namespace glint::model
