// SPDX-License-Identifier: Apache-2.0
// Analytic tests of the path tracer with the directional surface models (docs/materials.md):
// - a leaf layer with gaps (a checkerboard, cover 1/2) over soil: the two-stream sum with the
//   layer's effective ρ_L = c ρ and τ_L = (1 − c) + c τ, within 0.5 % at 2 × 10⁵ samples;
// - Kirchhoff per direction: a closed isothermal enclosure whose walls are GGX, Ward or
//   Ross–Li (Kirchhoff's emissivity 1 − ρ A(θo)) radiates B(T) in every direction, within
//   0.5 % at 10⁵ samples (a direction-free ε = 1 − ρ would leave it short by ρ (1 − A));
// - a Ward plate under the sun, viewed near its specular peak and off it: L = E cos θ f(wo,
//   wi_sun), with the sun's disc found by shadow rays and by the lobe's draws (multiple
//   importance sampling), within 4 standard errors and 0.5 %;
// - a mirror (SPECULAR_FRACTION-style share s, roughness 0) shows the sun's disc, radiance
//   s ρ E / Ω_sun, in the specular direction, and only the diffuse share elsewhere;
// - a Ross–Li plate under a uniform sky: L = f_iso A(θv) L_sky (A by quadrature);
// - a lobe that would reflect more than it receives is refused by name.
#include <gtest/gtest.h>

#include <cmath>

#include "glint/core/error.h"
#include "glint/core/spectral.h"
#include "glint/radiometry/brdf_models.h"
#include "tracer_fixture.h"

namespace glint::radiometry {
namespace surface_models_test {

using test::batch_of;
using test::box;
using test::direction_from;
using test::FixedRay;
using test::flat_material;
using test::ground_plane;
using test::Rig;

using test::kBlack;
using test::kHighCountRelative;
using test::kSigmas;
using test::kSun;
using test::kVisible;

model::Material ward_material(const std::string& id, double diffuse, double specular,
                              double alpha_x, double alpha_y, double temperature_k = 300.0) {
    model::Material m = flat_material(id, diffuse + specular, temperature_k);
    m.model = model::ReflectionModel::ward;
    m.ward = {diffuse, specular, alpha_x, alpha_y};
    return m;
}

model::Material ross_li_material(const std::string& id, double iso, double vol, double geo,
                                 double temperature_k = 300.0) {
    model::Material m = flat_material(id, iso, temperature_k);
    m.model = model::ReflectionModel::ross_li;
    m.ross_li = {vol, geo};
    return m;
}

TEST(SurfaceModels, IsothermalEnclosuresOfDirectionalWallsRadiateAsABlackbody) {
    const SpectralGrid thermal({8.0, 10.0, 12.0});
    const double t_k = 300.0;
    std::vector<std::pair<std::string, model::Material>> walls = {
        {"ggx", flat_material("ggx", 0.7, t_k, std::nullopt, model::SpecularLobe{0.8, 0.5})},
        {"ward", ward_material("ward", 0.2, 0.5, 0.3, 0.1, t_k)},
        {"ross-li", ross_li_material("ross-li", 0.5, 0.6, 0.15, t_k)},
    };
    for (auto& [name, wall] : walls) {
        model::Scene scene;
        scene.materials.push_back(wall);
        test::add_primitive(scene, box({-5.0, -4.0, -3.0}, {5.0, 4.0, 3.0}), 0);
        TracerSettings settings;
        settings.max_bounces = 10'000;
        Rig rig(std::move(scene), thermal,
                Environment::uniform(thermal, {0.0, 0.0, 1.0}, {0, 0, 0}, {0, 0, 0}), settings);
        ASSERT_TRUE(rig.materials.directional_emission(0)) << name;
        const test::SphereRays source({0.5, -0.3, 0.2});
        const Solutions many = solve(rig.tracer, batch_of(source, 100'000), Context{});
        for (std::size_t b = 0; b < 3; ++b) {
            const double expected = planck_radiance_w_per_cm2_sr_um(thermal.wavelength_um(b), t_k);
            EXPECT_NEAR(many.radiance(0)[b], expected, kHighCountRelative * expected)
                << name << " band " << b;
        }
    }
}

TEST(SurfaceModels, WardPlateUnderTheSunNearAndOffItsPeak) {
    const double diffuse = 0.1;
    const double specular = 0.4;
    const double alpha = 0.12;
    model::Scene scene;
    scene.materials.push_back(ward_material("metal", diffuse, specular, alpha, alpha));
    test::add_primitive(scene, ground_plane(), 0);
    const double sun_zenith = 35.0;
    const Vec3 sun = direction_from(sun_zenith, 180.0);
    Rig rig(std::move(scene), kVisible, Environment::uniform(kVisible, sun, kSun, kBlack));
    const WardLobe lobe(alpha, alpha);
    // The peak is at the sun's mirror direction (zenith 35°, azimuth 0°).
    for (const double view_zenith : {38.0, 55.0}) {
        const Vec3 to_eye = direction_from(view_zenith, 0.0);
        const FixedRay source({to_eye * 10.0, -to_eye, 0.0, 1.0});
        // Ward's lobe is wavelength-free; the local frame is the scene's (normal +z). The lobe
        // varies across the sun's disc (0.27° against α = 0.12 rad: ~3e-4 relative), so the
        // reference averages f cos θ over the disc (400 × 400 stratified points, uniform in
        // solid angle).
        const Frame disc = Frame::from_normal(sun);
        const double one_minus_cos = rig.environment.sun_cone_one_minus_cos();
        double f_cos = 0.0;
        const int n = 400;
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                const Vec3 wi = disc.to_world(
                    sample_uniform_cone_1mc((i + 0.5) / n, (j + 0.5) / n, one_minus_cos));
                f_cos += (diffuse / kPi + specular * lobe.eval(to_eye, wi)) * wi.z;
            }
        }
        f_cos /= n * n;
        // The lobe's draws find the disc with probability ~4e-4 per path, carrying ~4e-4 of
        // the sum: a run of a few thousand paths may see none, so its standard error says
        // nothing of them; 200,000 paths see ~80.
        const Solution many = solve(rig.tracer, batch_of(source, 200'000), 0);
        for (std::size_t b = 0; b < 3; ++b) {
            const double expected = kSun[b] * f_cos;
            EXPECT_NEAR(
                many.radiance_w_per_cm2_sr_um[b], expected,
                kSigmas * many.standard_error_w_per_cm2_sr_um * kSun[b] / kSun[0] + 1e-5 * expected)
                << "view " << view_zenith << " band " << b;
            EXPECT_NEAR(many.radiance_w_per_cm2_sr_um[b], expected, kHighCountRelative * expected)
                << "view " << view_zenith << " band " << b;
        }
    }
}

TEST(SurfaceModels, AMirrorShowsTheSunsDiscInTheSpecularDirectionOnly) {
    const double rho = 0.3;
    const double share = 0.6;
    model::Scene scene;
    scene.materials.push_back(
        flat_material("water", rho, 300.0, std::nullopt, model::SpecularLobe{share, 0.0}));
    test::add_primitive(scene, ground_plane(), 0);
    const double sun_zenith = 40.0;
    const Vec3 sun = direction_from(sun_zenith, 90.0);
    const Environment env = Environment::uniform(kVisible, sun, kSun, kBlack);
    const double omega_sr = 2.0 * kPi * env.sun_cone_one_minus_cos();
    Rig rig(std::move(scene), kVisible, env);
    const auto view = [&](const Vec3& to_eye) {
        const FixedRay source({to_eye * 10.0, -to_eye, 0.0, 1.0});
        return solve(rig.tracer, batch_of(source, 2000), 0);
    };
    // The specular direction: the sun mirrored (zenith 40°, azimuth 270°).
    const Solution glint = view(direction_from(sun_zenith, 270.0));
    const Solution off = view(direction_from(sun_zenith + 5.0, 270.0));
    const Solutions many = solve(rig.tracer,
                                 batch_of(FixedRay({direction_from(sun_zenith, 270.0) * 10.0,
                                                    -direction_from(sun_zenith, 270.0), 0.0, 1.0}),
                                          100'000),
                                 Context{});
    for (std::size_t b = 0; b < 3; ++b) {
        const double diffuse = (1.0 - share) * rho * kSun[b] * sun.z / kPi;
        // A mirror draw (probability s, weight ρ) leaves in the one direction, inside the
        // disc: radiance E/Ω. The noise is the lobe choice's.
        const double expected = diffuse + share * rho * kSun[b] / omega_sr;
        EXPECT_NEAR(glint.radiance_w_per_cm2_sr_um[b], expected,
                    kSigmas * glint.standard_error_w_per_cm2_sr_um * kSun[b] / kSun[0])
            << b;
        EXPECT_NEAR(many.radiance(0)[b], expected, kHighCountRelative * expected) << b;
        // Off the specular direction only the diffuse share is left (the sun-disc cosine's
        // spread, ~1e-5, is the only noise).
        EXPECT_NEAR(off.radiance_w_per_cm2_sr_um[b], diffuse, 1e-4 * diffuse) << b;
    }
}

TEST(SurfaceModels, RossLiPlateUnderAUniformSkyReflectsItsAlbedo) {
    const double iso = 0.3;
    const std::vector<double> sky{1.0, 1.0, 1.0};
    model::Scene scene;
    scene.materials.push_back(ross_li_material("canopy", iso, 0.8, 0.2));
    test::add_primitive(scene, ground_plane(), 0);
    Rig rig(std::move(scene), kVisible,
            Environment::uniform(kVisible, {0.0, 0.0, 1.0}, kBlack, sky));
    const RossLiBrdf brdf(0.8, 0.2);
    for (const double view_zenith : {0.0, 50.0}) {
        const Vec3 to_eye = direction_from(view_zenith, 0.0);
        // ∫ f cos θi dωi by the midpoint rule in (cos θi, φ): 1000 × 400 cells.
        double albedo = 0.0;
        for (int i = 0; i < 1000; ++i) {
            const double mu = (i + 0.5) / 1000.0;
            for (int j = 0; j < 400; ++j) {
                const double phi = 2.0 * kPi * (j + 0.5) / 400.0;
                const double s = std::sqrt(1.0 - mu * mu);
                albedo += brdf.eval(to_eye, {s * std::cos(phi), s * std::sin(phi), mu}) * mu;
            }
        }
        albedo *= (1.0 / 1000.0) * (2.0 * kPi / 400.0);
        const FixedRay source({to_eye * 10.0, -to_eye, 0.0, 1.0});
        const Solutions many = solve(rig.tracer, batch_of(source, 100'000), Context{});
        EXPECT_NEAR(many.radiance(0)[1], iso * albedo, kHighCountRelative * iso * albedo)
            << view_zenith;
    }
}

TEST(SurfaceModels, AClearPaneLetsTheSunThroughStraight) {
    // A non-reflecting pane (τ = 0.8, straight) 2 m above a Lambertian ground (ρ_g = 0.4),
    // seen from above: the ground's shadow rays pass the pane (τ), and the view through it
    // (τ again): L = τ² ρ_g E cos θ / π. Without the shadow rays' pass the ground would be dark.
    const double tau = 0.8;
    const double ground = 0.4;
    const double zenith = 30.0;
    model::Scene scene;
    model::Material pane = flat_material("pane", 0.0, 300.0, std::nullopt, {}, tau);
    pane.straight_transmission = true;
    scene.materials.push_back(pane);
    scene.materials.push_back(flat_material("ground", ground));
    model::Primitive sheet = ground_plane(50.0);
    sheet.center_m = {0.0, 0.0, 2.0};
    test::add_primitive(scene, sheet, 0);
    test::add_primitive(scene, ground_plane(), 1);
    Rig rig(std::move(scene), kVisible,
            Environment::uniform(kVisible, direction_from(zenith, 135.0), kSun, kBlack));
    ASSERT_TRUE(rig.materials.any_straight());
    const FixedRay source({{0.0, 0.0, 1000.0}, {0.0, 0.0, -1.0}, 0.0, 1.0});
    const Solution s = solve(rig.tracer, batch_of(source, 2000), 0);
    for (std::size_t b = 0; b < 3; ++b) {
        const double expected = tau * tau * ground * kSun[b] * std::cos(zenith * kPi / 180.0) / kPi;
        // The only noise is the sun-disc cosine's (~1e-5).
        EXPECT_NEAR(s.radiance_w_per_cm2_sr_um[b], expected, 1e-4 * expected)
            << b << " ratio " << s.radiance_w_per_cm2_sr_um[b] / expected;
    }
}

/// A checkerboard of leaf squares (cell `cell_m`, leaves where the cell indices' sum is even:
/// cover fraction 1/2) over `size_m` × `size_m` at height `height_m`, material 0.
model::GeometryObject checkerboard_layer(double cell_m, double size_m, double height_m) {
    model::GeometryObject object;
    object.name = "layer";
    const int n = static_cast<int>(size_m / cell_m);
    const float z = static_cast<float>(height_m);
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            if ((i + j) % 2 != 0) continue;
            const float x0 = static_cast<float>(-size_m / 2 + i * cell_m);
            const float y0 = static_cast<float>(-size_m / 2 + j * cell_m);
            const float x1 = x0 + static_cast<float>(cell_m);
            const float y1 = y0 + static_cast<float>(cell_m);
            const auto v = static_cast<std::uint32_t>(object.mesh.vertices_m.size());
            object.mesh.vertices_m.insert(object.mesh.vertices_m.end(),
                                          {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}});
            object.mesh.triangles.push_back({v, v + 1, v + 2});
            object.mesh.triangles.push_back({v, v + 2, v + 3});
            object.mesh.triangle_materials.insert(object.mesh.triangle_materials.end(), {0, 0});
        }
    }
    return object;
}

/// Nadir rays from 100 m up, their origins uniform over a `side_m` square.
class AreaRays final : public RaySource {
public:
    explicit AreaRays(double side_m) : m_side_m(side_m) {}
    SampleRay generate(std::uint64_t, std::uint64_t, RandomStream& rng) const override {
        const double x = (rng.uniform() - 0.5) * m_side_m;
        const double y = (rng.uniform() - 0.5) * m_side_m;
        return {{x, y, 100.0}, {0.0, 0.0, -1.0}, 0.0, 1.0};
    }

private:
    double m_side_m;
};

TEST(SurfaceModels, ALeafLayerWithGapsReflectsTheTwoStreamSumWithItsGapTerm) {
    // A leaf layer covering c = 1/2 of a Lambertian soil ρ_s (a checkerboard of 0.1 m leaves
    // 2 m up). At the scale of the pixel (10 m) the layer is an effective sheet: it reflects
    // ρ_L = c ρ and passes τ_L = (1 − c) + c τ of the light from either side, whatever the
    // direction (a zero-thickness layer's gap fraction does not depend on the angle), so the
    // system reflects ρ_L + τ_L² ρ_s / (1 − ρ_L ρ_s). The sun's shift across the 2 m gap is
    // 9.5 cells (tan θ = 0.475) — an odd number of half cells, at which the checkerboard's
    // gaps seen by the view and by the sun are independent; diffuse light is spread over
    // many cells. Within 4 standard errors at 2,000 samples, 0.5 % at 200,000.
    const double rho = 0.45;
    const double tau = 0.45;
    const double soil = 0.3;
    const double c = 0.5;
    const double zenith_deg = std::atan(0.475) * 180.0 / kPi;
    model::Scene scene;
    scene.materials.push_back(
        flat_material("leaf", rho, 300.0, std::nullopt, model::SpecularLobe{}, tau));
    scene.materials.push_back(flat_material("soil", soil));
    scene.objects.push_back(checkerboard_layer(0.1, 40.0, 2.0));
    model::Instance layer;
    layer.object_index = 0;
    layer.name = "layer";
    scene.instances.push_back(layer);
    // The default 100 km plane, in 1 km tiles: as two 141 km triangles its spawn offset
    // (~4.5 cm) moved the sun's crossing of the layer by a fifth of a cell here and broke the
    // half-cell independence (docs/scene.md, "Spawn offset").
    test::add_primitive(scene, ground_plane(), 1);
    TracerSettings settings;
    settings.max_bounces = 64;
    Rig rig(std::move(scene), kVisible,
            Environment::uniform(kVisible, direction_from(zenith_deg, 90.0), kSun, kBlack),
            settings);
    const double rho_l = c * rho;
    const double tau_l = (1.0 - c) + c * tau;
    const double system = rho_l + tau_l * tau_l * soil / (1.0 - rho_l * soil);
    const AreaRays source(10.0);
    const Solution few = solve(rig.tracer, batch_of(source, 2000), 0);
    const Solution many = solve(rig.tracer, batch_of(source, 200'000), 0);
    const double expected = system * kSun[1] * std::cos(zenith_deg * kPi / 180.0) / kPi;
    EXPECT_NEAR(few.radiance_w_per_cm2_sr_um[1], expected,
                kSigmas * few.standard_error_w_per_cm2_sr_um * kSun[1] / kSun[0])
        << few.radiance_w_per_cm2_sr_um[1] / expected;
    EXPECT_NEAR(many.radiance_w_per_cm2_sr_um[1], expected, kHighCountRelative * expected)
        << many.radiance_w_per_cm2_sr_um[1] / expected;
}

TEST(SurfaceModels, ALobeThatReflectsMoreThanItReceivesIsRefused) {
    model::Scene scene;
    scene.materials.push_back(ross_li_material("bright", 0.9, 2.0, 0.0));
    try {
        const MaterialTable table(scene.materials, kVisible);
        FAIL() << "accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("material 'bright': its lobe's directional albedo "
                                             "reaches"),
                  std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("above 1 (it would reflect more than it receives)"),
                  std::string::npos);
    }
}

}  // namespace surface_models_test
}  // namespace glint::radiometry
