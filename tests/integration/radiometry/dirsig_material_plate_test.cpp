// SPDX-License-Identifier: Apache-2.0
// A DIRSIG `.mat` material that gives only an emissivity (tests/data/materials/plate.mat, a
// classic .ems curve) rendered as a plate: its reflectance is 1 − ε where the MaterialTable
// meets both, so under a sun L = (1 − ε) E cos θ / π + ε B and under a uniform sky
// L = (1 − ε) L_sky + ε B, with ε(λ) interpolated from the .ems by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "glint/core/spectral.h"
#include "glint/dirsig/scene_reader.h"
#include "tracer_fixture.h"

namespace glint::radiometry {
namespace dirsig_material_plate_test {

using test::batch_of;
using test::direction_from;
using test::FixedRay;
using test::ground_plane;
using test::Rig;

const std::filesystem::path kPlateMat =
    std::filesystem::path(GLINT_TEST_DATA_DIR) / "materials" / "plate.mat";

/// emissivity/paint.ems: 0.90 at 0.4 µm, 0.60 at 0.7 µm, 0.95 at 14 µm, linear between.
double paint_emissivity(double wavelength_um) {
    if (wavelength_um <= 0.7) return 0.90 + (wavelength_um - 0.4) / 0.3 * (0.60 - 0.90);
    return 0.60 + (wavelength_um - 0.7) / 13.3 * (0.95 - 0.60);
}

model::Scene plate_scene() {
    Diagnostics diagnostics;
    model::Scene scene;
    scene.materials = dirsig::read_dirsig_materials(kPlateMat, {}, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors());
    EXPECT_EQ(scene.materials.size(), 1u);
    test::add_primitive(scene, ground_plane(), 0);
    return scene;
}

SampleRay nadir_ray() { return {{0.0, 0.0, 1000.0}, {0.0, 0.0, -1.0}, 0.0, 1.0}; }

TEST(DirsigMaterialPlate, EmissivityOnlyPlateUnderTheSunReflectsOneMinusEmissivity) {
    const SpectralGrid visible({0.45, 0.55, 0.65});
    const std::vector<double> sun{0.20, 0.19, 0.16};
    const double zenith_deg = 30.0;
    Rig rig(plate_scene(), visible,
            Environment::uniform(visible, direction_from(zenith_deg, 135.0), sun, {0, 0, 0}));
    const FixedRay source(nadir_ray());
    const Solution s = solve(rig.tracer, batch_of(source, 2000), 0);
    const double relative_error = s.standard_error_w_per_cm2_sr_um / s.radiance_w_per_cm2_sr_um[0];
    for (std::size_t b = 0; b < 3; ++b) {
        const double w = visible.wavelength_um(b);
        const double eps = paint_emissivity(w);
        const double expected = (1.0 - eps) * sun[b] *
                                    std::cos(zenith_deg * std::numbers::pi / 180.0) /
                                    std::numbers::pi +
                                eps * planck_radiance_w_per_cm2_sr_um(w, 320.0);
        EXPECT_NEAR(rig.materials.reflectance(0)[b], 1.0 - eps, 1e-12) << b;
        EXPECT_NEAR(s.radiance_w_per_cm2_sr_um[b], expected,
                    (4.0 * relative_error + 1e-5) * expected)
            << "band " << b;
    }
}

TEST(DirsigMaterialPlate, EmissivityOnlyPlateUnderAUniformSkyEmitsAndReflects) {
    const SpectralGrid thermal({8.0, 10.0, 12.0});
    const std::vector<double> sky{0.001, 0.001, 0.001};
    Rig rig(plate_scene(), thermal, Environment::uniform(thermal, {0.0, 0.0, 1.0}, {0, 0, 0}, sky));
    const FixedRay source({{0.0, 0.0, 10.0}, {0.0, 0.0, -1.0}, 0.0, 1.0});
    const Solution s = solve(rig.tracer, batch_of(source, 4000), 0);
    for (std::size_t b = 0; b < 3; ++b) {
        const double w = thermal.wavelength_um(b);
        const double eps = paint_emissivity(w);
        const double expected =
            (1.0 - eps) * sky[b] + eps * planck_radiance_w_per_cm2_sr_um(w, 320.0);
        // As the furnace plate: exact but for rays grazing past the 100 km plate's edge.
        EXPECT_NEAR(s.radiance_w_per_cm2_sr_um[b], expected, 1e-6 * sky[b] + 1e-12 * expected)
            << "band " << b;
    }
}

}  // namespace dirsig_material_plate_test
}  // namespace glint::radiometry
