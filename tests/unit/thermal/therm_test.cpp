// SPDX-License-Identifier: Apache-2.0
// Tests of THERM's forcing and stepping (glint/thermal/therm.h): constant weather gives the
// closed-form steady balance; a day of weather warms a sunlit facet past the air and a
// shaded one less, a thick slab later than a thin one; a face without storage is in balance
// at every instant; the forcing's terms (Brutsaert sky, view factors, the sun's cosine and
// shadow, Watmuff's convection) are each what their formula says.
#include "glint/thermal/therm.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "glint/core/error.h"

namespace glint::thermal {
namespace therm_test {

/// 48 h every 0.25 h: air 290 ± 6 K peaking at 15:00, sun 06:00-18:00 (direct up to 850
/// W/m², diffuse up to 100), dew point 283.15 K, wind 2 m/s, clear.
model::Weather day(double amplitude_k = 6.0) {
    model::Weather w;
    w.step_h = 0.25;
    for (int i = 0; i <= 192; ++i) {
        const double t = 0.25 * i;
        const double hour = std::fmod(t, 24.0);
        model::WeatherRecord r;
        r.time_h = t;
        r.air_temperature_k =
            290.0 + amplitude_k * std::cos(2.0 * std::numbers::pi * (hour - 15.0) / 24.0);
        r.dew_point_k = 283.15;
        r.pressure_hpa = 1013.0;
        r.relative_humidity = 0.6;
        r.wind_speed_m_per_s = 2.0;
        const double elevation = std::sin(std::numbers::pi * (hour - 6.0) / 12.0);
        r.direct_insolation_w_per_m2 = elevation > 0.0 ? 850.0 * std::sqrt(elevation) : 0.0;
        r.diffuse_insolation_w_per_m2 = elevation > 0.0 ? 100.0 * elevation : 0.0;
        r.sky_exposure = 1.0;
        w.records.push_back(r);
    }
    return w;
}

/// The sun rising in the east at 06:00, due south (and up) at noon, setting at 18:00.
std::array<double, 3> sun_at(double t_h) {
    const double a = std::numbers::pi * (std::fmod(t_h, 24.0) - 6.0) / 12.0;
    const double elevation = std::sin(a);
    return {std::cos(a), -0.5 * std::sqrt(std::max(0.0, 1.0 - std::cos(a) * std::cos(a))),
            elevation};
}

model::ThermProperties concrete(double thickness_m) {
    model::ThermProperties p;
    p.specific_heat_j_per_kg_k = 880.0;
    p.density_kg_per_m3 = 2300.0;
    p.conductivity_w_per_m_k = 1.4;
    p.exposed_area = 1.0;
    p.thickness_m = thickness_m;
    return p;
}

ThermFacet flat() { return ThermFacet{{0.0, 0.0, 1.0}, 0.7, 0.9}; }

TEST(Therm, ForcingTermsFollowTheirFormulas) {
    // Brutsaert at 288.15 K with a 10 °C dew point: e = 12.27 hPa, ε = 0.790.
    EXPECT_NEAR(clear_sky_emissivity(288.15, 283.15), 0.790, 0.001);
    EXPECT_NEAR(convection_coefficient(4.0), 14.8, 1e-12);
    model::WeatherRecord w;
    w.air_temperature_k = 288.15;
    w.dew_point_k = 283.15;
    w.direct_insolation_w_per_m2 = 800.0;
    w.diffuse_insolation_w_per_m2 = 100.0;
    w.sky_exposure = 1.0;
    w.wind_speed_m_per_s = 4.0;
    const double black = kStefanBoltzmann * std::pow(288.15, 4);
    const double eps = clear_sky_emissivity(288.15, 283.15);
    const std::array<double, 3> sun{0.0, -0.6, 0.8};
    // Flat: the whole sky, the sun at cos 0.8.
    SurfaceForcing f = therm_forcing(w, flat(), sun, 1.0);
    EXPECT_NEAR(f.absorbed_sun_w_per_m2, 0.7 * (800.0 * 0.8 + 100.0), 1e-9);
    EXPECT_NEAR(f.longwave_down_w_per_m2, eps * black, 1e-9);
    EXPECT_EQ(f.convection_w_per_m2_k, 14.8);
    // A wall facing the sun's azimuth (south): half sky, half surroundings at T_air.
    const ThermFacet wall{{0.0, -1.0, 0.0}, 0.7, 0.9};
    f = therm_forcing(w, wall, sun, 1.0);
    EXPECT_NEAR(f.absorbed_sun_w_per_m2, 0.7 * (800.0 * 0.6 + 50.0), 1e-9);
    EXPECT_NEAR(f.longwave_down_w_per_m2, 0.5 * eps * black + 0.5 * black, 1e-9);
    // In shadow only the diffuse sun; facing away no direct sun; overcast, a black sky.
    EXPECT_NEAR(therm_forcing(w, flat(), sun, 0.0).absorbed_sun_w_per_m2, 70.0, 1e-9);
    const ThermFacet north{{0.0, 1.0, 0.0}, 0.7, 0.9};
    EXPECT_NEAR(therm_forcing(w, north, sun, 1.0).absorbed_sun_w_per_m2, 35.0, 1e-9);
    w.sky_exposure = 0.0;
    EXPECT_NEAR(therm_forcing(w, flat(), sun, 1.0).longwave_down_w_per_m2, black, 1e-9);
}

// Constant weather: after the spin-up the face is the closed-form balance of an insulated slab
// (no net flux through the face), to 10⁻⁶ K.
TEST(Therm, ConstantWeatherReachesTheSteadyBalance) {
    model::Weather w = day(0.0);
    for (auto& r : w.records) {
        r.direct_insolation_w_per_m2 = 0.0;
        r.diffuse_insolation_w_per_m2 = 300.0;
    }
    const auto p = concrete(0.1);
    const double times[] = {40.0};
    ThermSettings settings;
    settings.spin_up_h = 160.0;  // 40 time constants of 4 h (the weather held before it)
    const auto t = therm_temperatures_k(
        p, flat(), w, sun_at, [](double) { return 1.0; }, times, settings);
    const SurfaceForcing f = therm_forcing(w.records[0], flat(), sun_at(12.0), 1.0);
    EXPECT_NEAR(t[0], steady_surface_temperature_k(therm_slab(p, flat()), f), 1e-6);
}

// A day: the sunlit face rises well above the air by early afternoon and falls below it
// before dawn (a clear sky); a face shaded all day stays cooler; a 30 cm slab peaks later
// than a 1 cm one and swings less.
TEST(Therm, ADayOfWeatherWarmsTheSunlitFaceAndLagsTheThickSlab) {
    const model::Weather w = day();
    std::vector<double> times;
    for (int k = 0; k <= 96; ++k) times.push_back(24.0 + 0.25 * k);
    const auto lit = [](double) { return 1.0; };
    const auto shaded = [](double) { return 0.0; };
    const auto thin = therm_temperatures_k(concrete(0.01), flat(), w, sun_at, lit, times);
    const auto thick = therm_temperatures_k(concrete(0.30), flat(), w, sun_at, lit, times);
    const auto dark = therm_temperatures_k(concrete(0.01), flat(), w, sun_at, shaded, times);
    const auto at = [&](const std::vector<double>& v, double hour) {
        return v[static_cast<std::size_t>((hour) / 0.25)];
    };
    EXPECT_GT(at(thin, 13.0), 296.0 + 10.0);                 // air ≈ 295 K; the face far above it
    EXPECT_LT(at(thin, 5.0), w.at(29.0).air_temperature_k);  // radiating to a clear sky
    EXPECT_LT(at(dark, 13.0), at(thin, 13.0) - 10.0);
    const auto peak = [&](const std::vector<double>& v) {
        return 0.25 * static_cast<double>(std::max_element(v.begin(), v.end()) - v.begin());
    };
    EXPECT_GT(peak(thick), peak(thin));
    const auto swing = [](const std::vector<double>& v) {
        return *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
    };
    EXPECT_LT(swing(thick), 0.8 * swing(thin));
}

// The slab steps on a grid fixed by the start, so a time's temperature does not depend on
// which other times are asked with it (a render's shards must agree with the whole run); a
// time between grid points is a partial step from the grid, and a time before the start is
// refused.
TEST(Therm, ATimesTemperatureIsTheSameWhicheverTimesAreAskedWithIt) {
    const model::Weather w = day();
    const auto lit = [](double) { return 1.0; };
    ThermSettings settings;
    settings.start_h = 24.0;
    const double together[] = {24.0, 30.04, 37.0, 41.5};
    const double alone[] = {37.0};
    const double late[] = {30.04, 41.5};
    const auto all =
        therm_temperatures_k(concrete(0.05), flat(), w, sun_at, lit, together, settings);
    const auto one = therm_temperatures_k(concrete(0.05), flat(), w, sun_at, lit, alone, settings);
    const auto two = therm_temperatures_k(concrete(0.05), flat(), w, sun_at, lit, late, settings);
    EXPECT_EQ(all[2], one[0]);  // bit for bit
    EXPECT_EQ(all[1], two[0]);
    EXPECT_EQ(all[3], two[1]);
    // Without a start, the first time asked ends the spin-up: 37 h alone is then another
    // history (it starts at 13 h instead of 0 h), and differs.
    const auto own = therm_temperatures_k(concrete(0.05), flat(), w, sun_at, lit, alone);
    EXPECT_NE(own[0], one[0]);
    const double early[] = {23.0};
    EXPECT_THROW(therm_temperatures_k(concrete(0.05), flat(), w, sun_at, lit, early, settings),
                 Error);
}

// Without storage the face is the instantaneous balance of its forcing.
TEST(Therm, AFaceWithoutStorageIsInBalanceAtEveryInstant) {
    const model::Weather w = day();
    auto p = concrete(0.0);
    const double times[] = {30.0, 36.0, 40.0};
    const auto t = therm_temperatures_k(
        p, flat(), w, sun_at, [](double) { return 1.0; }, times);
    for (std::size_t i = 0; i < 3; ++i) {
        SlabMaterial m = therm_slab(concrete(0.1), flat());  // the face's flux needs no depth
        const SurfaceForcing f = therm_forcing(w.at(times[i]), flat(), sun_at(times[i]), 1.0);
        EXPECT_NEAR(Slab(m, 2, 300.0).face_flux_w_per_m2(f, t[i]), 0.0, 1e-5) << times[i];
    }
    EXPECT_THROW(therm_temperatures_k(
                     p, flat(), model::Weather{}, sun_at, [](double) { return 1.0; }, times),
                 Error);
}

}  // namespace therm_test
}  // namespace glint::thermal
