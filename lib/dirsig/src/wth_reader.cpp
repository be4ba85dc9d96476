// SPDX-License-Identifier: Apache-2.0
// The `.wth` weather history of glint/dirsig/wth_reader.h.
#include "glint/dirsig/wth_reader.h"

#include <cctype>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/text.h"

namespace glint::dirsig {
namespace {

constexpr double kCelsius = 273.15;
constexpr std::size_t kColumns = 13;
/// A row's time may differ from its index × step by this much, h (the files print 2 decimals).
constexpr double kTimeTolerance_h = 0.006;

/// The numbers of a line; a sign after a digit or a point starts a new number. Nullopt when
/// a field is not a number (`bad` names it).
std::optional<std::vector<double>> numbers_of(std::string_view line, std::string& bad) {
    std::vector<double> out;
    std::string token;
    const auto flush = [&]() -> bool {
        if (token.empty()) return true;
        const auto v = parse_double(token);
        if (!v || !std::isfinite(*v)) {
            bad = token;
            return false;
        }
        out.push_back(*v);
        token.clear();
        return true;
    };
    for (const char c : line) {
        if (c == ' ' || c == '\t' || c == ',' || c == '\r') {
            if (!flush()) return std::nullopt;
        } else if ((c == '-' || c == '+') && !token.empty() &&
                   (std::isdigit(static_cast<unsigned char>(token.back())) ||
                    token.back() == '.')) {
            if (!flush()) return std::nullopt;
            token.push_back(c);
        } else {
            token.push_back(c);
        }
    }
    if (!flush()) return std::nullopt;
    return out;
}

bool is_integer(double v) { return v == std::floor(v); }

}  // namespace

model::Weather parse_wth(std::string_view text, const std::string& file, Diagnostics& diagnostics) {
    model::Weather weather;
    weather.file = file;
    const std::size_t errors_before = diagnostics.error_count();
    const auto error = [&](int line, const std::string& message) {
        diagnostics.error(ErrorContext{file, line, {}}, message);
    };
    std::optional<long long> declared_rows;
    int line_number = 0;
    int last_line = 1;  ///< the last line with numbers
    int first_precipitation = 0;
    int first_cloud = 0;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::string line(trim(std::string(text.substr(start, end - start))));
        start = end + 1;
        ++line_number;
        if (line.empty() || line.front() == '#') {
            if (end == text.size()) break;
            continue;
        }
        last_line = line_number;
        std::string bad;
        const auto values = numbers_of(line, bad);
        if (!values) {
            error(line_number, "\"" + bad + "\" is not a number");
        } else if (!declared_rows) {
            // The header: rows and step.
            if (values->size() != 2 || !is_integer((*values)[0]) || (*values)[0] < 1.0 ||
                !((*values)[1] > 0.0)) {
                error(line_number,
                      "expected the header: the number of rows and the hours between them "
                      "(DIRSIG writes \"193 0.250000\")");
                return weather;
            }
            declared_rows = static_cast<long long>((*values)[0]);
            weather.step_h = (*values)[1];
        } else if (values->size() != kColumns) {
            error(line_number,
                  std::to_string(values->size()) +
                      " values, expected 13: time (h), air temperature (C), pressure (mbar), "
                      "relative humidity (0-1), dew point (C), wind speed (m/s), direct and "
                      "diffuse insolation (Langley/h), sky exposure (0-1), cloud type, "
                      "precipitation type, precipitation rate (cm/h), precipitation "
                      "temperature (C)");
        } else {
            const std::vector<double>& v = *values;
            model::WeatherRecord r;
            r.line = line_number;
            r.time_h = v[0];
            r.air_temperature_k = v[1] + kCelsius;
            r.pressure_hpa = v[2];
            r.relative_humidity = v[3];
            r.dew_point_k = v[4] + kCelsius;
            r.wind_speed_m_per_s = v[5];
            r.direct_insolation_w_per_m2 = v[6] * model::kLangleyPerHourWPerM2;
            r.diffuse_insolation_w_per_m2 = v[7] * model::kLangleyPerHourWPerM2;
            r.sky_exposure = v[8];
            r.cloud_type = static_cast<int>(v[9]);
            r.precipitation_type = static_cast<int>(v[10]);
            r.precipitation_cm_per_h = v[11];
            r.precipitation_temperature_k = v[12] + kCelsius;
            const double expected_h = static_cast<double>(weather.records.size()) * weather.step_h;
            if (std::abs(r.time_h - expected_h) > kTimeTolerance_h) {
                error(line_number, "time " + format_shortest(r.time_h) + " h, expected " +
                                       format_shortest(expected_h) +
                                       " h (one row every step of the header, from 0)");
            } else if (r.air_temperature_k <= 0.0 || r.dew_point_k <= 0.0) {
                error(line_number, "an air or dew-point temperature below absolute zero");
            } else if (!(r.pressure_hpa > 0.0)) {
                error(line_number, "pressure " + format_shortest(v[2]) + " mbar is not > 0");
            } else if (r.relative_humidity < 0.0 || r.relative_humidity > 1.0) {
                error(line_number, "relative humidity " + format_shortest(v[3]) +
                                       " is not a fraction in [0, 1]" +
                                       (v[3] > 1.0 && v[3] <= 100.0 ? " (a percentage?)" : ""));
            } else if (r.wind_speed_m_per_s < 0.0 || v[6] < 0.0 || v[7] < 0.0 || v[11] < 0.0) {
                error(line_number, "a negative wind speed, insolation or precipitation rate");
            } else if (r.sky_exposure < 0.0 || r.sky_exposure > 1.0) {
                error(line_number, "sky exposure " + format_shortest(v[8]) +
                                       " is not in [0, 1] (0 overcast, 1 clear)");
            } else if (!is_integer(v[9]) || !is_integer(v[10])) {
                error(line_number, "the cloud and precipitation types must be integers");
            }
            if (r.precipitation_cm_per_h > 0.0 && first_precipitation == 0) {
                first_precipitation = line_number;
            }
            if (r.cloud_type != 0 && first_cloud == 0) first_cloud = line_number;
            weather.records.push_back(r);
        }
        if (end == text.size()) break;
    }
    if (!declared_rows) {
        error(last_line, "no header line (the number of rows and the hours between them)");
    } else if (diagnostics.error_count() == errors_before &&
               static_cast<long long>(weather.records.size()) != *declared_rows) {
        error(last_line, "the header says " + std::to_string(*declared_rows) +
                             " rows, the file has " + std::to_string(weather.records.size()));
    }
    if (first_precipitation > 0) {
        diagnostics.warning(ErrorContext{file, first_precipitation, {}},
                            "precipitation is not modelled: its rate and temperature columns "
                            "are read but its cooling of surfaces is left out (said once per "
                            "file)");
    }
    if (first_cloud > 0) {
        diagnostics.warning(ErrorContext{file, first_cloud, {}},
                            "cloud types are not modelled: the sky exposure column says how "
                            "much of the sky is clear (said once per file)");
    }
    if (diagnostics.error_count() > errors_before) weather.records.clear();
    return weather;
}

model::Weather read_wth(const std::filesystem::path& path, const ReadOptions& options,
                        Diagnostics& diagnostics) {
    const std::string name = path.string();
    const std::optional<std::string> text = options.read_text_reported(path, name, diagnostics);
    if (!text) {
        model::Weather none;
        none.file = name;
        return none;
    }
    return parse_wth(*text, name, diagnostics);
}

}  // namespace glint::dirsig
