// SPDX-License-Identifier: Apache-2.0
// The rules of a PSD table (glint/model/jitter.h), shared by the PSD file reader and inline
// FlexMotion tables.
#include "glint/model/jitter.h"

#include <cmath>
#include <string>

#include "glint/core/text.h"

namespace glint::model {
namespace {

/// Shortest text that reads back as `value`.
std::string num(double value) { return format_shortest(value); }

}  // namespace

void check_psd_row(double frequency_hz, double psd, std::optional<double> previous_frequency_hz,
                   const std::function<void(const std::string&)>& report) {
    if (!std::isfinite(frequency_hz)) {
        report("frequency " + num(frequency_hz) + " is not a finite number");
    } else if (frequency_hz < 0.0) {
        report("frequency " + num(frequency_hz) + " Hz is negative");
    } else if (previous_frequency_hz && !(frequency_hz > *previous_frequency_hz)) {
        report("frequency " + num(frequency_hz) + " Hz is not greater than the previous " +
               num(*previous_frequency_hz) + " Hz; frequencies must be strictly increasing");
    }
    if (!std::isfinite(psd)) {
        report("psd " + num(psd) + " is not a finite number");
    } else if (psd < 0.0) {
        report("psd " + num(psd) + " is negative");
    }
}

void validate_psd_table(const model::PsdTable& table, Diagnostics& diagnostics) {
    const std::size_t rows = table.frequency_hz.size();
    if (table.psd.size() != rows) {
        diagnostics.error(table.where, "PSD table has " + std::to_string(rows) +
                                           " frequencies but " + std::to_string(table.psd.size()) +
                                           " PSD values");
        return;
    }
    if (!table.phase_rad.empty() && table.phase_rad.size() != rows) {
        diagnostics.error(table.where, "PSD table has " + std::to_string(rows) + " rows but " +
                                           std::to_string(table.phase_rad.size()) +
                                           " phases; give a phase on every row or on none");
        return;
    }
    if (rows < 2) {
        diagnostics.error(
            table.where, "PSD table has " + std::to_string(rows) + " rows; a PSD needs at least 2");
        return;
    }
    std::optional<double> previous_frequency_hz;
    for (std::size_t i = 0; i < rows; ++i) {
        const std::string row = "PSD row " + std::to_string(i + 1) + ": ";
        check_psd_row(
            table.frequency_hz[i], table.psd[i], previous_frequency_hz,
            [&](const std::string& message) { diagnostics.error(table.where, row + message); });
        if (!table.phase_rad.empty() && !std::isfinite(table.phase_rad[i])) {
            diagnostics.error(table.where,
                              row + "phase " + num(table.phase_rad[i]) + " is not a finite number");
        }
        const double f = table.frequency_hz[i];
        if (f >= 0.0 && std::isfinite(f) &&
            (!previous_frequency_hz || f > *previous_frequency_hz)) {
            previous_frequency_hz = f;
        }
    }
}

}  // namespace glint::model
