// SPDX-License-Identifier: Apache-2.0
// Tests of the atmosphere readers: the YAML models, the .atm simple subset, the table file,
// and bad input reported with file:line.
#include "glint/yaml/atmosphere_reader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "glint/inputs/scene_atmosphere.h"
#include "glint/model/aerosol_models.h"
#include "glint/test/temp_dir.h"

namespace glint::inputs {
namespace atmosphere_reader_test {

const std::filesystem::path kDir = std::filesystem::path(GLINT_TEST_DATA_DIR) / "atmosphere";

std::filesystem::path write(const test::TempDir& dir, const std::string& name,
                            const std::string& text) {
    const auto path = dir / name;
    std::ofstream(path) << text;
    return path;
}

/// The first error's text, or "" when there is none.
std::string first_error(const Diagnostics& diagnostics) {
    for (const auto& d : diagnostics.items()) {
        if (d.severity == Diagnostic::Severity::error) return d.text();
    }
    return {};
}

TEST(AtmosphereReader, ReadsParametricYaml) {
    Diagnostics diagnostics;
    const auto a = read_atmosphere(kDir / "parametric.yaml", {}, diagnostics, "parametric.yaml");
    EXPECT_EQ(diagnostics.items().size(), 0u) << first_error(diagnostics);
    EXPECT_EQ(a.kind, model::AtmosphereKind::parametric);
    EXPECT_DOUBLE_EQ(a.parametric.aerosol_optical_depth_550, 0.2);
    EXPECT_DOUBLE_EQ(a.parametric.angstrom_exponent, 1.1);
    EXPECT_DOUBLE_EQ(a.parametric.aerosol_scale_height_m, 1500.0);
    EXPECT_DOUBLE_EQ(a.parametric.aerosol_asymmetry, 0.65);
    EXPECT_DOUBLE_EQ(a.parametric.aerosol_single_scatter_albedo, 0.9);
    EXPECT_DOUBLE_EQ(a.parametric.sea_level_pressure_hpa, 1000.0);
    EXPECT_DOUBLE_EQ(a.parametric.air_temperature_k, 300.0);
    // The profile names the air's temperatures and the columns' defaults; the explicit
    // air_temperature_k wins over the profile's 294.2 K.
    EXPECT_EQ(a.parametric.profile, model::StandardAtmosphere::midlatitude_summer);
    EXPECT_DOUBLE_EQ(a.parametric.water_vapor_cm,
                     model::standard_atmosphere(a.parametric.profile).water_column_cm);
    EXPECT_NEAR(a.parametric.water_vapor_cm, 2.922, 0.001);
    EXPECT_NEAR(a.parametric.ozone_atm_cm, 0.334, 0.001);
    EXPECT_EQ(a.where.file, "parametric.yaml");
    EXPECT_EQ(a.where.line, 3);
}

TEST(AtmosphereReader, ProfileSetsDefaultsAndRefusesUnknownNames) {
    const test::TempDir dir;
    Diagnostics diagnostics;
    const auto a =
        read_atmosphere(write(dir, "profile.yaml",
                              "model: parametric\nprofile: subarctic_winter\nozone_atm_cm: 0.3\n"),
                        {}, diagnostics);
    EXPECT_TRUE(diagnostics.items().empty()) << first_error(diagnostics);
    EXPECT_EQ(a.parametric.profile, model::StandardAtmosphere::subarctic_winter);
    EXPECT_DOUBLE_EQ(a.parametric.air_temperature_k, 257.2);
    EXPECT_NEAR(a.parametric.water_vapor_cm, 0.416, 0.001);
    EXPECT_DOUBLE_EQ(a.parametric.ozone_atm_cm, 0.3);

    Diagnostics bad;
    const auto bad_path = write(dir, "bad_profile.yaml", "model: parametric\nprofile: arctic\n");
    (void)read_atmosphere(bad_path, {}, bad);
    EXPECT_EQ(first_error(bad),
              bad_path.string() +
                  ":2: profile: expected tropical, midlatitude_summer, midlatitude_winter, "
                  "subarctic_summer, subarctic_winter, us_standard_1976 or isothermal, got "
                  "'arctic'");

    // The vapour pressure sets only the Brutsaert sky: a warning with gas absorption on.
    Diagnostics warned;
    (void)read_atmosphere(
        write(dir, "vapour.yaml", "model: parametric\nwater_vapor_pressure_hpa: 12\n"), {}, warned);
    ASSERT_EQ(warned.items().size(), 1u);
    EXPECT_NE(warned.items()[0].text().find("water_vapor_pressure_hpa: has no effect"),
              std::string::npos);
}

TEST(AtmosphereReader, WeatherNamesTheWthForEveryModelAndRefusesANonPath) {
    const test::TempDir dir;
    for (const std::string model : {"none", "parametric"}) {
        Diagnostics diagnostics;
        const auto path = write(dir, model + ".yaml", "model: " + model + "\nweather: day.wth\n");
        const auto a = read_atmosphere(path, {}, diagnostics);
        EXPECT_TRUE(diagnostics.items().empty()) << first_error(diagnostics);
        EXPECT_EQ(a.weather_file, "day.wth");  // resolved against the YAML's folder when read
        EXPECT_EQ(a.weather_where.line, 2);
        EXPECT_EQ(a.weather_where.element, "weather");
    }
    Diagnostics bad;
    const auto bad_path = write(dir, "list.yaml", "model: none\nweather: [a.wth, b.wth]\n");
    const auto a = read_atmosphere(bad_path, {}, bad);
    EXPECT_EQ(first_error(bad),
              bad_path.string() + ":2: weather: 'weather' is the path of a .wth weather history");
    EXPECT_TRUE(a.weather_file.empty());
}

TEST(AtmosphereReader, ReadsNoneYaml) {
    Diagnostics diagnostics;
    const auto a = read_atmosphere(kDir / "none.yaml", {}, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors());
    EXPECT_EQ(a.kind, model::AtmosphereKind::none);
}

TEST(AtmosphereReader, ReadsTabulatedYamlAndTable) {
    Diagnostics diagnostics;
    const auto a = read_atmosphere(kDir / "tabulated.yaml", {}, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors()) << first_error(diagnostics);
    ASSERT_EQ(a.kind, model::AtmosphereKind::tabulated);
    ASSERT_EQ(a.tabulated.wavelengths_um.size(), 4u);
    EXPECT_DOUBLE_EQ(a.tabulated.wavelengths_um[1], 0.55);
    EXPECT_DOUBLE_EQ(a.tabulated.sun_transmittance[1], 0.75);
    EXPECT_DOUBLE_EQ(a.tabulated.sensor_transmittance[2], 0.93);
    EXPECT_DOUBLE_EQ(a.tabulated.path_radiance_w_per_cm2_sr_um[0], 0.003);
    EXPECT_DOUBLE_EQ(a.tabulated.sky_irradiance_w_per_cm2_um[3], 0.001);
    EXPECT_TRUE(a.tabulated.thermal_sky_radiance_w_per_cm2_sr_um.empty());
    EXPECT_DOUBLE_EQ(a.tabulated.sky_temperature_k, 250.0);
}

TEST(AtmosphereReader, ReadsAtmSimpleSubset) {
    Diagnostics diagnostics;
    const auto a = read_atmosphere(kDir / "simple.atm", {}, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors()) << first_error(diagnostics);
    EXPECT_EQ(a.kind, model::AtmosphereKind::simple);
    EXPECT_DOUBLE_EQ(a.simple.apparent_sky_temperature_k, 260.0);
    // The weather block names a .wth, read by the loader (inputs/weather.h).
    EXPECT_EQ(diagnostics.warning_count(), 0u);
    EXPECT_EQ(a.weather_file, "mls.wth");
    EXPECT_EQ(a.weather_where.line, 10);
}

TEST(AtmosphereReader, UnsupportedAtmBlockIsAnErrorNamingIt) {
    Diagnostics diagnostics;
    (void)read_atmosphere(kDir / "classic.atm", {}, diagnostics, "classic.atm");
    const std::string text = first_error(diagnostics);
    EXPECT_NE(text.find("classic.atm:5:"), std::string::npos) << text;
    EXPECT_NE(text.find("atmosphere kind <classicradiativetransfer> (a MODTRAN-built "
                        "atmosphere) is not supported"),
              std::string::npos)
        << text;
    // The way forward: the render option that replaces the atmosphere.
    EXPECT_NE(text.find("glint-render --atmosphere none|parametric|FILE"), std::string::npos)
        << text;
}

TEST(AtmosphereReader, YamlSyntaxErrorHasLine) {
    test::TempDir dir;
    const auto path = write(dir, "bad.yaml", "model: parametric\nangstrom_exponent: [1, 2\n");
    Diagnostics diagnostics;
    (void)read_atmosphere(path, {}, diagnostics, "bad.yaml");
    const std::string text = first_error(diagnostics);
    EXPECT_NE(text.find("bad.yaml:"), std::string::npos) << text;
    EXPECT_NE(text.find("invalid YAML: "), std::string::npos) << text;
    ASSERT_TRUE(diagnostics.has_errors());
    EXPECT_GE(diagnostics.items()[0].where.line, 2);
}

TEST(AtmosphereReader, UnknownModelIsAnError) {
    test::TempDir dir;
    const auto path = write(dir, "bad.yaml", "# c\nmodel: modtran\n");
    Diagnostics diagnostics;
    (void)read_atmosphere(path, {}, diagnostics, "bad.yaml");
    EXPECT_EQ(first_error(diagnostics),
              "bad.yaml:2: model: unknown atmosphere model 'modtran', expected none, parametric "
              "or tabulated");
}

TEST(AtmosphereReader, MissingModelIsAnError) {
    test::TempDir dir;
    const auto path = write(dir, "bad.yaml", "angstrom_exponent: 1\n");
    Diagnostics diagnostics;
    (void)read_atmosphere(path, {}, diagnostics, "bad.yaml");
    EXPECT_NE(first_error(diagnostics).find("missing required key 'model'"), std::string::npos);
}

TEST(AtmosphereReader, NegativeOpticalDepthIsAnError) {
    test::TempDir dir;
    const auto path =
        write(dir, "bad.yaml", "model: parametric\n\naerosol_optical_depth_550: -0.1\n");
    Diagnostics diagnostics;
    (void)read_atmosphere(path, {}, diagnostics, "bad.yaml");
    EXPECT_EQ(first_error(diagnostics),
              "bad.yaml:3: aerosol_optical_depth_550: value -0.1 out of range, expected a "
              "number in [0, 100]");
}

/// Every diagnostic of reading `text` as e.yaml in `dir`, as "file:line: key: message" texts.
std::vector<std::string> messages_of(const test::TempDir& dir, const std::string& text) {
    Diagnostics d;
    (void)read_atmosphere(write(dir, "e.yaml", text), {}, d, "e.yaml");
    std::vector<std::string> out;
    for (const auto& item : d.items()) out.push_back(item.text());
    return out;
}

TEST(AtmosphereReader, GasAndScatteringKeys) {
    test::TempDir dir;
    Diagnostics diagnostics;
    const auto a = read_atmosphere(
        write(dir, "g.yaml",
              "model: parametric\ngas_absorption: true\nwater_vapor_cm: 1.42\nozone_atm_cm: 0.34\n"
              "multiple_scattering: yes\nground_albedo: 0.35\n"),
        {}, diagnostics, "g.yaml");
    EXPECT_EQ(diagnostics.items().size(), 0u) << first_error(diagnostics);
    EXPECT_TRUE(a.parametric.gas_absorption);
    EXPECT_DOUBLE_EQ(a.parametric.water_vapor_cm, 1.42);
    EXPECT_DOUBLE_EQ(a.parametric.ozone_atm_cm, 0.34);
    EXPECT_TRUE(a.parametric.multiple_scattering);
    EXPECT_DOUBLE_EQ(a.parametric.ground_albedo, 0.35);
    const auto off =
        read_atmosphere(write(dir, "o.yaml",
                              "model: parametric\ngas_absorption: false\nmultiple_scattering: no\n"
                              "directional_sky: false\n"),
                        {}, diagnostics, "o.yaml");
    EXPECT_FALSE(off.parametric.gas_absorption);
    EXPECT_FALSE(off.parametric.multiple_scattering);
    EXPECT_FALSE(off.parametric.directional_sky);
    EXPECT_TRUE(a.parametric.directional_sky);
    EXPECT_TRUE(a.parametric.refraction);
    // Defaults: gases and multiple scattering on, a mid-latitude summer column, albedo 0.2.
    const model::ParametricAtmosphere defaults;
    EXPECT_TRUE(defaults.gas_absorption);
    EXPECT_DOUBLE_EQ(defaults.water_vapor_cm, 2.924);
    EXPECT_DOUBLE_EQ(defaults.ozone_atm_cm, 0.332);
    EXPECT_TRUE(defaults.multiple_scattering);
    EXPECT_DOUBLE_EQ(defaults.ground_albedo, 0.2);

    using V = std::vector<std::string>;
    EXPECT_EQ(messages_of(dir, "model: parametric\ngas_absorption: maybe\n"),
              V{"e.yaml:2: gas_absorption: expected true or false"});
    EXPECT_EQ(messages_of(dir, "model: parametric\ndirectional_sky: 3\n"),
              V{"e.yaml:2: directional_sky: expected true or false"});
    EXPECT_EQ(messages_of(dir, "model: parametric\nrefraction: sometimes\n"),
              V{"e.yaml:2: refraction: expected true or false"});
    EXPECT_EQ(messages_of(dir, "model: parametric\nwater_vapor_cm: -1\n"),
              V{"e.yaml:2: water_vapor_cm: value -1 out of range, expected a number >= 0"});
    EXPECT_EQ(messages_of(dir, "model: parametric\nground_albedo: 1.5\n"),
              V{"e.yaml:2: ground_albedo: value 1.5 out of range, expected a number in [0, 1]"});
}

TEST(AtmosphereReader, KeysLeftWithoutEffectAreWarnedAtTheirLine) {
    test::TempDir dir;
    using V = std::vector<std::string>;
    EXPECT_EQ(messages_of(dir,
                          "model: parametric\ngas_absorption: false\nwater_vapor_cm: 1\n"
                          "ozone_atm_cm: 0.3\nmultiple_scattering: false\n"
                          "ground_albedo: 0.4\n"),
              (V{"e.yaml:3: water_vapor_cm: has no effect: gas_absorption is false",
                 "e.yaml:4: ozone_atm_cm: has no effect: gas_absorption is false",
                 "e.yaml:6: ground_albedo: has no effect: multiple_scattering is false"}));
    // The isothermal profile has no levels to refract through.
    EXPECT_EQ(messages_of(dir, "model: parametric\nprofile: isothermal\nrefraction: true\n"),
              (V{"e.yaml:3: refraction: has no effect: profile isothermal has no levels to "
                 "refract through"}));
    EXPECT_EQ(messages_of(dir, "model: parametric\nrefraction: true\n"), V{});
    // The layered aerosol's own keys mean nothing without an aerosol_model.
    EXPECT_EQ(messages_of(dir,
                          "model: parametric\nrelative_humidity_percent: 80\n"
                          "aerosol_season: fall_winter\n"),
              (V{"e.yaml:2: relative_humidity_percent: has no effect: it belongs to the layered "
                 "aerosol of an aerosol_model, and none is given",
                 "e.yaml:3: aerosol_season: has no effect: it belongs to the layered aerosol of "
                 "an aerosol_model, and none is given"}));
}

TEST(AtmosphereReader, AerosolModelAndVisibility) {
    test::TempDir dir;
    Diagnostics diagnostics;
    // The layered aerosol: its type and keys.
    const auto a = read_atmosphere(
        write(dir, "m.yaml",
              "model: parametric\naerosol_model: maritime\nvisibility_km: 10\n"
              "relative_humidity_percent: 85\naerosol_season: fall_winter\n"
              "tropospheric_aerosol: continental_clean\nstratospheric_aerosol: none\n"),
        {}, diagnostics, "m.yaml");
    EXPECT_EQ(diagnostics.items().size(), 0u) << first_error(diagnostics);
    EXPECT_EQ(a.parametric.aerosol_model, "maritime");
    EXPECT_DOUBLE_EQ(a.parametric.visibility_km, 10.0);
    EXPECT_EQ(a.parametric.relative_humidity_percent, std::optional<double>(85.0));
    EXPECT_EQ(a.parametric.aerosol_season, model::AerosolSeason::fall_winter);
    EXPECT_EQ(a.parametric.tropospheric_aerosol, "continental_clean");
    EXPECT_EQ(a.parametric.stratospheric_aerosol, "none");
    EXPECT_FALSE(a.parametric.aerosol_column_depth_550.has_value());
    // With it, aerosol_optical_depth_550 scales the column.
    Diagnostics scaled_diagnostics;
    const auto scaled = read_atmosphere(
        write(dir, "s.yaml",
              "model: parametric\naerosol_model: urban\naerosol_optical_depth_550: 0.4\n"),
        {}, scaled_diagnostics, "s.yaml");
    EXPECT_EQ(scaled_diagnostics.items().size(), 0u) << first_error(scaled_diagnostics);
    EXPECT_EQ(scaled.parametric.aerosol_column_depth_550, std::optional<double>(0.4));
    // Without it, the exponential aerosol: Koschmieder's β = 3.912/23 − 0.01159 km⁻¹ over a
    // 1 km scale height.
    Diagnostics exponential_diagnostics;
    const auto e =
        read_atmosphere(write(dir, "x.yaml",
                              "model: parametric\nvisibility_km: 23\naerosol_scale_height_m: 1000\n"
                              "aerosol_asymmetry: 0.8\n"),
                        {}, exponential_diagnostics, "x.yaml");
    EXPECT_EQ(exponential_diagnostics.items().size(), 0u) << first_error(exponential_diagnostics);
    EXPECT_TRUE(e.parametric.aerosol_model.empty());
    EXPECT_DOUBLE_EQ(e.parametric.aerosol_asymmetry, 0.8);
    EXPECT_NEAR(e.parametric.aerosol_optical_depth_550, 3.912 / 23.0 - 0.01159, 1e-12);

    using V = std::vector<std::string>;
    EXPECT_EQ(messages_of(dir, "model: parametric\naerosol_model: volcanic\n"),
              V{std::string("e.yaml:2: aerosol_model: expected a boundary-layer type, one of ") +
                model::aerosol_mixture_names() + " but stratospheric, got 'volcanic'"});
    EXPECT_EQ(messages_of(dir, "model: parametric\naerosol_model: stratospheric\n"),
              V{std::string("e.yaml:2: aerosol_model: expected a boundary-layer type, one of ") +
                model::aerosol_mixture_names() + " but stratospheric, got 'stratospheric'"});
    // The exponential aerosol's keys are errors beside an aerosol_model, each at its line.
    EXPECT_EQ(messages_of(dir,
                          "model: parametric\naerosol_model: urban\nangstrom_exponent: 1\n"
                          "aerosol_asymmetry: 0.6\n"),
              (V{"e.yaml:3: angstrom_exponent: aerosol_model sets the aerosol's optics and "
                 "profile (OPAC's Mie optics, LOWTRAN 7's layers); give angstrom_exponent only "
                 "without it",
                 "e.yaml:4: aerosol_asymmetry: aerosol_model sets the aerosol's optics and "
                 "profile (OPAC's Mie optics, LOWTRAN 7's layers); give aerosol_asymmetry only "
                 "without it"}));
    EXPECT_EQ(messages_of(dir,
                          "model: parametric\naerosol_model: rural\naerosol_season: monsoon\n"
                          "relative_humidity_percent: 120\ntropospheric_aerosol: smoke\n"),
              (V{"e.yaml:4: relative_humidity_percent: value 120 out of range, expected a number "
                 "in [0, 100]",
                 "e.yaml:3: aerosol_season: expected spring_summer or fall_winter, got 'monsoon'",
                 std::string("e.yaml:5: tropospheric_aerosol: expected one of ") +
                     model::aerosol_mixture_names() + ", none, got 'smoke'"}));
    EXPECT_EQ(
        messages_of(dir, "model: parametric\naerosol_optical_depth_550: 0.1\nvisibility_km: 20\n"),
        V{"e.yaml:3: visibility_km: give aerosol_optical_depth_550 or visibility_km, not both"});
    EXPECT_EQ(
        messages_of(dir,
                    "model: parametric\naerosol_model: rural\n"
                    "aerosol_optical_depth_550: 0.1\nvisibility_km: 20\n"),
        V{"e.yaml:4: visibility_km: give aerosol_optical_depth_550 or visibility_km, not both"});
    EXPECT_EQ(messages_of(dir, "model: parametric\nvisibility_km: 400\n"),
              V{"e.yaml:2: visibility_km: visibility 400 km is beyond that of aerosol-free air "
                "(337 km)"});
    EXPECT_EQ(messages_of(dir, "model: parametric\nvisibility_km: 0\n"),
              V{"e.yaml:2: visibility_km: value 0 out of range, expected a number > 0"});
    // An optical depth of 10^6 would be 7 GB of scattering sublayers: refused at the reader.
    EXPECT_EQ(messages_of(dir, "model: parametric\naerosol_optical_depth_550: 1e6\n"),
              V{"e.yaml:2: aerosol_optical_depth_550: value 1e+06 out of range, expected a "
                "number in [0, 100]"});
    EXPECT_EQ(messages_of(dir, "model: parametric\nvisibility_km: 0.01\n"),
              V{"e.yaml:2: visibility_km: visibility 0.01 km gives an aerosol optical depth of "
                "469.4 at 550 nm, beyond the 100 glint takes"});
}

// A user's aerosol profile: rows in either order stored ascending, the top row closing it,
// masses with the humidity they were weighed at, and the keys beside it.
TEST(AtmosphereReader, AerosolProfile) {
    test::TempDir dir;
    Diagnostics diagnostics;
    const auto a = read_atmosphere(write(dir, "p.yaml",
                                         "model: parametric\n"
                                         "aerosol_optical_depth_550: 0.3\n"
                                         "aerosol_profile:\n"
                                         "  components: [inso, waso, soot]\n"
                                         "  unit: g_per_m3\n"
                                         "  mass_humidity_percent: 50\n"
                                         "  levels:\n"
                                         "    - [12, 0, 0, 0]\n"
                                         "    - [2, 2.3e-6, 4.6e-7, 1.4e-8]\n"
                                         "    - [0, 1.0e-5, 1.5e-5, 5.3e-7]\n"),
                                   {}, diagnostics, "p.yaml");
    EXPECT_EQ(diagnostics.items().size(), 0u) << first_error(diagnostics);
    ASSERT_TRUE(a.parametric.aerosol_profile.has_value());
    const model::AerosolProfile& profile = *a.parametric.aerosol_profile;
    EXPECT_EQ(profile.components, (std::vector<std::string>{"inso", "waso", "soot"}));
    EXPECT_TRUE(profile.mass_densities);
    EXPECT_EQ(profile.mass_humidity_percent, std::optional<double>(50.0));
    EXPECT_EQ(profile.altitudes_km, (std::vector<double>{0.0, 2.0, 12.0}));
    ASSERT_EQ(profile.densities.size(), 2u);
    EXPECT_EQ(profile.densities[0], (std::vector<double>{1.0e-5, 1.5e-5, 5.3e-7}));
    EXPECT_EQ(profile.densities[1], (std::vector<double>{2.3e-6, 4.6e-7, 1.4e-8}));
    EXPECT_EQ(profile.where.line, 4);
    EXPECT_EQ(a.parametric.aerosol_column_depth_550, std::optional<double>(0.3));
    EXPECT_TRUE(a.parametric.aerosol_model.empty());

    using V = std::vector<std::string>;
    const std::string head = "model: parametric\naerosol_profile:\n  components: [waso]\n";
    // Numbers per cm³; the humidity beside it is every layer's, no warning.
    Diagnostics numbers_diagnostics;
    const auto n = read_atmosphere(write(dir, "n.yaml",
                                         head + "  unit: per_cm3\n  levels: [[0, 7000], [2, 0]]\n"
                                                "relative_humidity_percent: 80\n"),
                                   {}, numbers_diagnostics, "n.yaml");
    EXPECT_EQ(numbers_diagnostics.items().size(), 0u) << first_error(numbers_diagnostics);
    ASSERT_TRUE(n.parametric.aerosol_profile.has_value());
    EXPECT_FALSE(n.parametric.aerosol_profile->mass_densities);
    EXPECT_EQ(n.parametric.relative_humidity_percent, std::optional<double>(80.0));
    // Keys without effect or unknown: warnings at their lines.
    EXPECT_EQ(messages_of(dir, head + "  unit: per_cm3\n  mass_humidity_percent: 50\n"
                                      "  level: 3\n  levels: [[0, 7000], [2, 0]]\n"
                                      "aerosol_season: fall_winter\n"),
              (V{"e.yaml:8: aerosol_season: has no effect: it belongs to the layered aerosol of "
                 "an aerosol_model, and aerosol_profile replaces it",
                 "e.yaml:6: aerosol_profile.level: unknown key, ignored (aerosol_profile takes "
                 "components, unit, mass_humidity_percent, levels)",
                 "e.yaml:5: aerosol_profile.mass_humidity_percent: has no effect: the densities "
                 "are particle numbers (unit per_cm3), not masses"}));
    // Errors, each at its line.
    EXPECT_EQ(messages_of(dir, head + "  unit: ug\n  levels: [[0, 7000], [2, 0]]\n"),
              V{"e.yaml:4: aerosol_profile.unit: expected per_cm3 (particles per cm^3) or "
                "g_per_m3 (grams per m^3), got 'ug'"});
    EXPECT_EQ(messages_of(dir,
                          "model: parametric\naerosol_profile:\n  components: [waso, dust, "
                          "waso]\n  unit: per_cm3\n  levels: [[0, 1, 1, 1], [2, 0, 0, 0]]\n"),
              (V{std::string("e.yaml:3: aerosol_profile.components: expected one of ") +
                     model::aerosol_component_names() + ", got 'dust'",
                 "e.yaml:3: aerosol_profile.components: component 'waso' is listed twice"}));
    EXPECT_EQ(messages_of(dir, "model: parametric\naerosol_profile:\n  unit: per_cm3\n"),
              (V{"e.yaml:3: aerosol_profile.components: expected a list of OPAC components (" +
                 std::string(model::aerosol_component_names()) + ")"}));
    EXPECT_EQ(messages_of(dir, head + "  unit: per_cm3\n"),
              V{"e.yaml:3: aerosol_profile.levels: expected at least two rows [altitude_km, then "
                "one density per component: 1]"});
    EXPECT_EQ(messages_of(dir, head + "  unit: per_cm3\n  levels:\n    - [0, 7000]\n"
                                      "    - [2, 1, 5]\n    - [3, many]\n    - [4, 0]\n"),
              (V{"e.yaml:7: aerosol_profile.levels: expected a row [altitude_km, then one "
                 "density per component: 1]",
                 "e.yaml:8: aerosol_profile.levels: expected numbers in the row [altitude_km, "
                 "then one density per component: 1]"}));
    EXPECT_EQ(messages_of(dir, head + "  unit: per_cm3\n  levels: [[0, -1], [200, 0]]\n"),
              (V{"e.yaml:5: aerosol_profile.levels: densities must be >= 0",
                 "e.yaml:5: aerosol_profile.levels: altitude 200 km out of range, expected [0, "
                 "100] km above sea level"}));
    EXPECT_EQ(messages_of(dir, head + "  unit: per_cm3\n  levels:\n    - [0, 1]\n"
                                      "    - [2, 1]\n    - [1, 0]\n"),
              V{"e.yaml:8: aerosol_profile.levels: altitudes must increase (or decrease) "
                "strictly from row to row"});
    EXPECT_EQ(messages_of(dir, head + "  unit: per_cm3\n  levels:\n    - [0, 7000]\n"
                                      "    - [2, 100]\n"),
              V{"e.yaml:7: aerosol_profile.levels: the highest row closes the profile (each "
                "row's densities fill the layer up to the next row): its densities must be 0; "
                "add a row above it to extend the aerosol"});
    EXPECT_EQ(messages_of(dir, head + "  unit: g_per_m3\n  mass_humidity_percent: 101\n"
                                      "  levels: [[0, 1e-5], [2, 0]]\n"),
              V{"e.yaml:5: aerosol_profile.mass_humidity_percent: value 101 out of range, "
                "expected a number in [0, 100]"});
    EXPECT_EQ(messages_of(dir, "model: parametric\naerosol_profile: [1, 2]\n"),
              V{"e.yaml:2: aerosol_profile: expected a mapping with components, unit and levels"});
    // The other aerosols' keys beside it.
    EXPECT_EQ(messages_of(dir,
                          "model: parametric\naerosol_model: rural\nvisibility_km: 5\n"
                          "angstrom_exponent: 1\n" +
                              head.substr(std::string("model: parametric\n").size()) +
                              "  unit: per_cm3\n  levels: [[0, 7000], [2, 0]]\n"),
              (V{"e.yaml:2: aerosol_model: give aerosol_model or aerosol_profile, not both",
                 "e.yaml:4: angstrom_exponent: aerosol_profile sets the aerosol's optics and "
                 "amount (OPAC's Mie optics, its own densities; aerosol_optical_depth_550 scales "
                 "it); give angstrom_exponent only without it",
                 "e.yaml:3: visibility_km: aerosol_profile sets the aerosol's optics and amount "
                 "(OPAC's Mie optics, its own densities; aerosol_optical_depth_550 scales it); "
                 "give visibility_km only without it"}));
}

TEST(AtmosphereReader, NonNumberAndUnknownKey) {
    test::TempDir dir;
    const auto path =
        write(dir, "bad.yaml", "model: parametric\nangstrom_exponent: big\ncloud_cover: 0.3\n");
    Diagnostics diagnostics;
    (void)read_atmosphere(path, {}, diagnostics, "bad.yaml");
    EXPECT_EQ(first_error(diagnostics), "bad.yaml:2: angstrom_exponent: expected a number");
    EXPECT_EQ(diagnostics.warning_count(), 1u);
}

TEST(AtmosphereReader, BadTableRowHasFileAndLine) {
    test::TempDir dir;
    write(dir, "t.txt",
          "# header\n0.4 0.5 0.5 0 0\n0.5 1.5 0.5 0 0\n0.35 0.5 0.5 0 0\n0.6 x 1 0 0\n");
    Diagnostics diagnostics;
    const auto table = yaml::read_atmosphere_table(dir / "t.txt", {}, diagnostics, "t.txt");
    ASSERT_EQ(diagnostics.error_count(), 4u);
    EXPECT_EQ(diagnostics.items()[0].text(), "t.txt:3: transmittances must lie in [0, 1]");
    EXPECT_NE(diagnostics.items()[1].text().find("t.txt:4: wavelength 0.35 um is not greater"),
              std::string::npos);
    EXPECT_EQ(diagnostics.items()[2].text(), "t.txt:5: 'x' is not a finite number");
    EXPECT_EQ(diagnostics.items()[3].text(),
              "t.txt:2: atmosphere table needs at least 2 rows, found 1");
    EXPECT_EQ(table.wavelengths_um.size(), 1u);
}

TEST(AtmosphereReader, TableWithWrongColumnCount) {
    test::TempDir dir;
    write(dir, "t.txt", "0.4 0.5 0.5 0 0 0\n0.5 0.5 0.5 0 0\n");
    Diagnostics diagnostics;
    (void)yaml::read_atmosphere_table(dir / "t.txt", {}, diagnostics, "t.txt");
    ASSERT_TRUE(diagnostics.has_errors());
    EXPECT_EQ(diagnostics.items()[0].text(), "t.txt:2: row has 5 values, the first row has 6");
}

TEST(AtmosphereReader, MissingTableFileIsReportedAtTheKey) {
    test::TempDir dir;
    const auto path = write(dir, "a.yaml", "model: tabulated\ntable: nowhere.txt\n");
    Diagnostics diagnostics;
    (void)read_atmosphere(path, {}, diagnostics, "a.yaml");
    const std::string text = first_error(diagnostics);
    EXPECT_EQ(text.rfind("a.yaml:2: table: ", 0), 0u) << text;
}

TEST(AtmosphereReader, UnreadableFileThrows) {
    Diagnostics diagnostics;
    EXPECT_THROW((void)read_atmosphere(kDir / "does-not-exist.yaml", {}, diagnostics), Error);
}

}  // namespace atmosphere_reader_test
}  // namespace glint::inputs
