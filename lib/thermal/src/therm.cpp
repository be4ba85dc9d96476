// SPDX-License-Identifier: Apache-2.0
// THERM's forcing and its time stepping (glint/thermal/therm.h).
#include "glint/thermal/therm.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <optional>

#include "glint/core/error.h"

namespace glint::thermal {

namespace {

constexpr double kCelsius = 273.15;
constexpr double kDaySeconds = 86'400.0;
constexpr std::size_t kMinNodes = 3;
constexpr std::size_t kMaxNodes = 41;

}  // namespace

double clear_sky_emissivity(double air_k, double dew_k) noexcept {
    const double t = dew_k - kCelsius;
    const double vapour_hpa = 6.112 * std::exp(17.62 * t / (243.12 + t));
    return std::min(1.24 * std::pow(vapour_hpa / air_k, 1.0 / 7.0), 1.0);
}

double convection_coefficient(double wind_m_per_s) noexcept {
    return 2.8 + 3.0 * std::max(wind_m_per_s, 0.0);
}

SurfaceForcing therm_forcing(const model::WeatherRecord& w, const ThermFacet& facet,
                             const std::array<double, 3>& sun, double sunlit) noexcept {
    const auto& n = facet.normal;
    const double up = 0.5 * (1.0 + n[2]);  // the sky's view factor of the face
    const double cos_sun = std::max(0.0, n[0] * sun[0] + n[1] * sun[1] + n[2] * sun[2]);
    const double sun_up = sun[2] > 0.0 ? 1.0 : 0.0;
    SurfaceForcing f;
    f.absorbed_sun_w_per_m2 = facet.solar_absorptance * (w.direct_insolation_w_per_m2 * cos_sun *
                                                             sun_up * std::clamp(sunlit, 0.0, 1.0) +
                                                         w.diffuse_insolation_w_per_m2 * up);
    const double clear = clear_sky_emissivity(w.air_temperature_k, w.dew_point_k);
    const double sky = clear + (1.0 - clear) * (1.0 - std::clamp(w.sky_exposure, 0.0, 1.0));
    const double t2 = w.air_temperature_k * w.air_temperature_k;
    const double black = kStefanBoltzmann * t2 * t2;
    f.longwave_down_w_per_m2 = sky * black * up + black * (1.0 - up);
    f.air_temperature_k = w.air_temperature_k;
    f.convection_w_per_m2_k = convection_coefficient(w.wind_speed_m_per_s);
    return f;
}

bool stores_heat(const model::ThermProperties& p) noexcept {
    return p.thickness_m > 0.0 && p.conductivity_w_per_m_k > 0.0 &&
           p.specific_heat_j_per_kg_k > 0.0 && p.density_kg_per_m3 > 0.0;
}

SlabMaterial therm_slab(const model::ThermProperties& p, const ThermFacet& facet) {
    SlabMaterial m;
    m.thickness_m = p.thickness_m;
    m.density_kg_per_m3 = p.density_kg_per_m3;
    m.specific_heat_j_per_kg_k = p.specific_heat_j_per_kg_k;
    m.conductivity_w_per_m_k = p.conductivity_w_per_m_k;
    m.solar_absorptance = facet.solar_absorptance;
    m.thermal_emissivity = facet.thermal_emissivity;
    m.exposed_area = p.exposed_area;
    m.back_held = false;
    return m;
}

ThermPlan therm_plan(bool stores, std::span<const double> times_h, const ThermSettings& settings) {
    if (!std::is_sorted(times_h.begin(), times_h.end())) {
        throw input_error("THERM's times must be ascending");
    }
    ThermPlan plan;
    if (times_h.empty()) return plan;
    if (times_h.front() < settings.start_h - 1e-9) {  // false for a NaN start
        throw input_error("THERM's times must not precede its start");
    }
    if (!stores) {
        // No storage: the face's balance at each instant.
        for (double t : times_h) plan.steps.push_back({t, 0.0, ThermStep::Kind::instant});
        return plan;
    }
    plan.start_h =
        (std::isnan(settings.start_h) ? times_h.front() : settings.start_h) - settings.spin_up_h;
    const double step_h = settings.step_s / 3600.0;
    // Grid time k is start + k · step (a product, not a running sum: no drift over a day).
    std::size_t k = 0;
    const auto grid = [&](std::size_t i) { return plan.start_h + static_cast<double>(i) * step_h; };
    // A target within this of a grid time is on it (the hours carry rounding from seconds).
    constexpr double kOnGrid_h = 1e-9;
    for (double target : times_h) {
        while (grid(k + 1) <= target + kOnGrid_h) {
            plan.steps.push_back({grid(k + 1), settings.step_s, ThermStep::Kind::advance});
            ++k;
        }
        if (target - grid(k) <= kOnGrid_h) {
            plan.steps.push_back({target, 0.0, ThermStep::Kind::current});
        } else {
            plan.steps.push_back({target, (target - grid(k)) * 3600.0, ThermStep::Kind::partial});
        }
    }
    return plan;
}

std::vector<double> ThermPlan::forcing_times_h() const {
    std::vector<double> out;
    for (const ThermStep& step : steps) {
        if (step.kind != ThermStep::Kind::current) out.push_back(step.time_h);
    }
    return out;
}

std::vector<double> therm_temperatures_k(const model::ThermProperties& properties,
                                         const ThermFacet& facet, const model::Weather& weather,
                                         const SunDirection& sun, std::span<const double> sunlit,
                                         const ThermPlan& plan) {
    if (weather.empty()) throw input_error("THERM needs a weather history");
    std::vector<double> out;
    std::size_t next = 0;  // into sunlit: the forcing steps in order
    const auto forcing_at = [&](double t_h) {
        if (next >= sunlit.size()) {
            throw internal_error("THERM: fewer sunlit shares than the plan's forcing steps");
        }
        return therm_forcing(weather.at(t_h), facet, sun(t_h), sunlit[next++]);
    };
    SlabMaterial material = therm_slab(properties, facet);
    if (!stores_heat(properties)) {
        // The balance alone: an insulated face conducting nothing.
        material.thickness_m = 1.0;
        material.density_kg_per_m3 = 1.0;
        material.specific_heat_j_per_kg_k = 1.0;
        material.conductivity_w_per_m_k = 1.0;
        material.back_held = false;
    }
    std::optional<Slab> slab;
    if (stores_heat(properties)) {
        const double depth = Slab::penetration_depth_m(material, kDaySeconds);
        const auto nodes = std::clamp(
            static_cast<std::size_t>(std::ceil(material.thickness_m / (0.1 * depth))) + 1,
            kMinNodes, kMaxNodes);
        slab.emplace(material, nodes, weather.at(plan.start_h).air_temperature_k);
    }
    for (const ThermStep& step : plan.steps) {
        switch (step.kind) {
            case ThermStep::Kind::instant:
                out.push_back(steady_surface_temperature_k(material, forcing_at(step.time_h)));
                break;
            case ThermStep::Kind::advance:
            case ThermStep::Kind::partial:
            case ThermStep::Kind::current:
                if (!slab) throw internal_error("THERM: a slab's plan for a face without storage");
                if (step.kind == ThermStep::Kind::advance) {
                    // Backward Euler: the forcing at the step's end.
                    slab->step(forcing_at(step.time_h), step.dt_s);
                } else if (step.kind == ThermStep::Kind::partial) {
                    Slab rest = *slab;
                    rest.step(forcing_at(step.time_h), step.dt_s);
                    out.push_back(rest.surface_temperature_k());
                } else {
                    out.push_back(slab->surface_temperature_k());
                }
                break;
        }
    }
    return out;
}

std::vector<double> therm_temperatures_k(const model::ThermProperties& properties,
                                         const ThermFacet& facet, const model::Weather& weather,
                                         const SunDirection& sun, const SunlitShare& sunlit,
                                         std::span<const double> times_h,
                                         const ThermSettings& settings) {
    if (weather.empty()) throw input_error("THERM needs a weather history");
    const ThermPlan plan = therm_plan(stores_heat(properties), times_h, settings);
    std::vector<double> shares;
    for (double t : plan.forcing_times_h()) shares.push_back(sunlit(t));
    return therm_temperatures_k(properties, facet, weather, sun, shares, plan);
}

}  // namespace glint::thermal
