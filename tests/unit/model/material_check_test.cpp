// SPDX-License-Identifier: Apache-2.0
// model::check_material, the physical checks every tool applies alike, and sample_held.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "glint/model/scene.h"

namespace glint::model {
namespace material_check_test {

SpectralTable table(std::vector<double> wavelengths_um, std::vector<double> values) {
    SpectralTable t;
    t.wavelengths_um = std::move(wavelengths_um);
    t.values = std::move(values);
    return t;
}

Material material(SpectralTable reflectance, SpectralTable emissivity = {}) {
    Material m;
    m.id = "m";
    m.reflectance = std::move(reflectance);
    m.emissivity = std::move(emissivity);
    m.emissivity_is_default = m.emissivity.empty();
    m.where = ErrorContext{"s.yaml", 7, "materials[0]"};
    return m;
}

std::string only_error(const Material& m) {
    Diagnostics diagnostics;
    check_material(m, diagnostics);
    if (diagnostics.error_count() != 1)
        return "errors: " + std::to_string(diagnostics.error_count());
    return diagnostics.items().front().text();
}

TEST(SampleHeld, LinearInsideHeldOutside) {
    const SpectralTable t = table({0.4, 1.0}, {0.2, 0.8});
    EXPECT_DOUBLE_EQ(sample_held(t, 0.7), 0.5);
    EXPECT_DOUBLE_EQ(sample_held(t, 0.1), 0.2);
    EXPECT_DOUBLE_EQ(sample_held(t, 5.0), 0.8);
}

TEST(CheckMaterial, GoodMaterialsPass) {
    Diagnostics diagnostics;
    check_material(material(table({0.4, 2.5}, {0.1, 0.12})), diagnostics);  // ε = 1 − ρ
    check_material(material(table({0.4, 2.5}, {0.1, 0.12}), table({0.4, 14.0}, {0.85, 0.95})),
                   diagnostics);
    EXPECT_EQ(diagnostics.items().size(), 0u);
}

TEST(CheckMaterial, SumAboveOneWhereBothAreMeasured) {
    // The emissivity rises linearly: at 2.5 µm it is 0.9077, with ρ = 0.12 the sum is 1.028.
    EXPECT_EQ(
        only_error(material(table({0.4, 2.5}, {0.1, 0.12}), table({0.4, 14.0}, {0.90, 0.95}))),
        "s.yaml:7: materials[0]: material 'm': emissivity 0.9077205882352941 + reflectance "
        "0.12 exceed 1 at 2.5 um (an opaque surface cannot emit and reflect more than a "
        "blackbody)");
}

TEST(CheckMaterial, SumWithinRoundingOfOnePasses) {
    // 0.1000005 + 0.9: 5e-7 above 1, within kEmissivityReflectanceSlack (1e-6).
    Diagnostics diagnostics;
    check_material(
        material(table({0.4, 2.5}, {0.1000005, 0.1000005}), table({0.4, 2.5}, {0.9, 0.9})),
        diagnostics);
    EXPECT_EQ(diagnostics.items().size(), 0u)
        << (diagnostics.items().empty() ? "" : diagnostics.items()[0].text());
    EXPECT_EQ(
        only_error(material(table({0.4, 2.5}, {0.100002, 0.100002}), table({0.4, 2.5}, {0.9, 0.9})))
            .substr(0, 60),
        "s.yaml:7: materials[0]: material 'm': emissivity 0.9 + refle");
}

TEST(CheckMaterial, SumAboveOneOnlyBeyondTheMeasuredCurvesPasses) {
    // ρ measured 0.4–1 µm (held at 0.5 beyond), ε 0.3 at 1 µm rising to 0.9 at 14 µm: the
    // sum exceeds 1 only where ρ is a held guess; the renderer lowers ε there.
    Diagnostics diagnostics;
    check_material(material(table({0.4, 1.0}, {0.5, 0.5}), table({1.0, 14.0}, {0.3, 0.9})),
                   diagnostics);
    EXPECT_EQ(diagnostics.error_count(), 0u);
}

TEST(CheckMaterial, RangesAndTemperature) {
    EXPECT_EQ(only_error(material(table({0.4, 1.0}, {0.1, 1.2}))),
              "s.yaml:7: materials[0]: material 'm': reflectance 1.2 at 1 um lies outside [0, 1]");
    EXPECT_EQ(
        only_error(material(table({0.4, 1.0}, {0.1, 0.2}), table({0.4, 1.0}, {-0.1, 0.2}))),
        "s.yaml:7: materials[0]: material 'm': emissivity -0.1 at 0.4 um lies outside [0, 1]");
    Material cold = material(table({0.4, 1.0}, {0.1, 0.2}));
    cold.temperature_k = -3.0;
    EXPECT_EQ(only_error(cold),
              "s.yaml:7: materials[0]: material 'm': temperature -3 K must be a finite number > 0");
    EXPECT_EQ(only_error(material(SpectralTable{})),
              "s.yaml:7: materials[0]: material 'm' has no reflectance");
}

Material sheet(SpectralTable reflectance, SpectralTable transmittance,
               SpectralTable emissivity = {}) {
    Material m = material(std::move(reflectance), std::move(emissivity));
    m.transmittance = std::move(transmittance);
    return m;
}

TEST(CheckMaterial, ALeafPassesWithKirchhoffsEmissivity) {
    // ρ + τ = 0.9 with no emissivity given: ε = 1 − ρ − τ = 0.1, the sum exactly 1.
    Diagnostics diagnostics;
    check_material(sheet(table({0.4, 2.5}, {0.45, 0.45}), table({0.4, 2.5}, {0.45, 0.45})),
                   diagnostics);
    EXPECT_EQ(diagnostics.items().size(), 0u)
        << (diagnostics.items().empty() ? "" : diagnostics.items()[0].text());
}

TEST(CheckMaterial, ALeafScatteringMoreThanItReceivesIsRefused) {
    EXPECT_EQ(only_error(sheet(table({0.4, 2.5}, {0.5, 0.5}), table({0.4, 2.5}, {0.4, 0.6}))),
              "s.yaml:7: materials[0]: material 'm': reflectance 0.5 + transmittance 0.6 "
              "exceed 1 at 2.5 um (a sheet cannot scatter more than it receives)");
    EXPECT_EQ(only_error(sheet(table({0.4, 2.5}, {0.5, 0.5}), table({0.4, 2.5}, {0.4, 1.5}))),
              "s.yaml:7: materials[0]: material 'm': transmittance 1.5 at 2.5 um lies outside "
              "[0, 1]");
}

TEST(CheckMaterial, ALeafsEmissivityCountsItsTransmittance) {
    // ε 0.2 given, ρ 0.45, τ 0.45: 1.1 > 1.
    EXPECT_EQ(only_error(sheet(table({0.4, 2.5}, {0.45, 0.45}), table({0.4, 2.5}, {0.45, 0.45}),
                               table({0.4, 2.5}, {0.2, 0.2}))),
              "s.yaml:7: materials[0]: material 'm': emissivity 0.2 + reflectance 0.45 + "
              "transmittance 0.45 exceed 1 at 0.4 um (Kirchhoff: a sheet absorbs, so emits, "
              "only 1 - reflectance - transmittance)");
}

TEST(CheckMaterial, ASingleSidedSheetIsRefused) {
    Material m = sheet(table({0.4, 2.5}, {0.4, 0.4}), table({0.4, 2.5}, {0.4, 0.4}));
    m.double_sided = false;
    EXPECT_EQ(only_error(m),
              "s.yaml:7: materials[0]: material 'm' is single-sided and has a transmittance: "
              "light cannot pass a surface whose back face is black");
}

}  // namespace material_check_test
}  // namespace glint::model
