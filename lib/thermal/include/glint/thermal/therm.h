// SPDX-License-Identifier: Apache-2.0
// THERM as glint runs it: a facet's temperature history from a weather history, the facet's
// orientation and its sunlit share over time, through the slab of glint/thermal/slab.h. The
// forcing of one weather row on a facet of unit normal n (ENU, z up):
//   sun        α (E_direct max(0, n·s) · lit + E_diffuse (1 + n_z)/2)
//   longwave   ε_sky σ T_air⁴ (1 + n_z)/2 + σ T_air⁴ (1 − n_z)/2  (the sky, and surroundings at
//              the air's temperature below the horizon), ε_sky the Brutsaert clear-sky
//              emissivity of the dew point's vapour pressure, raised towards 1 as the sky
//              exposure falls: ε_clear + (1 − ε_clear)(1 − exposure)
//   convection h = 2.8 + 3.0 v W/(m² K) (wind speed v, m/s) times the exposed area
// The slab starts at the air's temperature spin_up_h before the first time asked and steps
// every step_s; its back is insulated (all its heat comes and goes through the exposed face:
// glint's reading, DIRSIG does not publish THERM's). A face that stores no
// heat (zero thickness, conductivity, heat capacity) is in balance at every instant. SI units;
// times in the weather's hours. docs/thermal.md ("Surface temperatures").
#pragma once

#include <array>
#include <functional>
#include <limits>
#include <span>
#include <vector>

#include "glint/model/scene.h"
#include "glint/model/weather.h"
#include "glint/thermal/slab.h"

namespace glint::thermal {

/// How THERM steps.
struct ThermSettings {
    double step_s = 300.0;    ///< time step of the slab
    double spin_up_h = 24.0;  ///< history before `start_h`
    /// The weather hour the spin-up ends at (its history starts spin_up_h before); NaN: the
    /// first time asked. The slab steps on the grid start + k · step_s whatever times are
    /// asked, so a time's temperature is the same whichever others are asked with it (a
    /// render's shards agree with the whole run).
    double start_h = std::numeric_limits<double>::quiet_NaN();
};

/// A facet: its unit normal (ENU) and broadband optical properties.
struct ThermFacet {
    std::array<double, 3> normal{0.0, 0.0, 1.0};
    double solar_absorptance = 0.7;
    double thermal_emissivity = 0.9;
};

/// The unit direction towards the sun (ENU) at a weather time, h.
using SunDirection = std::function<std::array<double, 3>(double time_h)>;
/// The facet's sunlit share, [0, 1], at a weather time, h (1: no shadow).
using SunlitShare = std::function<double(double time_h)>;

/// The Brutsaert (1975) clear-sky emissivity at air temperature `air_k` and dew point `dew_k`:
/// 1.24 (e / T)^{1/7}, e the vapour pressure (hPa) of the dew point (Magnus: 6.112
/// exp(17.62 t / (243.12 + t)), t in °C), at most 1.
double clear_sky_emissivity(double air_k, double dew_k) noexcept;

/// The convective heat-transfer coefficient at wind speed `wind_m_per_s`, W/(m² K):
/// 2.8 + 3.0 v (J. T. Watmuff, W. W. S. Charters, D. Proctor, "Solar and wind induced external
/// coefficients for solar collectors", COMPLES 2, 1977, 56).
double convection_coefficient(double wind_m_per_s) noexcept;

/// The forcing of `weather` on `facet` with the sun towards `sun` and `sunlit` of it lit.
SurfaceForcing therm_forcing(const model::WeatherRecord& weather, const ThermFacet& facet,
                             const std::array<double, 3>& sun, double sunlit) noexcept;

/// The slab THERM builds for `properties` (its back insulated).
SlabMaterial therm_slab(const model::ThermProperties& properties, const ThermFacet& facet);

/// Whether `properties` store heat (thickness, conductivity, specific heat and density > 0).
bool stores_heat(const model::ThermProperties& properties) noexcept;

/// One step of THERM's time stepping.
struct ThermStep {
    enum class Kind {
        advance,  ///< the slab steps dt_s to time_h (a grid step), the forcing at time_h
        partial,  ///< a copy of the slab steps dt_s to time_h: its face is an output
        current,  ///< the slab's face is an output (time_h is on the grid); no forcing
        instant,  ///< a face without storage: its balance under the forcing at time_h
    };
    double time_h = 0.0;
    double dt_s = 0.0;
    Kind kind = Kind::advance;
};

/// THERM's steps for a set of times: the same for every facet of a kind (storing heat or
/// not), so a caller can find the sunlit shares a facet needs before solving it, and solve
/// facets with the same material, normal and shares once.
struct ThermPlan {
    double start_h = 0.0;  ///< where the history starts (the slab at the air's temperature)
    std::vector<ThermStep> steps;
    /// The times the forcing is evaluated at, in order (every step but `current`).
    std::vector<double> forcing_times_h() const;
};

/// The plan for a facet that stores heat (`stores`) or not, at `times_h` (ascending weather
/// hours, none before settings.start_h): the slab stepped on its grid to the last grid time
/// at or before each, then a copy of it stepped the rest of the way. Throws glint::Error
/// (input) for times not ascending or before the start.
ThermPlan therm_plan(bool stores, std::span<const double> times_h,
                     const ThermSettings& settings = {});

/// The facet's surface temperature at each of the plan's outputs, K, `sunlit` its sunlit
/// share at each of plan.forcing_times_h(). Throws glint::Error (input) for an empty weather
/// history, (internal) for a plan of the other kind or too few shares.
std::vector<double> therm_temperatures_k(const model::ThermProperties& properties,
                                         const ThermFacet& facet, const model::Weather& weather,
                                         const SunDirection& sun, std::span<const double> sunlit,
                                         const ThermPlan& plan);

/// The facet's surface temperature at each of `times_h` (ascending weather hours, none
/// before settings.start_h), K: the slab stepped on its grid to the last grid time at or
/// before each, then a copy of it stepped the rest of the way. Throws glint::Error (input)
/// for an empty weather history, times not ascending or a time before the start.
std::vector<double> therm_temperatures_k(const model::ThermProperties& properties,
                                         const ThermFacet& facet, const model::Weather& weather,
                                         const SunDirection& sun, const SunlitShare& sunlit,
                                         std::span<const double> times_h,
                                         const ThermSettings& settings = {});

}  // namespace glint::thermal
