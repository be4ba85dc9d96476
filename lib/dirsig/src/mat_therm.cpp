// SPDX-License-Identifier: Apache-2.0
// A `.mat` entry's THERM parameters (`TEMP_SOLVER_NAME = Therm`, docs/thermal.md): the
// TEMP_SOLVER block's SPECIFIC_HEAT, MASS_DENSITY, THERMAL_CONDUCTIVITY, THICKNESS,
// EXPOSED_AREA, SOLAR_ABSORPTION (older files: VISIBLE_EMISSIVITY) and THERMAL_EMISSIVITY,
// converted to SI. DIRSIG's manuals label the conductivity W/(m K) and the specific heat
// "Langley/C", but the values of real files fit cal/(cm h °C) and cal/(g °C) (water 5.13 and
// 1, steel 464.4 and 0.089): glint reads them so, and says so once per file.
#include <cmath>
#include <string>

#include "glint/core/text.h"
#include "mat_blocks.h"

namespace glint::dirsig::detail {
namespace {

/// cal/(g °C) → J/(kg K).
constexpr double kSpecificHeat = 4186.8;
/// g/cm³ → kg/m³.
constexpr double kDensity = 1000.0;
/// cal/(cm h °C) → W/(m K): 4.1868 J / (0.01 m · 3600 s · 1 K).
constexpr double kConductivity = 4.1868 / 36.0;
/// cm → m.
constexpr double kThickness = 0.01;

}  // namespace

void MatReader::read_therm(const MatBlock& solver, const std::string& path, model::Material& m) {
    warn_unknown(
        solver, path,
        {"SPECIFIC_HEAT", "MASS_DENSITY", "THERMAL_CONDUCTIVITY", "THICKNESS", "EXPOSED_AREA",
         "SOLAR_ABSORPTION", "VISIBLE_EMISSIVITY", "THERMAL_EMISSIVITY", "SPECULARITY"},
        {});
    model::ThermProperties t;
    t.where = at(solver.line, path);
    bool ok = true;
    // A number of `key` in [low, high] (high 0: unbounded); nullopt, with an error, when
    // present but bad; nullopt silently when absent.
    const auto number = [&](const char* key, double low, double high,
                            const char* range) -> std::optional<double> {
        const MatEntry* e = solver.find(key);
        if (!e) return std::nullopt;
        const auto v = parse_double(e->value);
        if (!v || !std::isfinite(*v) || *v < low || (high > low && *v > high)) {
            diagnostics.error(at(e->line, path + "/" + key),
                              std::string(key) + " \"" + e->value + "\" is not " + range);
            ok = false;
            return std::nullopt;
        }
        return v;
    };
    const auto required = [&](const char* key, double low, double high,
                              const char* range) -> double {
        if (!solver.find(key)) {
            diagnostics.error(t.where, "THERM material \"" + m.name + "\" needs " + key);
            ok = false;
            return 0.0;
        }
        return number(key, low, high, range).value_or(0.0);
    };
    t.specific_heat_j_per_kg_k =
        required("SPECIFIC_HEAT", 0.0, 0.0, "a number >= 0") * kSpecificHeat;
    t.density_kg_per_m3 = required("MASS_DENSITY", 0.0, 0.0, "a number >= 0") * kDensity;
    t.conductivity_w_per_m_k =
        required("THERMAL_CONDUCTIVITY", 0.0, 0.0, "a number >= 0") * kConductivity;
    const double exposed = required("EXPOSED_AREA", -1.0, 1.0, "a number in [-1, 1]");
    t.exposed_area = std::abs(exposed);
    if (exposed < 0.0 && !said_therm_exposed_sign) {
        said_therm_exposed_sign = true;
        diagnostics.warning(at(solver.find("EXPOSED_AREA")->line, path + "/EXPOSED_AREA"),
                            "a negative EXPOSED_AREA is read as its magnitude (DIRSIG does not "
                            "publish what the sign means; glint's reading, said once per file)");
    }
    t.thickness_m = number("THICKNESS", 0.0, 0.0, "a number >= 0").value_or(0.0) * kThickness;
    const MatEntry* solar = solver.find("SOLAR_ABSORPTION");
    const MatEntry* visible = solver.find("VISIBLE_EMISSIVITY");
    if (solar && visible) {
        diagnostics.warning(at(visible->line, path + "/VISIBLE_EMISSIVITY"),
                            "VISIBLE_EMISSIVITY (the older name of the solar absorptance) is not "
                            "used: SOLAR_ABSORPTION " +
                                solar->value + " is");
    }
    t.solar_absorptance =
        number(solar ? "SOLAR_ABSORPTION" : "VISIBLE_EMISSIVITY", 0.0, 1.0, "a number in [0, 1]");
    t.thermal_emissivity = number("THERMAL_EMISSIVITY", 0.0, 1.0, "a number in [0, 1]");
    if (const MatEntry* specularity = solver.find("SPECULARITY")) {
        ignore("SPECULARITY (the surface properties' lobes apply)",
               at(specularity->line, path + "/SPECULARITY"));
    }
    if (!ok) return;
    if (!said_therm_units) {
        said_therm_units = true;
        diagnostics.warning(t.where,
                            "THERM units read as DIRSIG's files use them: SPECIFIC_HEAT "
                            "cal/(g C), MASS_DENSITY g/cm^3, THERMAL_CONDUCTIVITY cal/(cm h C), "
                            "THICKNESS cm (glint's reading, said once per file)");
    }
    const bool stores = t.thickness_m > 0.0 && t.conductivity_w_per_m_k > 0.0 &&
                        t.specific_heat_j_per_kg_k > 0.0 && t.density_kg_per_m3 > 0.0;
    if (!stores && !said_therm_no_storage) {
        said_therm_no_storage = true;
        diagnostics.warning(t.where,
                            "THERM material \"" + m.name +
                                "\" has a zero THICKNESS, THERMAL_CONDUCTIVITY, SPECIFIC_HEAT or "
                                "MASS_DENSITY: its face stores no heat and is in balance with "
                                "its forcing at every instant (glint's reading, said once per "
                                "file)");
    }
    m.therm = t;
}

}  // namespace glint::dirsig::detail
