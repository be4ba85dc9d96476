// SPDX-License-Identifier: Apache-2.0
// A weather history: DIRSIG's `.wth` file (glint/dirsig/wth_reader.h) in SI units, the forcing
// of the THERM surface temperatures (docs/thermal.md, "Weather"). Plain data.
#pragma once

#include <string>
#include <vector>

#include "glint/core/error.h"

namespace glint::model {

/// One row of a weather history.
struct WeatherRecord {
    double time_h = 0.0;  ///< hours from the history's start (local time)
    double air_temperature_k = 0.0;
    double pressure_hpa = 0.0;
    double relative_humidity = 0.0;  ///< fraction, [0, 1]
    double dew_point_k = 0.0;
    double wind_speed_m_per_s = 0.0;
    double direct_insolation_w_per_m2 = 0.0;   ///< the sun's beam
    double diffuse_insolation_w_per_m2 = 0.0;  ///< the sky's, on a horizontal surface
    double sky_exposure = 1.0;  ///< 0: overcast … 1: clear
    int cloud_type = 0;
    int precipitation_type = 0;
    double precipitation_cm_per_h = 0.0;
    double precipitation_temperature_k = 0.0;
    int line = 0;  ///< in the file
};

/// A weather history: rows every step_h hours from 0.
struct Weather {
    std::string file;  ///< as read (empty: none)
    double step_h = 0.25;
    std::vector<WeatherRecord> records;
    ErrorContext where;  ///< what named it (the plugin input or the .atm element)

    bool empty() const noexcept { return records.empty(); }
    /// The history at `time_h`, linear between rows, the first and last rows held beyond.
    /// Integer columns are the earlier row's. Requires !empty().
    WeatherRecord at(double time_h) const noexcept;
};

/// Langley per hour (1 cal/cm² per hour) in W/m².
inline constexpr double kLangleyPerHourWPerM2 = 41868.0 / 3600.0;

}  // namespace glint::model
