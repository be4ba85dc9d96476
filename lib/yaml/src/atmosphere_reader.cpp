// SPDX-License-Identifier: Apache-2.0
// The atmosphere readers (glint/yaml/atmosphere_reader.h): the YAML atmosphere read with
// yaml-cpp (line numbers from its marks), the DIRSIG .atm simpleradiativetransfer subset read
// with glint::io::XmlNode, and the tabulated model's table file.
#include "glint/yaml/atmosphere_reader.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "aerosol_profile_reader.h"
#include "glint/core/text.h"
#include "glint/io/xml.h"
#include "yaml_keys.h"
#include "yaml_text.h"

namespace glint::yaml {
namespace {

using detail::at;
using detail::Bounds;
using detail::read_number;
using detail::read_optional_number;

std::string num(double value) { return format_shortest(value); }

void read_flag(const YAML::Node& map, const char* key, const std::string& file, bool& value,
               Diagnostics& diagnostics) {
    const YAML::Node node = map[key];
    if (!node) return;
    const auto parsed = node.IsScalar() ? parse_bool(node.Scalar()) : std::nullopt;
    if (parsed) {
        value = *parsed;
    } else {
        diagnostics.error(at(file, node, key), "expected true or false");
    }
}

const Bounds kNonNegative{0.0, std::nullopt, false, false, "a number >= 0"};
const Bounds kPositive{0.0, std::nullopt, true, false, "a number > 0"};
const Bounds kAny{std::nullopt, std::nullopt, false, false, "a number"};
const Bounds kFraction{0.0, 1.0, false, false, "a number in [0, 1]"};
const Bounds kAsymmetry{-1.0, 1.0, true, true, "a number in (-1, 1)"};
/// The thickest aerosol a parametric atmosphere takes: an optical depth of 100 at 550 nm
/// lets e^-100 of the sun through (the densest smoke and dust measured reach about 7; a fog
/// of 100 m visibility about 47). Beyond it a value is a typo, not an atmosphere.
constexpr double kMaxAerosolDepth550 = 100.0;
const Bounds kAerosolDepth{0.0, kMaxAerosolDepth550, false, false, "a number in [0, 100]"};

/// The keys of the exponential aerosol, which an aerosol_model replaces.
constexpr const char* kExponentialAerosolKeys[] = {"angstrom_exponent", "aerosol_scale_height_m",
                                                   "aerosol_asymmetry",
                                                   "aerosol_single_scatter_albedo"};
/// The keys of the layered aerosol, which only an aerosol_model uses.
constexpr const char* kLayeredAerosolKeys[] = {"relative_humidity_percent", "aerosol_season",
                                               "tropospheric_aerosol", "stratospheric_aerosol"};

/// aerosol_model: LOWTRAN 7's layered profiles with OPAC's optics, the boundary layer of this
/// type (glint/model/aerosol_models.h); with it, visibility_km sets the profiles,
/// aerosol_optical_depth_550 scales them, and the exponential aerosol's keys are errors.
void read_aerosol_model(const YAML::Node& root, const std::string& file,
                        model::ParametricAtmosphere& p, Diagnostics& diagnostics) {
    const YAML::Node node = root["aerosol_model"];
    if (root["aerosol_profile"]) return;  // the profile's reader handles the keys beside it
    if (!node) {
        for (const char* key : kLayeredAerosolKeys) {
            if (const YAML::Node unused = root[key]) {
                diagnostics.warning(at(file, unused, key),
                                    "has no effect: it belongs to the layered aerosol of an "
                                    "aerosol_model, and none is given");
            }
        }
        return;
    }
    const std::string name = node.IsScalar() ? node.Scalar() : std::string{};
    if (!model::aerosol_mixture_named(name) || name == "stratospheric") {
        diagnostics.error(at(file, node, "aerosol_model"),
                          std::string("expected a boundary-layer type, one of ") +
                              model::aerosol_mixture_names() + " but stratospheric, got '" + name +
                              "'");
        return;
    }
    p.aerosol_model = name;
    for (const char* key : kExponentialAerosolKeys) {
        if (const YAML::Node clash = root[key]) {
            diagnostics.error(at(file, clash, key),
                              "aerosol_model sets the aerosol's optics and profile (OPAC's Mie "
                              "optics, LOWTRAN 7's layers); give " +
                                  std::string(key) + " only without it");
        }
    }
    const Bounds positive{0.0, std::nullopt, true, false, "a number > 0"};
    read_number(root, "visibility_km", file, positive, p.visibility_km, diagnostics);
    if (const YAML::Node depth = root["aerosol_optical_depth_550"]) {
        if (root["visibility_km"]) {
            diagnostics.error(at(file, root["visibility_km"], "visibility_km"),
                              "give aerosol_optical_depth_550 or visibility_km, not both");
        }
        if (const auto value = read_optional_number(root, "aerosol_optical_depth_550", file,
                                                    kAerosolDepth, diagnostics)) {
            p.aerosol_column_depth_550 = value;
        }
    }
    const Bounds percent{0.0, 100.0, false, false, "a number in [0, 100]"};
    if (const auto rh =
            read_optional_number(root, "relative_humidity_percent", file, percent, diagnostics)) {
        p.relative_humidity_percent = rh;
    }
    if (const YAML::Node season = root["aerosol_season"]) {
        const std::string value = season.IsScalar() ? season.Scalar() : std::string{};
        if (value == "spring_summer") {
            p.aerosol_season = model::AerosolSeason::spring_summer;
        } else if (value == "fall_winter") {
            p.aerosol_season = model::AerosolSeason::fall_winter;
        } else {
            diagnostics.error(at(file, season, "aerosol_season"),
                              "expected spring_summer or fall_winter, got '" + value + "'");
        }
    }
    for (const auto& [key, target] :
         {std::pair<const char*, std::string*>{"tropospheric_aerosol", &p.tropospheric_aerosol},
          std::pair<const char*, std::string*>{"stratospheric_aerosol",
                                               &p.stratospheric_aerosol}}) {
        const YAML::Node type = root[key];
        if (!type) continue;
        const std::string value = type.IsScalar() ? type.Scalar() : std::string{};
        if (value != "none" && !model::aerosol_mixture_named(value)) {
            diagnostics.error(at(file, type, key), std::string("expected one of ") +
                                                       model::aerosol_mixture_names() +
                                                       ", none, got '" + value + "'");
            continue;
        }
        *target = value;
    }
}

/// visibility_km: the aerosol optical depth at 550 nm from Koschmieder's law,
/// τ₅₅₀ = (3.912/V − β_Rayleigh) · H_a.
void read_visibility(const YAML::Node& root, const std::string& file,
                     model::ParametricAtmosphere& p, Diagnostics& diagnostics) {
    const YAML::Node node = root["visibility_km"];
    // The layered aerosol reads it itself; beside a profile it is an error there.
    if (!node || root["aerosol_model"] || root["aerosol_profile"]) return;
    const ErrorContext where = at(file, node, "visibility_km");
    if (root["aerosol_optical_depth_550"]) {
        diagnostics.error(where, "give aerosol_optical_depth_550 or visibility_km, not both");
        return;
    }
    double visibility_km = 0.0;
    const Bounds positive{0.0, std::nullopt, true, false, "a number > 0"};
    const std::size_t errors = diagnostics.error_count();
    read_number(root, "visibility_km", file, positive, visibility_km, diagnostics);
    if (diagnostics.error_count() != errors) return;
    const double extinction_per_km =
        model::kKoschmieder / visibility_km - model::kRayleighExtinction550PerKm;
    if (!(extinction_per_km > 0.0)) {
        diagnostics.error(
            where, "visibility " + num(visibility_km) + " km is beyond that of aerosol-free air (" +
                       std::to_string(static_cast<int>(model::kKoschmieder /
                                                       model::kRayleighExtinction550PerKm)) +
                       " km)");
        return;
    }
    const double depth = extinction_per_km * p.aerosol_scale_height_m / 1000.0;
    if (depth > kMaxAerosolDepth550) {
        char shown[32];
        std::snprintf(shown, sizeof shown, "%.4g", depth);
        diagnostics.error(where, "visibility " + num(visibility_km) +
                                     " km gives an aerosol optical depth of " + shown +
                                     " at 550 nm, beyond the 100 glint takes");
        return;
    }
    p.aerosol_optical_depth_550 = depth;
}

/// profile: the air's temperature profile, and the defaults of the sea-level air
/// temperature and of the water and ozone columns (keys given explicitly are read after, and
/// win). The isothermal profile keeps every default.
void read_profile(const YAML::Node& root, const std::string& file, model::ParametricAtmosphere& p,
                  Diagnostics& diagnostics) {
    const YAML::Node node = root["profile"];
    if (!node) return;
    const std::string name = node.IsScalar() ? node.Scalar() : std::string{};
    const std::optional<model::StandardAtmosphere> which = model::standard_atmosphere_named(name);
    if (!which) {
        diagnostics.error(
            at(file, node, "profile"),
            std::string("expected ") + model::standard_atmosphere_names() + ", got '" + name + "'");
        return;
    }
    p.profile = *which;
    if (*which == model::StandardAtmosphere::isothermal) return;
    const model::StandardAtmosphereProfile& table = model::standard_atmosphere(*which);
    p.air_temperature_k = model::profile_temperature_k(table.levels, 0.0);
    p.water_vapor_cm = table.water_column_cm;
    p.ozone_atm_cm = table.ozone_column_atm_cm;
}

/// Keys whose value the settings given with them leave without effect: one warning each at
/// its line (nothing a user wrote is dropped silently).
void warn_unused(const YAML::Node& root, const std::string& file,
                 const model::ParametricAtmosphere& p, Diagnostics& diagnostics) {
    const auto warn = [&](const char* key, const std::string& why) {
        if (const YAML::Node node = root[key]) {
            diagnostics.warning(at(file, node, key), "has no effect: " + why);
        }
    };
    if (!p.gas_absorption) {
        warn("water_vapor_cm", "gas_absorption is false");
        warn("ozone_atm_cm", "gas_absorption is false");
    } else {
        warn("water_vapor_pressure_hpa",
             "gas_absorption is true: the sky's emission is the gases' own (the vapour pressure "
             "sets only the grey Brutsaert sky of an atmosphere without gas absorption)");
    }
    if (!p.multiple_scattering) warn("ground_albedo", "multiple_scattering is false");
    if (p.profile == model::StandardAtmosphere::isothermal) {
        warn("refraction", "profile isothermal has no levels to refract through");
    }
}

void read_parametric(const YAML::Node& root, const std::string& file,
                     model::ParametricAtmosphere& p, Diagnostics& diagnostics) {
    read_aerosol_model(root, file, p, diagnostics);
    detail::read_aerosol_profile(root, file, p, diagnostics);
    read_profile(root, file, p, diagnostics);
    if (p.aerosol_model.empty() && !root["aerosol_profile"]) {
        read_number(root, "aerosol_optical_depth_550", file, kAerosolDepth,
                    p.aerosol_optical_depth_550, diagnostics);
        read_number(root, "angstrom_exponent", file, kAny, p.angstrom_exponent, diagnostics);
        read_number(root, "aerosol_scale_height_m", file, kPositive, p.aerosol_scale_height_m,
                    diagnostics);
        read_number(root, "aerosol_asymmetry", file, kAsymmetry, p.aerosol_asymmetry, diagnostics);
        read_number(root, "aerosol_single_scatter_albedo", file, kFraction,
                    p.aerosol_single_scatter_albedo, diagnostics);
    }
    if (const auto height_m =
            read_optional_number(root, "rayleigh_scale_height_m", file, kPositive, diagnostics)) {
        p.rayleigh_scale_height_m = height_m;
    }
    read_number(root, "sea_level_pressure_hpa", file, kNonNegative, p.sea_level_pressure_hpa,
                diagnostics);
    read_number(root, "air_temperature_k", file, kNonNegative, p.air_temperature_k, diagnostics);
    read_number(root, "water_vapor_pressure_hpa", file, kNonNegative, p.water_vapor_pressure_hpa,
                diagnostics);
    read_number(root, "water_vapor_cm", file, kNonNegative, p.water_vapor_cm, diagnostics);
    read_number(root, "ozone_atm_cm", file, kNonNegative, p.ozone_atm_cm, diagnostics);
    read_number(root, "ground_albedo", file, kFraction, p.ground_albedo, diagnostics);
    read_visibility(root, file, p, diagnostics);  // after the aerosol scale height
    read_flag(root, "gas_absorption", file, p.gas_absorption, diagnostics);
    read_flag(root, "multiple_scattering", file, p.multiple_scattering, diagnostics);
    read_flag(root, "directional_sky", file, p.directional_sky, diagnostics);
    read_flag(root, "refraction", file, p.refraction, diagnostics);
    warn_unused(root, file, p, diagnostics);
}

model::Atmosphere read_yaml(const std::string& text, const std::filesystem::path& path,
                            const std::string& file, const dirsig::ReadOptions& options,
                            Diagnostics& diagnostics) {
    model::Atmosphere atmosphere;
    atmosphere.where = ErrorContext{file, 0, {}};
    const std::optional<YAML::Node> parsed = detail::parse_yaml(text, file, diagnostics);
    if (!parsed) return atmosphere;
    const YAML::Node& root = *parsed;
    if (!root.IsMap()) {
        diagnostics.error(ErrorContext{file, root.Mark().line >= 0 ? root.Mark().line + 1 : 1, {}},
                          "expected a YAML mapping with a 'model' key");
        return atmosphere;
    }
    try {
        const YAML::Node model_node = root["model"];
        if (!model_node) {
            diagnostics.error(ErrorContext{file, 1, "model"},
                              "missing required key 'model' (none, parametric, tabulated)");
            return atmosphere;
        }
        const ErrorContext model_where = at(file, model_node, "model");
        atmosphere.where = model_where;
        const std::string name = model_node.IsScalar() ? model_node.Scalar() : std::string{};
        std::vector<std::string_view> known{"model", "weather"};
        // The weather history THERM is solved under (a DIRSIG .wth, relative to this file),
        // as a DIRSIG .atm's <uniformweather> names it.
        if (const YAML::Node weather = root["weather"]) {
            if (!weather.IsScalar() || weather.Scalar().empty()) {
                diagnostics.error(at(file, weather, "weather"),
                                  "'weather' is the path of a .wth weather history");
            } else {
                atmosphere.weather_file = weather.Scalar();
                atmosphere.weather_where = at(file, weather, "weather");
            }
        }
        if (name == "none") {
            atmosphere.kind = model::AtmosphereKind::none;
        } else if (name == "parametric") {
            atmosphere.kind = model::AtmosphereKind::parametric;
            known.insert(known.end(), {"aerosol_optical_depth_550",
                                       "angstrom_exponent",
                                       "aerosol_scale_height_m",
                                       "aerosol_asymmetry",
                                       "aerosol_single_scatter_albedo",
                                       "rayleigh_scale_height_m",
                                       "sea_level_pressure_hpa",
                                       "air_temperature_k",
                                       "water_vapor_pressure_hpa",
                                       "gas_absorption",
                                       "water_vapor_cm",
                                       "ozone_atm_cm",
                                       "multiple_scattering",
                                       "ground_albedo",
                                       "directional_sky",
                                       "refraction",
                                       "aerosol_model",
                                       "aerosol_profile",
                                       "visibility_km",
                                       "profile",
                                       "relative_humidity_percent",
                                       "aerosol_season",
                                       "tropospheric_aerosol",
                                       "stratospheric_aerosol"});
            read_parametric(root, file, atmosphere.parametric, diagnostics);
        } else if (name == "tabulated") {
            atmosphere.kind = model::AtmosphereKind::tabulated;
            known.insert(known.end(), {"table", "sky_temperature_k"});
            double sky_temperature_k = 0.0;
            read_number(root, "sky_temperature_k", file, kNonNegative, sky_temperature_k,
                        diagnostics);
            const YAML::Node table = root["table"];
            if (!table || !table.IsScalar() || table.Scalar().empty()) {
                diagnostics.error(table ? at(file, table, "table") : model_where,
                                  "tabulated model needs 'table': the path of a table file");
            } else {
                const ErrorContext where = at(file, table, "table");
                const model::FileRef ref =
                    options.paths.resolve(table.Scalar(), path.parent_path(), where, diagnostics);
                if (!ref.resolved.empty()) {
                    try {
                        atmosphere.tabulated = read_atmosphere_table(
                            ref.resolved, options, diagnostics, ref.resolved.string());
                    } catch (const Error& e) {
                        diagnostics.error(where, e.what());
                    }
                }
            }
            atmosphere.tabulated.sky_temperature_k = sky_temperature_k;
        } else {
            diagnostics.error(model_where, "unknown atmosphere model '" + name +
                                               "', expected none, parametric or tabulated");
            return atmosphere;
        }
        for (const auto& entry : root) {
            const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "?";
            bool found = false;
            for (std::string_view k : known) found = found || k == key;
            if (!found) {
                diagnostics.warning(at(file, entry.first, key),
                                    "unknown key '" + key + "' ignored for model " + name);
            }
        }
    } catch (const YAML::Exception& e) {
        diagnostics.error(ErrorContext{file, e.mark.line >= 0 ? e.mark.line + 1 : 0, {}},
                          std::string("malformed atmosphere: ") + e.msg);
    }
    return atmosphere;
}

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::vector<std::string> split_row(std::string_view line) {
    std::vector<std::string> fields;
    std::string current;
    for (char c : line) {
        if (is_blank(c) || c == ',') {
            if (!current.empty()) fields.push_back(std::move(current));
            current.clear();
        } else {
            current.push_back(c);
        }
    }
    if (!current.empty()) fields.push_back(std::move(current));
    return fields;
}

}  // namespace

model::TabulatedAtmosphere read_atmosphere_table(const std::filesystem::path& path,
                                                 const dirsig::ReadOptions& options,
                                                 Diagnostics& diagnostics,
                                                 const std::string& display_name) {
    const std::string file = display_name.empty() ? path.string() : display_name;
    const std::string text = options.read_text(path, file);
    model::TabulatedAtmosphere table;
    table.table_file = file;
    std::size_t columns = 0;
    int first_line = 0;
    int line_number = 0;
    std::size_t start = 0;
    if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) start = 3;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string_view line(text.data() + start, end - start);
        start = end + 1;
        ++line_number;
        if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) {
            line = line.substr(0, hash);
        }
        const std::vector<std::string> fields = split_row(line);
        if (fields.empty()) continue;
        const ErrorContext where{file, line_number, {}};
        if (fields.size() != 5 && fields.size() != 6) {
            diagnostics.error(where,
                              "expected 5 or 6 values (wavelength_um sun_T sensor_T "
                              "path_radiance sky_irradiance [thermal_sky_radiance]), "
                              "found " +
                                  std::to_string(fields.size()));
            continue;
        }
        if (columns == 0) {
            columns = fields.size();
            first_line = line_number;
        } else if (fields.size() != columns) {
            diagnostics.error(where, "row has " + std::to_string(fields.size()) +
                                         " values, the first row has " + std::to_string(columns));
            continue;
        }
        std::vector<double> v;
        bool ok = true;
        for (const std::string& f : fields) {
            const auto parsed = parse_double(f);
            if (!parsed) {
                diagnostics.error(where, "'" + f + "' is not a finite number");
                ok = false;
                break;
            }
            v.push_back(*parsed);
        }
        if (!ok) continue;
        if (v[0] <= 0.0) {
            diagnostics.error(where, "wavelength " + num(v[0]) + " um must be > 0");
            continue;
        }
        if (!table.wavelengths_um.empty() && v[0] <= table.wavelengths_um.back()) {
            diagnostics.error(where, "wavelength " + num(v[0]) +
                                         " um is not greater than the previous row's " +
                                         num(table.wavelengths_um.back()));
            continue;
        }
        if (v[1] < 0.0 || v[1] > 1.0 || v[2] < 0.0 || v[2] > 1.0) {
            diagnostics.error(where, "transmittances must lie in [0, 1]");
            continue;
        }
        if (v[3] < 0.0 || v[4] < 0.0 || (v.size() == 6 && v[5] < 0.0)) {
            diagnostics.error(where, "radiances and irradiances must be >= 0");
            continue;
        }
        table.wavelengths_um.push_back(v[0]);
        table.sun_transmittance.push_back(v[1]);
        table.sensor_transmittance.push_back(v[2]);
        table.path_radiance_w_per_cm2_sr_um.push_back(v[3]);
        table.sky_irradiance_w_per_cm2_um.push_back(v[4]);
        if (v.size() == 6) table.thermal_sky_radiance_w_per_cm2_sr_um.push_back(v[5]);
    }
    if (table.wavelengths_um.size() < 2) {
        diagnostics.error(ErrorContext{file, first_line, {}},
                          "atmosphere table needs at least 2 rows, found " +
                              std::to_string(table.wavelengths_um.size()));
    }
    return table;
}

model::Atmosphere parse_yaml_atmosphere(const std::string& text, const std::filesystem::path& path,
                                        const std::string& display_name,
                                        const dirsig::ReadOptions& options,
                                        Diagnostics& diagnostics) {
    const std::string file = display_name.empty() ? path.string() : display_name;
    return read_yaml(text, path, file, options, diagnostics);
}

}  // namespace glint::yaml
