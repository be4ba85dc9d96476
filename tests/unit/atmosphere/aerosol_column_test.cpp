// SPDX-License-Identifier: Apache-2.0
// Tests of the parametric atmosphere's aerosol (glint/atmosphere/aerosol_column.h): the
// exponential aerosol is the closed form it always was; the layered aerosol's optical depths
// are the integrals of LOWTRAN 7's profiles (checked by a separate fine quadrature), its
// regimes own their altitudes, a column depth rescales it, and its spectra and phase functions
// are its mixture's from the optics table; and the single-scatter path radiance of a thin
// layered aerosol is the closed form with the table's phase function.
#include "glint/atmosphere/aerosol_column.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "glint/atmosphere/atmosphere.h"
#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/model/aerosol_models.h"
#include "glint/test/aerosol_table.h"

namespace glint::atmosphere {
namespace aerosol_column_test {

constexpr double kPi = std::numbers::pi;

model::ParametricAtmosphere layered(const std::string& type) {
    model::ParametricAtmosphere p;
    p.aerosol_model = type;
    p.gas_absorption = false;
    return p;
}

TEST(AerosolColumn, TheExponentialAerosolIsItsClosedForm) {
    model::ParametricAtmosphere p;
    p.aerosol_optical_depth_550 = 0.3;
    p.angstrom_exponent = 1.1;
    p.aerosol_scale_height_m = 1500.0;
    p.aerosol_asymmetry = 0.65;
    p.aerosol_single_scatter_albedo = 0.9;
    const AerosolColumn c(p, nullptr);
    ASSERT_EQ(c.regimes(), 1u);
    for (double wl : {0.4, 0.55, 2.0}) {
        for (double z : {0.0, 800.0, 5000.0}) {
            const double expected = 0.3 * std::pow(wl / 0.55, -1.1) * std::exp(-z / 1500.0);
            EXPECT_NEAR(c.optical_depth(wl, z), expected, 1e-14 * expected);
        }
    }
    const RegimeOptics o = c.optics(0, 0.7, 4);
    EXPECT_DOUBLE_EQ(o.single_scatter_albedo, 0.9);
    EXPECT_NEAR(o.moments[3], 0.65 * 0.65 * 0.65, 1e-15);
    const double mu[] = {1.0, 0.0, -1.0};
    const std::vector<double> phase = c.phases(0, 0.7, mu);
    const double g = 0.65;
    EXPECT_NEAR(phase[0], (1 - g * g) / std::pow(1 - g, 3), 1e-12);
    EXPECT_NEAR(phase[2], (1 - g * g) / std::pow(1 + g, 3), 1e-12);
}

/// ∫ from z to 100 km of LOWTRAN's profile of the regime owning [bottom, top] km, by the
/// midpoint rule on 1 m steps of the exponential through neighbouring levels.
double lowtran_depth(double visibility_km, double bottom_km, double top_km, double from_km) {
    const auto levels = model::aerosol_profile_levels_km();
    auto total = [&](std::size_t k) {
        const model::RegimeExtinction e = model::lowtran_aerosol_extinction(
            k, visibility_km, model::AerosolSeason::spring_summer);
        return e.boundary_layer + e.troposphere + e.stratosphere;
    };
    double sum = 0.0;
    for (std::size_t k = 0; k + 1 < levels.size(); ++k) {
        const double a = std::max({levels[k], bottom_km, from_km});
        const double b = std::min(levels[k + 1], top_km);
        if (b <= a) continue;
        const double ba = total(k), bb = total(k + 1);
        const int steps = static_cast<int>(std::ceil((b - a) * 1000.0));
        const double h = (b - a) / steps;
        for (int i = 0; i < steps; ++i) {
            const double z = a + (i + 0.5) * h;
            const double t = (z - levels[k]) / (levels[k + 1] - levels[k]);
            sum += (ba > 0 && bb > 0 ? ba * std::pow(bb / ba, t) : ba + t * (bb - ba)) * h;
        }
    }
    return sum;
}

// The layered aerosol's 550 nm depths are LOWTRAN's profile integrated, regime by regime
// (1e-6: the midpoint rule on 1 m steps); at 23 km visibility the column holds 0.205 in the
// boundary layer, 0.110 in the free troposphere, 0.008 in the stratosphere.
TEST(AerosolColumn, TheLayeredDepthsAreLowtransProfilesIntegrated) {
    model::ParametricAtmosphere p = layered("rural");
    p.aerosol_season = model::AerosolSeason::spring_summer;
    for (double v : {5.0, 23.0, 50.0}) {
        p.visibility_km = v;
        const AerosolColumn c(p, test::aerosol_table());
        ASSERT_EQ(c.regimes(), 3u);
        const double bounds[][2] = {{0.0, 2.0}, {2.0, 10.0}, {10.0, 100.0}};
        for (std::size_t j = 0; j < 3; ++j) {
            for (double from_km : {0.0, 0.5, 1.5, 2.5, 7.0, 12.0, 40.0}) {
                const double expected = lowtran_depth(v, bounds[j][0], bounds[j][1], from_km);
                EXPECT_NEAR(c.depth_550_above(j, from_km * 1000.0), expected,
                            1e-6 * std::max(expected, 1e-3))
                    << v << " km visibility, regime " << j << ", from " << from_km << " km";
            }
        }
        // At 550 nm the optical depth is the 550 nm depth.
        EXPECT_NEAR(c.optical_depth(0.55, 0.0), c.depth_550_above(0.0), 1e-12);
    }
    p.visibility_km = 23.0;
    const AerosolColumn c(p, test::aerosol_table());
    EXPECT_NEAR(c.depth_550_above(0, 0.0), 0.205, 0.001);
    EXPECT_NEAR(c.depth_550_above(1, 0.0), 0.110, 0.001);
    EXPECT_NEAR(c.depth_550_above(2, 0.0), 0.0079, 0.0001);
}

TEST(AerosolColumn, AColumnDepthRescalesEveryRegime) {
    model::ParametricAtmosphere p = layered("urban");
    const AerosolColumn unscaled(p, test::aerosol_table());
    p.aerosol_column_depth_550 = 0.5;
    const AerosolColumn scaled(p, test::aerosol_table());
    EXPECT_NEAR(scaled.depth_550_above(0.0), 0.5, 1e-12);
    const double f = 0.5 / unscaled.depth_550_above(0.0);
    for (double z : {0.0, 1500.0, 6000.0, 20000.0}) {
        EXPECT_NEAR(scaled.depth_550_above(z), f * unscaled.depth_550_above(z), 1e-12);
    }
    p.tropospheric_aerosol = "none";
    p.stratospheric_aerosol = "none";
    const AerosolColumn boundary_only(p, test::aerosol_table());
    EXPECT_EQ(boundary_only.regimes(), 1u);
    EXPECT_EQ(boundary_only.depth_550_above(2000.0), 0.0);
}

// The boundary layer's spectrum and phase function are its mixture's (OPAC's components in
// their standard proportions, at the humidity asked for).
TEST(AerosolColumn, TheOpticsAreTheMixtures) {
    model::ParametricAtmosphere p = layered("maritime_clean");
    p.relative_humidity_percent = 80.0;
    const AerosolColumn c(p, test::aerosol_table());
    const AerosolTable& t = *test::aerosol_table();
    const std::vector<MixtureShare> shares{{"waso", 1500.0}, {"ssam", 20.0}, {"sscm", 3.2e-3}};
    const ComponentOptics at_550 = t.mixture(shares, 0.55, 80.0);
    for (double wl : {0.35, 0.55, 0.865, 1.6}) {
        const ComponentOptics m = t.mixture(shares, wl, 80.0);
        const RegimeOptics o = c.optics(0, wl, 17);
        // The column samples the mixture at the table's wavelengths and interpolates: exact at
        // them (0.35, 0.55), within 0.5 % between (0.865, 1.6).
        EXPECT_NEAR(o.extinction_ratio, m.extinction_um2 / at_550.extinction_um2,
                    5e-3 * o.extinction_ratio)
            << wl;
        EXPECT_NEAR(o.single_scatter_albedo, m.single_scatter_albedo(), 2e-3) << wl;
        EXPECT_NEAR(o.moments[1], m.moments[1], 2e-3) << wl;
    }
    // Sea salt scatters forward: the phase function falls by orders of magnitude from 0° to
    // 90°, and backscatter rises again towards 180°.
    const double mu[] = {1.0, 0.0, std::cos(150.0 * kPi / 180.0), -1.0};
    const std::vector<double> phase = c.phases(0, 0.55, mu);
    EXPECT_GT(phase[0] / phase[1], 100.0);
    EXPECT_GT(phase[3], phase[2]);
}

TEST(AerosolColumn, BadTypesAndAMissingTableAreInputErrors) {
    auto message = [](const model::ParametricAtmosphere& p,
                      std::shared_ptr<const AerosolTable> table) {
        try {
            const AerosolColumn c(p, std::move(table));
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message(layered("rural"), nullptr),
              "aerosol_model needs the aerosol optics table (atmosphere/aerosol_optics.csv in "
              "glint's data folder)");
    model::ParametricAtmosphere p = layered("rural");
    p.tropospheric_aerosol = "smoke";
    EXPECT_NE(message(p, test::aerosol_table())
                  .find("tropospheric_aerosol: unknown aerosol type 'smoke' (expected one of "),
              std::string::npos);
    p = layered("rural");
    p.visibility_km = 0.0;
    EXPECT_EQ(message(p, test::aerosol_table()), "visibility_km must be > 0, got 0");
}

// A thin aerosol seen from above the atmosphere, without Rayleigh or gases: the path radiance
// is E₀ ω τ P(Θ) / (4π μ_v) (1 − τ (m_s + m_v)/2) to second order in τ, P the mixtures'
// tabulated phase functions (0.5 %: the third order of τ = 0.02 along both slant paths is
// 3e-4, the regimes' different albedos weigh the attenuation slightly differently).
/// A user's profile of `densities` (one component each) in layers between `altitudes_km`.
model::ParametricAtmosphere profiled(std::vector<std::string> components, bool mass,
                                     std::vector<double> altitudes_km,
                                     std::vector<std::vector<double>> densities) {
    model::ParametricAtmosphere p;
    p.gas_absorption = false;
    model::AerosolProfile profile;
    profile.components = std::move(components);
    profile.mass_densities = mass;
    profile.altitudes_km = std::move(altitudes_km);
    profile.densities = std::move(densities);
    profile.where = ErrorContext{"p.yaml", 4, "aerosol_profile"};
    p.aerosol_profile = profile;
    return p;
}

// A user's profile: one regime per layer with particles, its depth the number density times
// the mixture's cross section over its thickness; masses are numbers times one particle's mass
// (grown at the layer's humidity, or at the one the masses were weighed at); the humidity is
// the profile's at the layer's middle unless given; a column depth rescales it; the layers
// keep their altitudes.
TEST(AerosolColumn, AProfilesLayersAreItsDensitiesTimesTheTablesCrossSections) {
    const auto table = test::aerosol_table();
    // 7000 water-soluble particles per cm³ from 0 to 2 km, nothing from 2 to 5 km, 1000 from 5
    // to 6 km, every layer at 70 %.
    model::ParametricAtmosphere numbers =
        profiled({"waso"}, false, {0.0, 2.0, 5.0, 6.0}, {{7000.0}, {0.0}, {1000.0}});
    numbers.relative_humidity_percent = 70.0;
    const AerosolColumn column(numbers, table);
    EXPECT_EQ(column.regimes(), 2u);
    const double sigma = table->optics("waso", 0.55, 70.0).extinction_um2;  // µm²
    // n [1/cm³] σ [µm²] = 1e-6 per m.
    EXPECT_NEAR(column.depth_550_above(0.0), (7000.0 * 2000.0 + 1000.0 * 1000.0) * sigma * 1e-6,
                1e-12);
    EXPECT_NEAR(column.depth_550_above(3000.0), 1000.0 * 1000.0 * sigma * 1e-6, 1e-12);
    EXPECT_NEAR(column.depth_550_above(1000.0), 8000.0 * 1000.0 * sigma * 1e-6, 1e-12);
    EXPECT_DOUBLE_EQ(column.depth_550_above(6000.0), 0.0);
    EXPECT_NEAR(column.extinction_ratio(0, 0.35),
                table->optics("waso", 0.35, 70.0).extinction_um2 / sigma, 1e-9);
    EXPECT_EQ(column.description(),
              "profile: 3 layers of waso (1/cm^3), humidity 70 %, tau550 " +
                  format_shortest(std::round(column.depth_550_above(0.0) * 1e4) / 1e4));

    // The same particles as masses weighed at 70 %: the same column.
    const double grams = table->optics("waso", 0.55, 70.0).particle_mass_g * 1e6;  // per m³
    model::ParametricAtmosphere masses =
        profiled({"waso"}, true, {0.0, 2.0, 5.0, 6.0}, {{7000.0 * grams}, {0.0}, {1000.0 * grams}});
    masses.relative_humidity_percent = 70.0;
    EXPECT_NEAR(AerosolColumn(masses, table).depth_550_above(0.0) / column.depth_550_above(0.0),
                1.0, 1e-9);
    // Weighed dry instead, then grown to 70 %: each gram holds more particles.
    masses.aerosol_profile->mass_humidity_percent = 0.0;
    const double dry = table->optics("waso", 0.55, 0.0).particle_mass_g * 1e6;
    EXPECT_NEAR(AerosolColumn(masses, table).depth_550_above(0.0) / column.depth_550_above(0.0),
                grams / dry, 1e-9);

    // Without a humidity: the U.S. Standard profile's at each layer's middle (46 % at the
    // ground, drier aloft), so the 0-2 km layer's cross section lies between the dry and the
    // 50 % one.
    const AerosolColumn own(profiled({"waso"}, false, {0.0, 2.0, 10.0}, {{7000.0}, {0.0}}), table);
    const double own_sigma = own.depth_550_above(0.0) / (7000.0 * 2000.0 * 1e-6);
    EXPECT_GT(own_sigma, table->optics("waso", 0.55, 0.0).extinction_um2);
    EXPECT_LT(own_sigma, table->optics("waso", 0.55, 50.0).extinction_um2);

    // A column depth rescales every layer.
    numbers.aerosol_column_depth_550 = 0.25;
    const AerosolColumn scaled(numbers, table);
    EXPECT_NEAR(scaled.depth_550_above(0.0), 0.25, 1e-12);
    EXPECT_NEAR(scaled.depth_550_above(3000.0) / scaled.depth_550_above(0.0),
                column.depth_550_above(3000.0) / column.depth_550_above(0.0), 1e-12);
}

// A mixed layer: its optics are the table's mixture of its components at its humidity.
TEST(AerosolColumn, AProfilesMixedLayerHasTheMixturesOptics) {
    const auto table = test::aerosol_table();
    model::ParametricAtmosphere p =
        profiled({"inso", "waso", "soot"}, false, {0.0, 1.0}, {{0.4, 7000.0, 8300.0}});
    p.relative_humidity_percent = 80.0;
    const AerosolColumn column(p, table);
    ASSERT_EQ(column.regimes(), 1u);
    const std::vector<MixtureShare> shares{{"inso", 0.4}, {"waso", 7000.0}, {"soot", 8300.0}};
    const ComponentOptics mixed = table->mixture(shares, 0.45, 80.0);
    const RegimeOptics o = column.optics(0, 0.45, 8);
    EXPECT_NEAR(o.single_scatter_albedo, mixed.single_scatter_albedo(), 1e-9);
    for (std::size_t l = 0; l < 8; ++l) EXPECT_NEAR(o.moments[l], mixed.moments[l], 1e-9) << l;
}

// A profile without particles is clean air: no regime, and the model runs without aerosol.
TEST(AerosolColumn, AProfileWithoutParticlesIsCleanAir) {
    const auto table = test::aerosol_table();
    const model::ParametricAtmosphere p =
        profiled({"waso"}, false, {0.0, 1.0, 3.0}, {{0.0}, {0.0}});
    const AerosolColumn column(p, table);
    EXPECT_EQ(column.regimes(), 0u);
    EXPECT_DOUBLE_EQ(column.optical_depth(0.55, 0.0), 0.0);
    EXPECT_EQ(column.description(), "profile: 2 layers of waso (1/cm^3), humidity -, tau550 0");
    model::ParametricAtmosphere clear = p;
    clear.aerosol_profile.reset();
    clear.aerosol_optical_depth_550 = 0.0;
    const ParametricAtmosphereModel with_profile(p, nullptr, table);
    const ParametricAtmosphereModel without(clear, nullptr, table);
    AtmosphereGeometry g;
    g.sun_zenith_deg = 30.0;
    g.sensor_altitude_m = 5000.0;
    const SpectralGrid grid({0.55});
    const std::vector<double> toa{1.0};
    EXPECT_NEAR(with_profile.path_radiance_w_per_cm2_sr_um(grid, g, toa)[0],
                without.path_radiance_w_per_cm2_sr_um(grid, g, toa)[0], 1e-12);
}

TEST(AerosolColumn, AProfileNeedsTheTableAndItsComponents) {
    const model::ParametricAtmosphere p = profiled({"waso"}, false, {0.0, 1.0}, {{100.0}});
    try {
        (void)AerosolColumn(p, nullptr);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "aerosol_profile needs the aerosol optics table (atmosphere/aerosol_optics.csv "
                  "in glint's data folder)");
    }
    const auto tiny = std::make_shared<const AerosolTable>(AerosolTable::from_csv(
        "component,rh_percent,wavelength_um,extinction_um2,scattering_um2,asymmetry,"
        "particle_mass_g,chi_1,p_0,p_180\n"
        "inso,0,0.5,2,1,0.5,1e-11,0.5,4,1\n",
        "tiny.csv"));
    try {
        (void)AerosolColumn(p, tiny);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_EQ(std::string(e.what()),
                  "p.yaml:4: aerosol_profile: the aerosol optics table has no component 'waso'");
    }
}

TEST(AerosolColumn, ThinAerosolPathRadianceIsTheTablesPhaseFunction) {
    model::ParametricAtmosphere p = layered("continental_average");
    p.sea_level_pressure_hpa = 0.0;
    p.multiple_scattering = false;
    p.aerosol_column_depth_550 = 0.02;
    const ParametricAtmosphereModel atmosphere(p, nullptr, test::aerosol_table());
    const SpectralGrid grid({0.55});
    const std::vector<double> toa{1.0};
    AtmosphereGeometry g;
    g.sun_zenith_deg = 30.0;
    g.sun_azimuth_deg = 0.0;
    g.sensor_altitude_m = 200'000.0;
    g.view_zenith_deg = 20.0;
    for (double azimuth : {0.0, 90.0, 180.0}) {
        g.view_azimuth_deg = azimuth;
        const double cos_scatter = -(std::sin(30.0 * kPi / 180.0) * std::sin(20.0 * kPi / 180.0) *
                                         std::cos(azimuth * kPi / 180.0) +
                                     std::cos(30.0 * kPi / 180.0) * std::cos(20.0 * kPi / 180.0));
        const double mu[] = {cos_scatter};
        double omega_tau_p = 0.0;
        for (std::size_t j = 0; j < atmosphere.aerosol().regimes(); ++j) {
            const RegimeOptics o = atmosphere.aerosol().optics(j, 0.55, 1);
            omega_tau_p += o.single_scatter_albedo * atmosphere.aerosol().depth_550_above(j, 0.0) *
                           atmosphere.aerosol().phases(j, 0.55, mu)[0];
        }
        const double slant = relative_air_mass(30.0) + relative_air_mass(20.0);
        const double expected = omega_tau_p / (4.0 * kPi * std::cos(20.0 * kPi / 180.0)) *
                                relative_air_mass(20.0) * std::cos(20.0 * kPi / 180.0) *
                                (1.0 - 0.5 * 0.02 * slant);
        const double path = atmosphere.path_radiance_w_per_cm2_sr_um(grid, g, toa)[0];
        EXPECT_NEAR(path / expected, 1.0, 0.005) << azimuth;
    }
}

}  // namespace aerosol_column_test
}  // namespace glint::atmosphere
