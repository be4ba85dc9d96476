// SPDX-License-Identifier: Apache-2.0
// The YAML atmosphere's aerosol_profile (aerosol_profile_reader.h).
#include "aerosol_profile_reader.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "glint/core/text.h"
#include "glint/model/aerosol_models.h"
#include "yaml_keys.h"

namespace glint::yaml::detail {
namespace {

/// The most layers a profile takes: each is a regime the scattering solver sums over at
/// every wavelength and direction (LOWTRAN's and libRadtran's profiles have 30–50 levels).
constexpr std::size_t kMaxProfileLayers = 200;
/// The top of glint's atmosphere, km.
constexpr double kProfileTopKm = 100.0;

std::optional<double> profile_number(const YAML::Node& node) {
    if (!node.IsScalar()) return std::nullopt;
    const std::optional<double> v = parse_double(node.Scalar());
    if (!v || !std::isfinite(*v)) return std::nullopt;
    return v;
}

const Bounds kZeroToHundred{0.0, 100.0, false, false, "a number in [0, 100]"};

/// The keys beside aerosol_profile: errors for the other aerosols' keys, warnings for the
/// layered aerosol's that have no effect, the scaling depth and the humidity read.
void read_profile_companions(const YAML::Node& root, const std::string& file,
                             model::ParametricAtmosphere& p, Diagnostics& diagnostics) {
    if (const YAML::Node clash = root["aerosol_model"]) {
        diagnostics.error(at(file, clash, "aerosol_model"),
                          "give aerosol_model or aerosol_profile, not both");
    }
    for (const char* key : {"angstrom_exponent", "aerosol_scale_height_m", "aerosol_asymmetry",
                            "aerosol_single_scatter_albedo", "visibility_km"}) {
        if (const YAML::Node clash = root[key]) {
            diagnostics.error(at(file, clash, key),
                              "aerosol_profile sets the aerosol's optics and amount (OPAC's Mie "
                              "optics, its own densities; aerosol_optical_depth_550 scales it); "
                              "give " +
                                  std::string(key) + " only without it");
        }
    }
    for (const char* key : {"aerosol_season", "tropospheric_aerosol", "stratospheric_aerosol"}) {
        if (const YAML::Node unused = root[key]) {
            diagnostics.warning(at(file, unused, key),
                                "has no effect: it belongs to the layered aerosol of an "
                                "aerosol_model, and aerosol_profile replaces it");
        }
    }
    // Both [0, 100]: a percentage, and the depth range of every aerosol.
    if (const auto depth = read_optional_number(root, "aerosol_optical_depth_550", file,
                                                kZeroToHundred, diagnostics)) {
        p.aerosol_column_depth_550 = depth;
    }
    if (const auto rh = read_optional_number(root, "relative_humidity_percent", file,
                                             kZeroToHundred, diagnostics)) {
        p.relative_humidity_percent = rh;
    }
}

/// components: a sequence of distinct OPAC component names.
bool read_profile_components(const YAML::Node& profile, const std::string& file,
                             model::AerosolProfile& out, Diagnostics& diagnostics) {
    const YAML::Node node = profile["components"];
    const ErrorContext where = at(file, node ? node : profile, "aerosol_profile.components");
    if (!node || !node.IsSequence() || node.size() == 0) {
        diagnostics.error(where, std::string("expected a list of OPAC components (") +
                                     model::aerosol_component_names() + ")");
        return false;
    }
    std::set<std::string> seen;
    bool ok = true;
    for (const YAML::Node& item : node) {
        const std::string name = item.IsScalar() ? item.Scalar() : std::string{};
        const ErrorContext here = at(file, item, "aerosol_profile.components");
        if (!model::is_aerosol_component(name)) {
            diagnostics.error(here, std::string("expected one of ") +
                                        model::aerosol_component_names() + ", got '" + name + "'");
            ok = false;
        } else if (!seen.insert(name).second) {
            diagnostics.error(here, "component '" + name + "' is listed twice");
            ok = false;
        }
        out.components.push_back(name);
    }
    return ok;
}

/// levels: rows [altitude_km, density...], monotonic in altitude; stored ascending, the top
/// row closing the profile (its densities must be 0).
bool read_profile_levels(const YAML::Node& profile, const std::string& file,
                         model::AerosolProfile& out, Diagnostics& diagnostics) {
    const YAML::Node node = profile["levels"];
    const ErrorContext where = at(file, node ? node : profile, "aerosol_profile.levels");
    const std::size_t columns = 1 + out.components.size();
    const std::string shape =
        "[altitude_km, then one density per component: " + std::to_string(out.components.size()) +
        "]";
    if (!node || !node.IsSequence() || node.size() < 2) {
        diagnostics.error(where, "expected at least two rows " + shape);
        return false;
    }
    if (node.size() > kMaxProfileLayers + 1) {
        diagnostics.error(where, "at most " + std::to_string(kMaxProfileLayers + 1) + " rows (" +
                                     std::to_string(kMaxProfileLayers) + " layers), got " +
                                     std::to_string(node.size()));
        return false;
    }
    struct Row {
        double altitude_km = 0.0;
        std::vector<double> densities;
        ErrorContext where;
    };
    std::vector<Row> rows;
    bool ok = true;
    for (const YAML::Node& item : node) {
        Row row;
        row.where = at(file, item, "aerosol_profile.levels");
        if (!item.IsSequence() || item.size() != columns) {
            diagnostics.error(row.where, "expected a row " + shape);
            ok = false;
            continue;
        }
        std::vector<double> values;
        bool numbers = true;
        for (const YAML::Node& v : item) {
            const std::optional<double> parsed = profile_number(v);
            values.push_back(parsed.value_or(-1.0));
            numbers = numbers && parsed.has_value();
        }
        if (!numbers) {
            diagnostics.error(row.where, "expected numbers in the row " + shape);
            ok = false;
            continue;
        }
        row.altitude_km = values.front();
        row.densities.assign(values.begin() + 1, values.end());
        if (row.altitude_km < 0.0 || row.altitude_km > kProfileTopKm) {
            diagnostics.error(row.where, "altitude " + format_shortest(row.altitude_km) +
                                             " km out of range, expected [0, 100] km above "
                                             "sea level");
            ok = false;
        }
        if (std::any_of(row.densities.begin(), row.densities.end(),
                        [](double d) { return d < 0.0; })) {
            diagnostics.error(row.where, "densities must be >= 0");
            ok = false;
        }
        rows.push_back(std::move(row));
    }
    if (!ok) return false;
    const bool descending = rows.front().altitude_km > rows.back().altitude_km;
    if (descending) std::reverse(rows.begin(), rows.end());
    for (std::size_t i = 1; i < rows.size(); ++i) {
        if (!(rows[i].altitude_km > rows[i - 1].altitude_km)) {
            diagnostics.error(rows[descending ? i - 1 : i].where,
                              "altitudes must increase (or decrease) strictly from row to row");
            return false;
        }
    }
    const Row& top = rows.back();
    if (std::any_of(top.densities.begin(), top.densities.end(),
                    [](double d) { return d != 0.0; })) {
        diagnostics.error(top.where,
                          "the highest row closes the profile (each row's densities fill the "
                          "layer up to the next row): its densities must be 0; add a row "
                          "above it to extend the aerosol");
        return false;
    }
    for (std::size_t i = 0; i + 1 < rows.size(); ++i) {
        out.altitudes_km.push_back(rows[i].altitude_km);
        out.densities.push_back(rows[i].densities);
    }
    out.altitudes_km.push_back(top.altitude_km);
    return true;
}

}  // namespace

void read_aerosol_profile(const YAML::Node& root, const std::string& file,
                          model::ParametricAtmosphere& p, Diagnostics& diagnostics) {
    const YAML::Node node = root["aerosol_profile"];
    if (!node) return;
    const std::size_t errors = diagnostics.error_count();
    read_profile_companions(root, file, p, diagnostics);
    const ErrorContext where = at(file, node, "aerosol_profile");
    if (!node.IsMap()) {
        diagnostics.error(where, "expected a mapping with components, unit and levels");
        return;
    }
    model::AerosolProfile out;
    out.where = where;
    for (const auto& entry : node) {
        const std::string key = entry.first.Scalar();
        if (key != "components" && key != "unit" && key != "mass_humidity_percent" &&
            key != "levels") {
            diagnostics.warning(at(file, entry.first, "aerosol_profile." + key),
                                "unknown key, ignored (aerosol_profile takes components, unit, "
                                "mass_humidity_percent, levels)");
        }
    }
    const YAML::Node unit = node["unit"];
    const std::string unit_name = unit && unit.IsScalar() ? unit.Scalar() : std::string{};
    if (unit_name == "g_per_m3") {
        out.mass_densities = true;
    } else if (unit_name != "per_cm3") {
        diagnostics.error(at(file, unit ? unit : node, "aerosol_profile.unit"),
                          "expected per_cm3 (particles per cm^3) or g_per_m3 (grams per m^3), "
                          "got '" +
                              unit_name + "'");
    }
    if (const YAML::Node rh = node["mass_humidity_percent"]) {
        const auto v = number_at(rh, file, "aerosol_profile.mass_humidity_percent", kZeroToHundred,
                                 diagnostics);
        if (v && unit_name == "per_cm3") {
            diagnostics.warning(at(file, rh, "aerosol_profile.mass_humidity_percent"),
                                "has no effect: the densities are particle numbers "
                                "(unit per_cm3), not masses");
        } else if (v) {
            out.mass_humidity_percent = *v;
        }
    }
    if (read_profile_components(node, file, out, diagnostics)) {
        read_profile_levels(node, file, out, diagnostics);
    }
    if (diagnostics.error_count() == errors) p.aerosol_profile = std::move(out);
}

}  // namespace glint::yaml::detail
