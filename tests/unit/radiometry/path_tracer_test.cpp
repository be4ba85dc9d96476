// SPDX-License-Identifier: Apache-2.0
// Analytic tests of the path tracer (docs/validation.md): a Lambertian plate under an exo-
// atmospheric sun (L = ρ E cos θ / π), a blackbody plate (L = ε B), furnaces (a plate under a
// uniform sky: L = ρ L_sky; a closed isothermal enclosure: L = B(T) whatever its reflectance),
// a shadowed plate, the GGX lobe's albedo, a moving box's motion blur, the atmosphere's
// sensor path, and thin transmitting sheets (a leaf seen from below: L = τ E cos θ / π; a
// leaf layer over soil: ρ + τ² ρ_s / (1 − ρ ρ_s); a leaf in an isothermal enclosure: B(T)).
// Each is checked within k standard errors at a low sample count and within 0.5 % at a high
// one.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "glint/atmosphere/atmosphere.h"
#include "glint/core/error.h"
#include "glint/core/spectral.h"
#include "glint/radiometry/brdf.h"
#include "tracer_fixture.h"

namespace glint::radiometry {
namespace path_tracer_test {

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

/// A camera 1 km above the origin looking straight down.
SampleRay nadir_ray(Vec3 target = {0.0, 0.0, 0.0}) {
    return {target + Vec3{0.0, 0.0, 1000.0}, {0.0, 0.0, -1.0}, 0.0, 1.0};
}

model::Scene plate_scene(double reflectance, double temperature_k = 300.0,
                         model::SpecularLobe specular = {}) {
    model::Scene scene;
    scene.materials.push_back(
        flat_material("plate", reflectance, temperature_k, std::nullopt, specular));
    test::add_primitive(scene, ground_plane(), 0);
    return scene;
}

TEST(PathTracer, LambertianPlateUnderTheSunAtSeveralZenithAngles) {
    for (double zenith : {0.0, 30.0, 60.0, 75.0}) {
        const double rho = 0.35;
        Rig rig(plate_scene(rho), kVisible,
                Environment::uniform(kVisible, direction_from(zenith, 135.0), kSun, kBlack));
        const FixedRay source(nadir_ray());
        const Solution s = solve(rig.tracer, batch_of(source, 2000), 0);
        // The only randomness is the direction inside the sun disk (its cosine spreads by
        // ~α tan θ); the disk's mean cosine differs from cos θ by α²/4 ≈ 5e-6 relative.
        const double relative_error =
            s.standard_error_w_per_cm2_sr_um / s.radiance_w_per_cm2_sr_um[0];
        for (std::size_t b = 0; b < 3; ++b) {
            const double expected = rho * kSun[b] * std::cos(zenith * kPi / 180.0) / kPi;
            EXPECT_NEAR(s.radiance_w_per_cm2_sr_um[b], expected,
                        (kSigmas * relative_error + 1e-5) * expected)
                << "zenith " << zenith << " band " << b;
            EXPECT_NEAR(s.radiance_w_per_cm2_sr_um[b], expected, kHighCountRelative * expected);
        }
    }
}

/// A horizontal square sheet at height `height_m` (a ground plane lifted; two-sided).
model::Primitive sheet_at(double height_m, double size_m = model::kDefaultGroundPlaneSize_m) {
    model::Primitive p = ground_plane(size_m);
    p.center_m = {0.0, 0.0, height_m};
    return p;
}

TEST(PathTracer, ALeafSeenFromBelowTransmitsTheSun) {
    // A sheet (ρ = 0.4, τ = 0.35) and nothing else, seen from below with the sun above: its
    // underside sends τ E cos θ / π down (the sun's next-event estimate through the sheet).
    for (double zenith : {0.0, 50.0}) {
        model::Scene scene;
        scene.materials.push_back(
            flat_material("leaf", 0.4, 300.0, std::nullopt, model::SpecularLobe{}, 0.35));
        test::add_primitive(scene, sheet_at(0.0), 0);
        Rig rig(std::move(scene), kVisible,
                Environment::uniform(kVisible, direction_from(zenith, 20.0), kSun, kBlack));
        const FixedRay source({{0.0, 0.0, -1000.0}, {0.0, 0.0, 1.0}, 0.0, 1.0});
        const Solution s = solve(rig.tracer, batch_of(source, 2000), 0);
        // As the front-lit plate: the only randomness is the direction inside the sun disk.
        const double relative_error =
            s.standard_error_w_per_cm2_sr_um / s.radiance_w_per_cm2_sr_um[0];
        for (std::size_t b = 0; b < 3; ++b) {
            const double expected = 0.35 * kSun[b] * std::cos(zenith * kPi / 180.0) / kPi;
            EXPECT_NEAR(s.radiance_w_per_cm2_sr_um[b], expected,
                        (kSigmas * relative_error + 1e-5) * expected)
                << "zenith " << zenith << " band " << b;
        }
    }
}

TEST(PathTracer, ALeafLayerOverSoilReflectsTheTwoStreamSum) {
    // A horizontal leaf layer (Lambertian ρ, τ) fully covering a Lambertian soil ρ_s: the
    // fluxes between them sum to a reflectance ρ + τ² ρ_s / (1 − ρ ρ_s), so L = that · E cos θ
    // / π above the layer. The soil sees the sun only through the leaf's transmitted
    // next-event estimate at the layer's underside.
    const double rho = 0.45;
    const double tau = 0.45;
    const double soil = 0.3;
    const double zenith = 30.0;
    model::Scene scene;
    scene.materials.push_back(
        flat_material("leaf", rho, 300.0, std::nullopt, model::SpecularLobe{}, tau));
    scene.materials.push_back(flat_material("soil", soil));
    test::add_primitive(scene, sheet_at(1.0), 0);
    test::add_primitive(scene, ground_plane(), 1);
    TracerSettings settings;
    settings.max_bounces = 64;  // the series ρ ρ_s per round trip: 0.135^32 is nothing
    Rig rig(std::move(scene), kVisible,
            Environment::uniform(kVisible, direction_from(zenith, 135.0), kSun, kBlack), settings);
    const FixedRay source(nadir_ray());
    const double system = rho + tau * tau * soil / (1.0 - rho * soil);

    const Solution few = solve(rig.tracer, batch_of(source, 2000), 0);
    const double expected_1 = system * kSun[1] * std::cos(zenith * kPi / 180.0) / kPi;
    EXPECT_NEAR(few.radiance_w_per_cm2_sr_um[1], expected_1,
                kSigmas * few.standard_error_w_per_cm2_sr_um);
    EXPECT_GT(few.standard_error_w_per_cm2_sr_um, 0.0);

    const Solution many = solve(rig.tracer, batch_of(source, 200'000), 0);
    for (std::size_t b = 0; b < 3; ++b) {
        const double expected = system * kSun[b] * std::cos(zenith * kPi / 180.0) / kPi;
        EXPECT_NEAR(many.radiance_w_per_cm2_sr_um[b], expected, kHighCountRelative * expected) << b;
    }
}

TEST(PathTracer, BlackbodyPlate) {
    const SpectralGrid thermal({8.0, 10.0, 12.0});
    model::Scene scene;
    scene.materials.push_back(flat_material("hot", 0.1, 320.0, 0.9));
    test::add_primitive(scene, ground_plane(), 0);
    Rig rig(std::move(scene), thermal,
            Environment::uniform(thermal, {0.0, 0.0, 1.0}, kBlack, kBlack));
    const FixedRay source(nadir_ray());
    const Solution s = solve(rig.tracer, batch_of(source, 16), 0);
    for (std::size_t b = 0; b < 3; ++b) {
        const double expected =
            0.9 * planck_radiance_w_per_cm2_sr_um(thermal.wavelength_um(b), 320.0);
        EXPECT_NEAR(s.radiance_w_per_cm2_sr_um[b], expected, 1e-12 * expected);
    }
}

TEST(PathTracer, ASingleSidedPlatesBackFaceIsBlack) {
    // A hot plate (ε = 0.9, 320 K) whose front faces up: seen from above it radiates ε B; seen
    // from below only when it is double-sided (DOUBLE_SIDED = FALSE makes the back black).
    const SpectralGrid thermal({8.0, 10.0, 12.0});
    for (const bool double_sided : {true, false}) {
        model::Scene scene;
        scene.materials.push_back(flat_material("hot", 0.1, 320.0, 0.9));
        scene.materials.back().double_sided = double_sided;
        test::add_primitive(scene, ground_plane(), 0);
        Rig rig(std::move(scene), thermal,
                Environment::uniform(thermal, {0.0, 0.0, 1.0}, kBlack, kBlack));
        const FixedRay above(nadir_ray());
        const FixedRay below({{0.0, 0.0, -1000.0}, {0.0, 0.0, 1.0}, 0.0, 1.0});
        const Solution front = solve(rig.tracer, batch_of(above, 16), 0);
        const Solution back = solve(rig.tracer, batch_of(below, 16), 0);
        for (std::size_t b = 0; b < 3; ++b) {
            const double expected =
                0.9 * planck_radiance_w_per_cm2_sr_um(thermal.wavelength_um(b), 320.0);
            EXPECT_NEAR(front.radiance_w_per_cm2_sr_um[b], expected, 1e-12 * expected) << b;
            EXPECT_NEAR(back.radiance_w_per_cm2_sr_um[b], double_sided ? expected : 0.0,
                        1e-12 * expected)
                << b << " double-sided " << double_sided;
        }
    }
}

TEST(PathTracer, FurnacePlateUnderAUniformSky) {
    const std::vector<double> sky{0.01, 0.02, 0.03};
    const double rho = 0.7;
    Rig rig(plate_scene(rho), kVisible,
            Environment::uniform(kVisible, {0.0, 0.0, 1.0}, kBlack, sky));
    const FixedRay source({{0.0, 0.0, 10.0}, normalized(Vec3{0.3, 0.1, -1.0}), 0.0, 1.0});
    const Solution s = solve(rig.tracer, batch_of(source, 4000), 0);
    for (std::size_t b = 0; b < 3; ++b) {
        // Every bounce ray leaves a 100 km plate seen from its centre: L = ρ L_sky exactly
        // but for the rays that graze past the edge (solid angle < 1e-7 of the hemisphere).
        EXPECT_NEAR(s.radiance_w_per_cm2_sr_um[b], rho * sky[b], 1e-6 * sky[b]) << b;
    }
}

TEST(PathTracer, FurnaceIsothermalEnclosureRadiatesAsABlackbody) {
    // Kirchhoff: inside a closed opaque enclosure at one temperature the radiance is B(T)
    // whatever the walls' reflectance; it takes ~1/(1 − ρ) bounces to build up.
    const SpectralGrid thermal({8.0, 10.0, 12.0});
    const double t_k = 300.0;
    model::Scene scene;
    scene.materials.push_back(flat_material("wall", 0.6, t_k));
    test::add_primitive(scene, box({-5.0, -4.0, -3.0}, {5.0, 4.0, 3.0}), 0);
    TracerSettings settings;
    settings.max_bounces = 10'000;
    Rig rig(std::move(scene), thermal,
            Environment::uniform(thermal, {0.0, 0.0, 1.0}, {0, 0, 0}, {0, 0, 0}), settings);
    const test::SphereRays source({0.5, -0.3, 0.2});

    ProblemBatch low = batch_of(source, 2000);
    const Solution few = solve(rig.tracer, low, 0);
    const std::size_t ref = 1;
    const double b_ref = planck_radiance_w_per_cm2_sr_um(thermal.wavelength_um(ref), t_k);
    EXPECT_NEAR(few.radiance_w_per_cm2_sr_um[ref], b_ref,
                kSigmas * few.standard_error_w_per_cm2_sr_um);
    EXPECT_GT(few.standard_error_w_per_cm2_sr_um, 0.0);

    Context context;
    ProblemBatch high = batch_of(source, 100'000);
    const Solutions many = solve(rig.tracer, high, context);
    for (std::size_t b = 0; b < 3; ++b) {
        const double expected = planck_radiance_w_per_cm2_sr_um(thermal.wavelength_um(b), t_k);
        EXPECT_NEAR(many.radiance(0)[b], expected, kHighCountRelative * expected) << b;
    }
}

TEST(PathTracer, AnIsothermalEnclosureWithALeafInsideRadiatesAsABlackbody) {
    // Kirchhoff for a sheet: a leaf (ρ = 0.3, τ = 0.5, so ε = 0.2) hung inside a closed
    // enclosure at its temperature leaves the radiance B(T) everywhere, seen through the leaf
    // or off it.
    const SpectralGrid thermal({8.0, 10.0, 12.0});
    const double t_k = 300.0;
    model::Scene scene;
    scene.materials.push_back(flat_material("wall", 0.6, t_k));
    scene.materials.push_back(
        flat_material("leaf", 0.3, t_k, std::nullopt, model::SpecularLobe{}, 0.5));
    test::add_primitive(scene, box({-5.0, -4.0, -3.0}, {5.0, 4.0, 3.0}), 0);
    test::add_primitive(scene, sheet_at(0.0, 4.0), 1);
    TracerSettings settings;
    settings.max_bounces = 10'000;
    Rig rig(std::move(scene), thermal,
            Environment::uniform(thermal, {0.0, 0.0, 1.0}, {0, 0, 0}, {0, 0, 0}), settings);
    const test::SphereRays source({0.5, -0.3, 1.0});
    Context context;
    const Solutions many = solve(rig.tracer, batch_of(source, 100'000), context);
    for (std::size_t b = 0; b < 3; ++b) {
        const double expected = planck_radiance_w_per_cm2_sr_um(thermal.wavelength_um(b), t_k);
        EXPECT_NEAR(many.radiance(0)[b], expected, kHighCountRelative * expected) << b;
    }
}

TEST(PathTracer, ShadowedPlate) {
    const double rho = 0.5;
    model::Scene scene = plate_scene(rho);
    scene.materials.push_back(flat_material("black", 0.0));
    // A black 20 m square slab 10 m up (black, so no light bounces off its underside); with the sun
    // at 30° from the south its shadow is centred 10 tan 30° = 5.77 m north of the origin.
    test::add_primitive(scene, box({-10.0, -10.0, 10.0}, {10.0, 10.0, 11.0}), 1);
    const Vec3 sun = direction_from(30.0, 180.0);
    Rig rig(std::move(scene), kVisible, Environment::uniform(kVisible, sun, kSun, kBlack));
    // Look from the side, under the slab.
    const Vec3 eye{100.0, 5.77, 5.0};
    const auto look_at = [&](Vec3 target) {
        return FixedRay({eye, normalized(target - eye), 0.0, 1.0});
    };
    const FixedRay shadowed = look_at({0.0, 5.77, 0.0});
    const Solution dark = solve(rig.tracer, batch_of(shadowed, 500), 0);
    // Only the black materials' 300 K emission (< 1e-26 W/(cm² sr µm) below 0.7 µm) is left.
    for (double v : dark.radiance_w_per_cm2_sr_um) EXPECT_NEAR(v, 0.0, 1e-20);

    const FixedRay lit = look_at({40.0, 5.77, 0.0});
    const Solution bright = solve(rig.tracer, batch_of(lit, 500), 0);
    const double relative_error =
        bright.standard_error_w_per_cm2_sr_um / bright.radiance_w_per_cm2_sr_um[0];
    for (std::size_t b = 0; b < 3; ++b) {
        const double expected = rho * kSun[b] * std::cos(kPi / 6.0) / kPi;
        EXPECT_NEAR(bright.radiance_w_per_cm2_sr_um[b], expected,
                    (kSigmas * relative_error + 1e-5) * expected);
    }
}

/// ∫ f_GGX cos θi dωi by a midpoint rule in (cos θi, φ) (the reference for the lobe albedo).
double ggx_albedo(double alpha, const Vec3& wo) {
    const GgxBrdf ggx(alpha);
    const int n_mu = 2000;
    const int n_phi = 800;
    double sum = 0.0;
    for (int i = 0; i < n_mu; ++i) {
        const double mu = (i + 0.5) / n_mu;
        const double sin_t = std::sqrt(1.0 - mu * mu);
        for (int j = 0; j < n_phi; ++j) {
            const double phi = 2.0 * kPi * (j + 0.5) / n_phi;
            const Vec3 wi{sin_t * std::cos(phi), sin_t * std::sin(phi), mu};
            sum += ggx.eval(wo, wi) * mu;
        }
    }
    return sum * (1.0 / n_mu) * (2.0 * kPi / n_phi);
}

TEST(PathTracer, SpecularLobeAlbedoUnderAUniformSky) {
    const double rho = 0.8;
    const double roughness = 0.6;
    const std::vector<double> sky{1.0, 1.0, 1.0};
    Rig rig(plate_scene(rho, 300.0, {1.0, roughness}), kVisible,
            Environment::uniform(kVisible, {0.0, 0.0, 1.0}, kBlack, sky));
    const double view_zenith = 40.0;
    const Vec3 to_eye = direction_from(view_zenith, 0.0);
    const FixedRay source({to_eye * 10.0, -to_eye, 0.0, 1.0});
    const double expected =
        rho * ggx_albedo(roughness * roughness, {std::sin(view_zenith * kPi / 180.0), 0.0,
                                                 std::cos(view_zenith * kPi / 180.0)});
    ASSERT_LT(expected, rho);  // single-scattering GGX loses energy: the bound is strict

    const Solution few = solve(rig.tracer, batch_of(source, 1000), 0);
    EXPECT_NEAR(few.radiance_w_per_cm2_sr_um[1], expected,
                kSigmas * few.standard_error_w_per_cm2_sr_um);
    const Solutions many = solve(rig.tracer, batch_of(source, 200'000), Context{});
    EXPECT_NEAR(many.radiance(0)[1], expected, kHighCountRelative * expected);
    EXPECT_LE(many.radiance(0)[1], rho);
}

TEST(PathTracer, MovingBoxMotionBlurMatchesTheCoveredFraction) {
    // A black 2 m box slides along +x from centre x = −4 m at t = 0 to +6 m at t = 1 s over a
    // white plate lit from the zenith; the nadir point x = 0 is covered for t in [0.3, 0.5],
    // so the window-averaged radiance is (1 − 0.2) ρ E / π.
    model::Scene scene;
    scene.materials.push_back(flat_material("white", 1.0));
    scene.materials.push_back(flat_material("black", 0.0));
    test::add_primitive(scene, ground_plane(), 0);
    model::GenericMotion motion;
    motion.entries.resize(2);
    motion.entries[0].time_s = 0.0;
    motion.entries[0].location.xyz_m = {-4.0, 0.0, 0.0};
    motion.entries[1].time_s = 1.0;
    motion.entries[1].location.xyz_m = {6.0, 0.0, 0.0};
    model::PlatformMotion platform_motion;
    platform_motion.file = "slide.ppd";
    platform_motion.generic = motion;
    test::add_primitive(scene, box({-1.0, -1.0, 0.0}, {1.0, 1.0, 1.0}), 1, platform_motion);
    Rig rig(std::move(scene), kVisible,
            Environment::uniform(kVisible, {0.0, 0.0, 1.0}, kSun, kBlack), {},
            scene::TimeWindow{0.0, 1.0});
    const test::WindowRays source(nadir_ray(), 0.0, 1.0);
    const double covered = 0.2;

    const Solution few = solve(rig.tracer, batch_of(source, 2000), 0);
    const double expected = (1.0 - covered) * kSun[1] / kPi;
    EXPECT_NEAR(few.radiance_w_per_cm2_sr_um[1], expected,
                kSigmas * few.standard_error_w_per_cm2_sr_um);
    const Solutions many = solve(rig.tracer, batch_of(source, 200'000), Context{});
    EXPECT_NEAR(many.radiance(0)[1], expected, kHighCountRelative * expected);
}

/// The default parametric atmosphere on `grid`: sun at zenith 40°, azimuth 160°, a sensor at
/// 3000 m, a made-up solar spectrum; the isotropic sky (a Lambertian plate reflects it
/// exactly with every draw; directional_sky_test.cpp tests the directional one).
Environment parametric_environment(const SpectralGrid& grid) {
    model::ParametricAtmosphere parameters;
    parameters.gas_absorption = false;  // scattering only: the gases have their own tests
    parameters.directional_sky = false;
    const glint::atmosphere::ParametricAtmosphereModel atmosphere(parameters);
    const glint::atmosphere::SolarSpectrum sun(SpectralCurve({0.3, 1.0, 4.0}, {0.2, 0.1, 0.001}));
    EnvironmentInputs inputs;
    inputs.sun_direction_begin = inputs.sun_direction_end = direction_from(40.0, 160.0);
    inputs.sensor_altitude_m = 3000.0;
    return Environment::make(grid, atmosphere, sun, inputs);
}

TEST(PathTracer, AtmosphereSensorPathAndSkyOnAPlate) {
    // With the parametric atmosphere the plate's at-aperture radiance is
    // T_v (ρ (E_sun cos θs / π + L_sky)) + L_p, every term taken from the environment.
    const SpectralGrid grid({0.45, 0.55, 0.65, 0.85});
    const double rho = 0.3;
    const Environment env = parametric_environment(grid);
    ASSERT_TRUE(env.has_sensor_path());
    Rig rig(plate_scene(rho), grid, env);
    const FixedRay source(nadir_ray());
    const Solutions many = solve(rig.tracer, batch_of(source, 20'000), Context{});

    std::vector<double> t_v(grid.size()), l_p(grid.size());
    rig.environment.sensor_path({0.0, 0.0, 1.0}, 0.0, t_v, l_p);
    for (std::size_t b = 0; b < grid.size(); ++b) {
        const double surface = rho * (rig.environment.sun_irradiance_w_per_cm2_um()[b] *
                                          std::cos(40.0 * kPi / 180.0) / kPi +
                                      rig.environment.sky_radiance_w_per_cm2_sr_um()[b]);
        const double expected = t_v[b] * surface + l_p[b];
        EXPECT_NEAR(many.radiance(0)[b], expected, 1e-4 * expected) << b;
        EXPECT_LT(t_v[b], 1.0);
        EXPECT_GT(l_p[b], 0.0);
    }
}

TEST(PathTracer, ABandRangeTracesExactlyThoseBandsOfTheWholeGrid) {
    // Split channels trace a channel's bands alone. Without Russian roulette (the only place
    // the bands meet) a range's radiance is the whole grid's on those bands, sample by sample,
    // through the sun, emission, bounces between a box and the plate, the sky and the sensor
    // path.
    const SpectralGrid grid({0.45, 0.55, 0.65, 0.85});
    model::Scene scene = plate_scene(0.3);
    scene.materials.push_back(flat_material("warm box", 0.5, 330.0, 0.4));
    test::add_primitive(scene, box({-1.0, -1.0, 0.0}, {1.0, 1.0, 1.5}), 1);
    TracerSettings settings;
    settings.roulette_start_bounce = 1'000;
    Rig rig(std::move(scene), grid, parametric_environment(grid), settings);
    const BandRange range{1, 2};
    const PathTracer part(rig.geometry, rig.materials, rig.environment, settings, range);
    EXPECT_EQ(part.bands(), 2u);

    const test::SphereRays source({1.8, -0.4, 0.7});
    PathScratch scratch(grid.size());
    std::vector<double> whole(grid.size()), only(range.count);
    double seen = 0.0;
    for (std::uint64_t n = 0; n < 500; ++n) {
        RandomStream a(11, {n});
        RandomStream b(11, {n});
        rig.tracer.trace(source.generate(0, n, a), a, scratch, whole);
        part.trace(source.generate(0, n, b), b, scratch, only);
        for (std::size_t i = 0; i < range.count; ++i) {
            EXPECT_EQ(only[i], whole[range.first + i]) << "sample " << n << " band " << i;
        }
        seen += whole[1];
    }
    EXPECT_GT(seen, 0.0);

    for (const BandRange bad : {BandRange{0, 0}, BandRange{3, 2}, BandRange{5, 1}}) {
        try {
            const PathTracer wrong(rig.geometry, rig.materials, rig.environment, settings, bad);
            FAIL() << "expected a usage error for " << bad.first << " + " << bad.count;
        } catch (const Error& e) {
            EXPECT_EQ(e.category(), ErrorCategory::usage);
            EXPECT_NE(e.message().find("does not fit 4 bands"), std::string::npos) << e.message();
        }
    }
}

}  // namespace path_tracer_test
}  // namespace glint::radiometry
