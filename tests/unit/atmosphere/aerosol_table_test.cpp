// SPDX-License-Identifier: Apache-2.0
// Tests of the aerosol optics table (glint/atmosphere/aerosol_table.h): parsing and its errors
// at file:line, interpolation in wavelength and humidity, mixtures; and of the shipped
// data/atmosphere/aerosol_optics.csv: every component read, its phase functions normalised,
// its moments those of its phase function.
#include "glint/atmosphere/aerosol_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "glint/core/error.h"
#include "glint/test/aerosol_table.h"

namespace glint::atmosphere {
namespace aerosol_table_test {

// Two components: "aa" at 0 and 50 % humidity, "bb" without growth; 2 moments, 3 angles.
const std::string kTable =
    "# a comment\n"
    "component,rh_percent,wavelength_um,extinction_um2,scattering_um2,asymmetry,particle_mass_g,"
    "chi_1,chi_2,p_0,p_90,p_180\n"
    "aa,0,0.5,2,1,0.5,1e-15,0.5,0.3,4,1,0.5\n"
    "aa,0,1.0,1,0.5,0.4,1e-15,0.4,0.2,2,1,1\n"
    "aa,50,0.5,4,4,0.6,3e-15,0.6,0.4,8,1,0.5\n"
    "aa,50,1.0,2,2,0.5,3e-15,0.5,0.3,4,1,1\n"
    "bb,0,0.5,1,0.25,0,5e-15,0,0,1,1,1\n"
    "bb,0,1.0,1,0.25,0,5e-15,0,0,1,1,1\n";

TEST(AerosolTable, InterpolatesInLnWavelengthAndInHumidity) {
    const AerosolTable t = AerosolTable::from_csv(kTable, "t.csv");
    EXPECT_EQ(t.moment_count(), 3u);
    EXPECT_EQ(t.angles_deg(), (std::vector<double>{0, 90, 180}));
    EXPECT_TRUE(t.has("aa"));
    EXPECT_FALSE(t.has("cc"));
    // Halfway in ln λ: the cross sections' geometric mean, the rest the arithmetic one.
    const ComponentOptics mid = t.optics("aa", std::sqrt(0.5), 0.0);
    EXPECT_NEAR(mid.extinction_um2, std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(mid.scattering_um2, std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(mid.moments[1], 0.45, 1e-12);
    EXPECT_NEAR(mid.phase[0], 3.0, 1e-12);
    // Clamped beyond the table.
    EXPECT_DOUBLE_EQ(t.optics("aa", 0.2, 0.0).extinction_um2, 2.0);
    EXPECT_DOUBLE_EQ(t.optics("aa", 5.0, 0.0).extinction_um2, 1.0);
    // Humidity: linear between 0 and 50 %, held beyond 50 %; bb has no growth.
    EXPECT_NEAR(t.optics("aa", 0.5, 25.0).extinction_um2, 3.0, 1e-12);
    EXPECT_NEAR(t.optics("aa", 0.7, 25.0).particle_mass_g, 2e-15, 1e-27);
    EXPECT_DOUBLE_EQ(t.optics("aa", 0.7, 0.0).particle_mass_g, 1e-15);
    EXPECT_NEAR(t.optics("aa", 0.5, 25.0).moments[2], 0.35, 1e-12);
    EXPECT_DOUBLE_EQ(t.optics("aa", 0.5, 90.0).extinction_um2, 4.0);
    EXPECT_DOUBLE_EQ(t.optics("bb", 0.5, 90.0).scattering_um2, 0.25);
    EXPECT_THROW((void)t.optics("cc", 0.5, 0.0), Error);
}

// A mixture: cross sections weighted by number, moments and phase by scattering.
TEST(AerosolTable, AMixtureWeighsByNumberAndByScattering) {
    const AerosolTable t = AerosolTable::from_csv(kTable, "t.csv");
    const std::vector<MixtureShare> shares{{"aa", 1.0}, {"bb", 3.0}};
    const ComponentOptics m = t.mixture(shares, 0.5, 0.0);
    EXPECT_NEAR(m.extinction_um2, 0.25 * 2.0 + 0.75 * 1.0, 1e-12);
    EXPECT_NEAR(m.scattering_um2, 0.25 * 1.0 + 0.75 * 0.25, 1e-12);
    EXPECT_NEAR(m.particle_mass_g, 0.25 * 1e-15 + 0.75 * 5e-15, 1e-27);
    const double wa = 0.25 * 1.0, wb = 0.75 * 0.25;
    EXPECT_NEAR(m.moments[1], (wa * 0.5 + wb * 0.0) / (wa + wb), 1e-12);
    EXPECT_NEAR(m.phase[0], (wa * 4.0 + wb * 1.0) / (wa + wb), 1e-12);
    EXPECT_DOUBLE_EQ(m.moments[0], 1.0);
    EXPECT_THROW((void)t.mixture(std::vector<MixtureShare>{}, 0.5, 0.0), Error);
}

std::string error_of(const std::string& text) {
    try {
        (void)AerosolTable::from_csv(text, "t.csv");
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        return e.what();
    }
    return "no error";
}

TEST(AerosolTable, AMalformedTableIsAnInputErrorAtItsLine) {
    const std::string header =
        "component,rh_percent,wavelength_um,extinction_um2,scattering_um2,asymmetry,"
        "particle_mass_g,chi_1,p_0,p_180\n";
    const std::string expected_header =
        "t.csv:1: expected the header line component,rh_percent,wavelength_um,extinction_um2,"
        "scattering_um2,asymmetry,particle_mass_g,...";
    EXPECT_EQ(error_of("x,y\n"), expected_header);
    // The table before its particle-mass column.
    EXPECT_EQ(error_of("component,rh_percent,wavelength_um,extinction_um2,scattering_um2,"
                       "asymmetry,chi_1,p_0,p_180\n"),
              expected_header);
    EXPECT_EQ(error_of(header + "aa,0,0.5,2,1,0.5,1e-15,0.5,4\n"),
              "t.csv:2: expected 10 columns, found 9");
    EXPECT_EQ(error_of(header + "aa,0,0.5,2,3,0.5,1e-15,0.5,4,1\n"),
              "t.csv:2: expected a wavelength > 0 and 0 <= scattering <= extinction");
    EXPECT_EQ(error_of(header + "aa,0,0.5,2,1,0.5,0,0.5,4,1\n"),
              "t.csv:2: expected a particle mass > 0 g");
    EXPECT_EQ(error_of(header + "aa,0,0.5,2,1,0.5,1e-15,0.5,4,1\naa,0,0.4,2,1,0.5,1e-15,0.5,4,1\n"),
              "t.csv:3: a component's wavelengths must increase");
    EXPECT_EQ(error_of(header + "aa,0,0.5,2,1,0.5,1e-15,0.5,4,-1\n"),
              "t.csv:2: phase-function values must be > 0");
    EXPECT_EQ(error_of(header + "aa,0,0.5,2,1,0.5,1e-15,0.5,four,1\n"),
              "t.csv:2: not a number: 'four'");
    EXPECT_EQ(error_of(header), "t.csv: the aerosol optics table has no rows");
    EXPECT_EQ(error_of("component,rh_percent,wavelength_um,extinction_um2,scattering_um2,"
                       "asymmetry,particle_mass_g,chi_2,p_0,p_180\n"),
              "t.csv:1: expected column chi_1, found 'chi_2'");
    EXPECT_EQ(
        error_of(header + "aa,0,0.5,2,1,0.5,1e-15,0.5,4,1\naa,50,0.6,2,1,0.5,1e-15,0.5,4,1\n"),
        "t.csv: component aa has different wavelengths at 50 % humidity");
}

// The shipped table: OPAC's ten components; every phase function integrates to 1 over the
// sphere (to 2 %: 50 angles, linear in ln P, through forward peaks of 0.1°; the exact
// normalisation lives in the moments), and χ₁ is the asymmetry column it was written with.
TEST(AerosolTable, TheShippedTableHoldsOpacsComponents) {
    const AerosolTable& t = *test::aerosol_table();
    for (const char* c :
         {"inso", "waso", "soot", "ssam", "sscm", "minm", "miam", "micm", "mitr", "suso"}) {
        EXPECT_TRUE(t.has(c)) << c;
    }
    EXPECT_EQ(t.moment_count(), 33u);
    const std::vector<double>& angles = t.angles_deg();
    for (const char* c : {"waso", "sscm", "soot"}) {
        for (double wl : {0.3, 0.55, 1.0, 10.0}) {
            const ComponentOptics o = t.optics(c, wl, 70.0);
            double integral = 0.0;
            for (std::size_t i = 0; i + 1 < angles.size(); ++i) {
                // ∫ P sin θ dθ / 2 by log-linear pieces, each split finely.
                constexpr int kSteps = 64;
                const double a = angles[i] * std::numbers::pi / 180.0;
                const double b = angles[i + 1] * std::numbers::pi / 180.0;
                for (int s = 0; s < kSteps; ++s) {
                    const double t0 = (s + 0.5) / kSteps;
                    const double p =
                        std::exp((1 - t0) * std::log(o.phase[i]) + t0 * std::log(o.phase[i + 1]));
                    integral += 0.5 * p * std::sin(a + t0 * (b - a)) * (b - a) / kSteps;
                }
            }
            EXPECT_NEAR(integral, 1.0, 0.02) << c << " " << wl;
            EXPECT_LE(o.scattering_um2, o.extinction_um2);
            EXPECT_GT(o.moments[1], 0.0) << c << " " << wl;
        }
    }
}

}  // namespace aerosol_table_test
}  // namespace glint::atmosphere
