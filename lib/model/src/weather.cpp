// SPDX-License-Identifier: Apache-2.0
// Interpolation of a weather history (glint/model/weather.h).
#include "glint/model/weather.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace glint::model {

WeatherRecord Weather::at(double time_h) const noexcept {
    if (records.size() == 1 || !(time_h > records.front().time_h)) return records.front();
    if (!(time_h < records.back().time_h)) return records.back();
    const auto after =
        std::upper_bound(records.begin(), records.end(), time_h,
                         [](double t, const WeatherRecord& r) { return t < r.time_h; });
    const WeatherRecord& b = *after;
    const WeatherRecord& a = *(after - 1);
    const double f = (time_h - a.time_h) / (b.time_h - a.time_h);
    const auto mix = [f](double x, double y) { return x + f * (y - x); };
    WeatherRecord r = a;
    r.time_h = time_h;
    r.air_temperature_k = mix(a.air_temperature_k, b.air_temperature_k);
    r.pressure_hpa = mix(a.pressure_hpa, b.pressure_hpa);
    r.relative_humidity = mix(a.relative_humidity, b.relative_humidity);
    r.dew_point_k = mix(a.dew_point_k, b.dew_point_k);
    r.wind_speed_m_per_s = mix(a.wind_speed_m_per_s, b.wind_speed_m_per_s);
    r.direct_insolation_w_per_m2 = mix(a.direct_insolation_w_per_m2, b.direct_insolation_w_per_m2);
    r.diffuse_insolation_w_per_m2 =
        mix(a.diffuse_insolation_w_per_m2, b.diffuse_insolation_w_per_m2);
    r.sky_exposure = mix(a.sky_exposure, b.sky_exposure);
    r.precipitation_cm_per_h = mix(a.precipitation_cm_per_h, b.precipitation_cm_per_h);
    r.precipitation_temperature_k =
        mix(a.precipitation_temperature_k, b.precipitation_temperature_k);
    return r;
}

}  // namespace glint::model
