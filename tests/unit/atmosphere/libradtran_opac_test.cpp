// SPDX-License-Identifier: Apache-2.0
// A hazy sky against libRadtran: its example UVSPEC_AEROSOL_OPAC (B. Mayer, A. Kylling, "The
// libRadtran software package for radiative transfer calculations — description and examples
// of use", Atmospheric Chemistry and Physics 5, 2005, 1855–1877; C. Emde et al., "The
// libRadtran software package for radiative transfer calculations (version 2.0.1)",
// Geoscientific Model Development 9, 2016, 1647–1672), reproduced with a user's aerosol
// profile: OPAC's continental average as libRadtran's mass profile (inso, waso, soot, suso by
// layer, g/m³), U.S. Standard 1976, ground albedo 0.2, sun at 32°, 350 nm. What is compared, per
// unit extraterrestrial irradiance (libRadtran's own spectrum at 350.00 nm, 1199.04
// mW m⁻² nm⁻¹, divided out): the direct and diffuse irradiances at the ground and the sky's
// radiance at 3 zeniths × 3 azimuths. The reference numbers and their setup:
// tests/data/libradtran/uvspec_aerosol_opac.txt.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "glint/atmosphere/atmosphere.h"
#include "glint/test/aerosol_table.h"
#include "glint/test/gas_table.h"

namespace glint::atmosphere {
namespace libradtran_opac_test {

constexpr double kPi = std::numbers::pi;
constexpr double kSunZenithDeg = 32.0;
constexpr double kSunAzimuthPhi0Deg = 30.0;  // libRadtran's phi0
constexpr double kWavelengthUm = 0.35;
constexpr double kExtraterrestrial = 1199.04;  // atlas_plus_modtran at 350.00 nm, mW/(m² nm)

struct Radiance {
    double umu, phi, value;
};

struct Reference {
    std::vector<std::pair<double, std::vector<double>>> profile;  // altitude, densities
    std::map<std::string, double> irradiance;
    std::vector<Radiance> radiances;
};

Reference reference() {
    std::ifstream in(std::filesystem::path(GLINT_TEST_DATA_DIR) / "libradtran" /
                     "uvspec_aerosol_opac.txt");
    EXPECT_TRUE(in) << "tests/data/libradtran/uvspec_aerosol_opac.txt";
    Reference out;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line.front() == '#') continue;
        std::istringstream fields(line);
        std::string kind;
        fields >> kind;
        if (kind == "profile") {
            double z = 0.0;
            std::vector<double> d(4);
            fields >> z >> d[0] >> d[1] >> d[2] >> d[3];
            out.profile.emplace_back(z, d);
        } else if (kind == "irradiance") {
            std::string what;
            double v = 0.0;
            fields >> what >> v;
            out.irradiance[what] = v;
        } else if (kind == "radiance") {
            Radiance r{};
            fields >> r.umu >> r.phi >> r.value;
            out.radiances.push_back(r);
        }
    }
    return out;
}

/// libRadtran's atmosphere in glint: its mass profile (rows top first, each the layer above
/// it), the particles weighed at each layer's own humidity (libRadtran's OPAC tables give the
/// optics per gram of the grown particles), the layers' humidity from the U.S. Standard
/// profile, gases on.
model::ParametricAtmosphere setup(const Reference& ref) {
    model::ParametricAtmosphere p;
    p.profile = model::StandardAtmosphere::us_standard_1976;
    const model::StandardAtmosphereProfile& air = model::standard_atmosphere(p.profile);
    p.water_vapor_cm = air.water_column_cm;
    p.ozone_atm_cm = air.ozone_column_atm_cm;
    p.air_temperature_k = model::profile_temperature_k(air.levels, 0.0);
    p.ground_albedo = 0.2;
    model::AerosolProfile profile;
    profile.components = {"inso", "waso", "soot", "suso"};
    profile.mass_densities = true;
    for (auto row = ref.profile.rbegin(); row != ref.profile.rend(); ++row) {
        profile.altitudes_km.push_back(row->first);
        if (row + 1 != ref.profile.rend()) profile.densities.push_back(row->second);
    }
    p.aerosol_profile = profile;
    return p;
}

// The direct beam, the diffuse irradiance and the sky's radiance at the ground. Measured
// (printed with GLINT_LIBRADTRAN_PRINT set): the direct beam +0.59 % (glint's total optical
// depth 0.8337 against the 0.8386 libRadtran's beam implies: Hansen & Travis's Rayleigh
// against Bodhaine's, the gases), the diffuse irradiance +0.27 %, the nine radiances −0.36 to
// +0.91 % (the largest at 83.5° from the zenith, where glint's 8 streams and 24 layers meet
// the horizon). Tolerance 2 % (the 3 % a libRadtran case asks, less the room glint's other
// comparisons leave: libRadtran's own 8-stream radiances are good to about 1 %). The mass
// convention matters: the same masses weighed at 50 % move the beam to +1.2 % and the
// aureole to −1.1 %; read as dry masses they give 40 % more aerosol optical depth (the beam
// −8.6 %, the aureole +16 %), which this test would refuse.
TEST(LibradtranOpac, TheContinentalAverageSkyAt350Nanometres) {
    const Reference ref = reference();
    ASSERT_EQ(ref.profile.size(), 14u);
    ASSERT_EQ(ref.radiances.size(), 9u);
    const ParametricAtmosphereModel atmosphere(setup(ref), test::gas_table(),
                                               test::aerosol_table());
    const bool print = std::getenv("GLINT_LIBRADTRAN_PRINT") != nullptr;
    const SpectralGrid grid({kWavelengthUm});
    const std::vector<double> toa{kExtraterrestrial};
    AtmosphereGeometry ground;
    ground.sun_zenith_deg = kSunZenithDeg;
    const double mu0 = std::cos(kSunZenithDeg * kPi / 180.0);
    const double direct = atmosphere.sun_transmittance(grid, ground)[0] * mu0 * kExtraterrestrial;
    const double diffuse = atmosphere.diffuse_sky_irradiance_w_per_cm2_um(grid, ground, toa)[0];
    if (print) {
        std::printf("aerosol: %s\n", atmosphere.aerosol().description().c_str());
        std::printf(
            "Rayleigh depth %.4f, aerosol %.4f, total %.4f (libRadtran's direct beam: "
            "%.4f)\n",
            atmosphere.rayleigh_optical_depth(kWavelengthUm, 0.0),
            atmosphere.aerosol_optical_depth(kWavelengthUm, 0.0),
            -std::log(atmosphere.sun_transmittance(grid, ground)[0]) * mu0,
            -std::log(ref.irradiance.at("direct") / (kExtraterrestrial * mu0)) * mu0);
        std::printf("direct %.2f vs %.2f (%+.2f%%)\n", direct, ref.irradiance.at("direct"),
                    100.0 * (direct / ref.irradiance.at("direct") - 1.0));
        std::printf("diffuse %.2f vs %.2f (%+.2f%%)\n", diffuse, ref.irradiance.at("diffuse_down"),
                    100.0 * (diffuse / ref.irradiance.at("diffuse_down") - 1.0));
    }
    EXPECT_NEAR(direct / ref.irradiance.at("direct"), 1.0, 0.02);
    EXPECT_NEAR(diffuse / ref.irradiance.at("diffuse_down"), 1.0, 0.02);
    for (const Radiance& r : ref.radiances) {
        const double zenith = std::acos(-r.umu) * 180.0 / kPi;
        // glint's azimuth of the sky from the sun: libRadtran's phi − phi0 (0 looks towards
        // the sun), folded to [0, 180].
        const double from_sun = std::abs(std::remainder(r.phi - kSunAzimuthPhi0Deg, 360.0));
        const double ours = atmosphere.scattered_sky_radiance_w_per_cm2_sr_um(grid, ground, toa,
                                                                              zenith, from_sun)[0];
        if (print) {
            std::printf(
                "umu %.4f phi %3.0f (zenith %4.1f, %3.0f from the sun): %.2f vs %.2f "
                "(%+.2f%%)\n",
                r.umu, r.phi, zenith, from_sun, ours, r.value, 100.0 * (ours / r.value - 1.0));
        }
        EXPECT_NEAR(ours / r.value, 1.0, 0.02) << "umu " << r.umu << ", phi " << r.phi;
    }
}

}  // namespace libradtran_opac_test
}  // namespace glint::atmosphere
