// SPDX-License-Identifier: Apache-2.0
// A white Lambertian plate tilted 37° towards the sun at air mass 1.5 over ground of albedo
// 0.2, rendered by the path tracer under the parametric atmosphere set to the conditions of
// ASTM G173-03 (gas absorption, multiple scattering), against the standard's global-tilt
// spectrum, which SMARTS 2.9.2 computed for that plate (C. A. Gueymard, "Parameterized
// transmittance model for direct beam and circumsolar spectral irradiance", Solar Energy
// 71, 2001, 325–346, is SMARTS's reference). π·L of a white plate is the irradiance on it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "glint/atmosphere/atmosphere.h"
#include "glint/atmosphere/gas_absorption.h"
#include "glint/atmosphere/solar.h"
#include "glint/core/spectral.h"
#include "glint/io/input_files.h"
#include "glint/radiometry/sampling.h"
#include "glint/test/gas_table.h"
#include "tracer_fixture.h"

namespace glint::radiometry {
namespace global_tilt_test {

using test::add_plate;
using test::batch_of;
using test::direction_from;
using test::FixedRay;
using test::ground_plane;
using test::Rig;

const std::filesystem::path kData = std::filesystem::path(GLINT_SOURCE_DIR) / "data";

/// ASTM G173-03: wavelength nm, the extraterrestrial and the global-tilt columns, W m-2 nm-1.
void read_astm(std::vector<double>& nm, std::vector<double>& exo, std::vector<double>& global) {
    std::ifstream in(kData / glint::atmosphere::SolarSpectrum::kAstmRelativePath);
    std::string line;
    std::getline(in, line);
    std::getline(in, line);
    while (std::getline(in, line)) {
        double v[4];
        if (std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2], &v[3]) == 4) {
            nm.push_back(v[0]);
            exo.push_back(v[1]);
            global.push_back(v[2]);
        }
    }
}

TEST(GlobalTilt, WhitePlateTiltedTowardsTheSunMatchesAstmG173) {
    const double sun_zenith = glint::atmosphere::zenith_for_relative_air_mass(1.5);  // 48.2°
    const double tilt_deg = 37.0;
    const Vec3 to_sun = direction_from(sun_zenith, 180.0);
    const Vec3 normal = direction_from(tilt_deg, 180.0);

    // The ASTM G173 conditions (1976 U.S. Standard Atmosphere: 1.42 cm water, 0.34 atm-cm
    // ozone; rural aerosol τ(500 nm) 0.084; ground albedo 0.2).
    model::ParametricAtmosphere p;
    p.water_vapor_cm = 1.42;
    p.ozone_atm_cm = 0.34;
    p.angstrom_exponent = 1.3;
    p.aerosol_optical_depth_550 = 0.084 * std::pow(0.55 / 0.5, -1.3);
    p.ground_albedo = 0.2;
    const glint::atmosphere::ParametricAtmosphereModel atmosphere(p, glint::test::gas_table());
    const auto sun = glint::atmosphere::SolarSpectrum::from_astm_g173(
        io::read_input_file(kData / glint::atmosphere::SolarSpectrum::kAstmRelativePath),
        glint::atmosphere::SolarSpectrum::kAstmRelativePath);
    const SpectralGrid grid = SpectralGrid::regular(0.300, 2.500, 0.005);
    EnvironmentInputs inputs;
    inputs.sun_direction_begin = inputs.sun_direction_end = to_sun;
    inputs.sun_distance_au = 1.0;
    inputs.surface_altitude_m = 0.0;
    inputs.sensor_altitude_m = 3.0;  // beside the plate: no path between them to speak of
    inputs.threads = 1;
    Environment env = Environment::make(grid, atmosphere, sun, inputs);

    model::Scene scene;
    scene.materials.push_back(model::flat_material("ground", 0.2, 300.0));
    scene.materials.push_back(model::flat_material("white plate", 1.0, 300.0));
    test::add_primitive(scene, ground_plane(), 0);
    add_plate(scene, normal, 1);
    TracerSettings settings;
    Rig rig(std::move(scene), grid, std::move(env), settings);
    const Vec3 eye = Vec3{0.0, 0.0, 1.5} + normal * 0.5;
    const FixedRay source({eye, normal * -1.0, 0.0, 1.0});
    const Solution s = solve(rig.tracer, batch_of(source, 20'000), 0);

    // π·L against ASTM's global tilt, both in W m-2 nm-1 (1 W/(cm² µm) = 10 W m-2 nm-1),
    // ASTM's nodes averaged over each 5 nm band's cell.
    std::vector<double> nm, exo, astm;
    read_astm(nm, exo, astm);
    std::vector<double> theirs(grid.size(), 0.0);
    std::vector<double> top(grid.size(), 0.0);  // extraterrestrial on the plate
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const double centre = grid.wavelength_um(i) * 1000.0;
        double sum = 0.0;
        int n = 0;
        for (std::size_t k = 0; k < nm.size(); ++k) {
            if (nm[k] >= centre - 2.5 && nm[k] < centre + 2.5) {
                sum += astm[k];
                top[i] += exo[k];
                ++n;
            }
        }
        theirs[i] = n > 0 ? sum / n : 0.0;
        top[i] = n > 0 ? top[i] / n * dot(to_sun, normal) : 0.0;
    }
    std::vector<double> ours(grid.size());
    for (std::size_t i = 0; i < grid.size(); ++i)
        ours[i] = kPi * s.radiance_w_per_cm2_sr_um[i] * 10.0;
    // For the documentation's plot (scripts/atmosphere_plots.py): the two spectra.
    if (const char* plots = std::getenv("GLINT_ATMOSPHERE_PLOT_DIR")) {
        std::ofstream csv(std::filesystem::path(plots) / "global_tilt.csv");
        csv << "wavelength_nm,glint_pi_l,astm_global_tilt\n";
        for (std::size_t i = 0; i < grid.size(); ++i) {
            csv << grid.wavelength_um(i) * 1000.0 << ',' << ours[i] << ',' << theirs[i] << '\n';
        }
    }
    // Band-integrated 300-2500 nm: within 5 %.
    double total_ours = 0.0;
    double total_theirs = 0.0;
    for (std::size_t i = 0; i < grid.size(); ++i) {
        total_ours += ours[i] * 5.0;
        total_theirs += theirs[i] * 5.0;
    }
    std::printf("global tilt 300-2500 nm: glint %.1f, ASTM %.1f W/m2\n", total_ours, total_theirs);
    EXPECT_NEAR(total_ours / total_theirs, 1.0, 0.05);
    // Every 50 nm band 400-2200 nm: within 10 %, or, where LOWTRAN 7's and SMARTS's water
    // bands part (1.3-1.5 and 1.85-1.95 um: the direct comparison's bins there differ by up
    // to 0.10 of the extraterrestrial irradiance E0, gas_absorption_test.cpp), within 0.10 of
    // the band's E0 on the plate. Measured with the directional sky: 31 of 36 bands within
    // 10 % (400-1250 nm within -8 to +10 %, 400-500 nm +8 to +10 %); the other five at 1300
    // (-7 % of E0), 1350 (0), 1450 (-5), 1850 (0) and 1900 (0); the whole range +2.9 %. With
    // directional_sky false the whole range is -1.2 % and 400-500 nm +1 to +3 %: the
    // directional sky gives this plate, facing the sun, about a fifth more sky light than the
    // isotropic one (docs/physics.md, "The sky in the renderer"); SMARTS's tilted diffuse
    // comes from its own transposition of the horizontal one. A difference reported, not
    // fitted.
    std::string bands;
    int relative_bands = 0;
    for (double start = 400.0; start < 2200.0; start += 50.0) {
        double a = 0.0;
        double b = 0.0;
        double e0 = 0.0;
        for (std::size_t i = 0; i < grid.size(); ++i) {
            const double centre = grid.wavelength_um(i) * 1000.0;
            if (centre >= start && centre < start + 50.0) {
                a += ours[i];
                b += theirs[i];
                e0 += top[i];
            }
        }
        const bool relative = std::abs(a / b - 1.0) <= 0.10;
        relative_bands += relative ? 1 : 0;
        bands +=
            " " + std::to_string(static_cast<int>(start)) + ":" +
            std::to_string(static_cast<int>(std::lround(100.0 * (a / b - 1.0)))) +
            (relative ? "" : "(" + std::to_string(std::lround(100.0 * (a - b) / e0)) + "% of E0)");
        EXPECT_TRUE(relative || std::abs(a - b) <= 0.10 * e0) << start << " nm";
    }
    EXPECT_GE(relative_bands, 30);
    std::printf("50 nm bands, glint/ASTM - 1 in %%:%s\n", bands.c_str());
}

}  // namespace global_tilt_test
}  // namespace glint::radiometry
