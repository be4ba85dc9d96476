// SPDX-License-Identifier: Apache-2.0
// The lidar tracer against analytic answers (docs/validation.md, "Lidar"): the pulse shapes'
// cumulative energy, the share of a return each time sample gets, the Gaussian beam's total
// energy, and a receiver ray straight down onto a Lambertian plate whose return is
// ρ/π · I(0)/R² at the delay 2R/c, in the bin that holds it.
#include "glint/radiometry/lidar.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <numeric>
#include <vector>

#include "glint/core/error.h"
#include "tracer_fixture.h"

namespace glint::radiometry {
namespace lidar_test {

using test::add_primitive;
using test::FixedRay;
using test::ground_plane;

TEST(PulseShape, GaussianHoldsHalfItsEnergyBeforeItsCentreAndErfInsideItsFwhm) {
    const PulseShape g = PulseShape::gaussian(5e-9);
    EXPECT_DOUBLE_EQ(g.cumulative(0.0), 0.5);
    // Inside ±FWHM/2: erf(√(ln 2)) = 0.76096…
    EXPECT_NEAR(g.cumulative(2.5e-9) - g.cumulative(-2.5e-9), std::erf(std::sqrt(std::log(2.0))),
                1e-12);
    EXPECT_LT(g.cumulative(g.begin_s()), 1e-8);
    EXPECT_GT(g.cumulative(g.end_s()), 1.0 - 1e-8);
    EXPECT_THROW((void)PulseShape::gaussian(0.0), Error);
}

TEST(PulseShape, TabulatedTriangleIsNormalisedAndIntegratedExactly) {
    // A triangle 0 → 1 → 0 over [0, 2] ns: C(1 ns) = 1/2, C(0.5 ns) = 1/8 (area of the rising
    // edge up to there over the total area 1 ns).
    const PulseShape t = PulseShape::tabulated({0.0, 1e-9, 2e-9}, {0.0, 4.0, 0.0});
    EXPECT_DOUBLE_EQ(t.cumulative(-1.0), 0.0);
    EXPECT_NEAR(t.cumulative(1e-9), 0.5, 1e-15);
    EXPECT_NEAR(t.cumulative(0.5e-9), 0.125, 1e-15);
    EXPECT_NEAR(t.cumulative(1.5e-9), 0.875, 1e-15);
    EXPECT_DOUBLE_EQ(t.cumulative(3e-9), 1.0);
    EXPECT_THROW((void)PulseShape::tabulated({0.0}, {1.0}), Error);
    EXPECT_THROW((void)PulseShape::tabulated({0.0, 0.0}, {1.0, 1.0}), Error);
    EXPECT_THROW((void)PulseShape::tabulated({0.0, 1.0}, {1.0, -1.0}), Error);
    EXPECT_THROW((void)PulseShape::tabulated({0.0, 1.0}, {0.0, 0.0}), Error);
}

TEST(LidarDeposit, EachSampleGetsItsShareOfTheShapeAndNothingIsLostInsideTheGate) {
    const PulseShape box = PulseShape::tabulated({-1e-9, 1e-9}, {1.0, 1.0});  // 2 ns flat
    const TimeGate gate{10e-9, 1e-9, 20};
    std::vector<double> h(gate.samples, 0.0);
    // Centred at 15.5 ns: [14.5, 16.5] ns, half of sample 4, all of 5, half of 6.
    deposit(box, gate, 15.5e-9, 8.0, h);
    EXPECT_NEAR(h[4], 2.0, 1e-12);
    EXPECT_NEAR(h[5], 4.0, 1e-12);
    EXPECT_NEAR(h[6], 2.0, 1e-12);
    EXPECT_NEAR(std::accumulate(h.begin(), h.end(), 0.0), 8.0, 1e-12);
    // Outside the gate: lost, nothing written out of bounds.
    std::vector<double> edge(gate.samples, 0.0);
    deposit(box, gate, 9.5e-9, 1.0, edge);   // [8.5, 10.5] ns: a quarter inside
    deposit(box, gate, 31.0e-9, 1.0, edge);  // [30, 32] ns: after the gate
    deposit(box, gate, 100e-9, 1.0, edge);
    EXPECT_NEAR(edge[0], 0.25, 1e-12);
    EXPECT_NEAR(std::accumulate(edge.begin(), edge.end(), 0.0), 0.25, 1e-12);
}

TEST(LaserPulse, GaussianBeamIntegratesToThePulseEnergy) {
    LaserPulse laser;
    laser.axis = {0.0, 0.0, -1.0};
    laser.divergence_rad = 2e-3;
    laser.energy_j = 0.5;
    // ∫ I dΩ over the cone out to 10 w by the midpoint rule in α (sin α dα dφ).
    const double w = 1e-3;
    const int n = 20000;
    double total = 0.0;
    for (int i = 0; i < n; ++i) {
        const double alpha = (i + 0.5) * 10.0 * w / n;
        const Vec3 d{std::sin(alpha), 0.0, -std::cos(alpha)};
        total +=
            laser.intensity_j_per_sr(d) * 2.0 * std::numbers::pi * std::sin(alpha) * (10.0 * w / n);
    }
    // The small-angle normalisation: sin α ≈ α to 1e-7 relative at α ≤ 10 mrad.
    EXPECT_NEAR(total, 0.5, 0.5 * 1e-6);
    EXPECT_DOUBLE_EQ(laser.intensity_j_per_sr({0.0, 0.0, -1.0}),
                     0.5 * 2.0 / (std::numbers::pi * w * w));
}

/// A 1 mJ pulse fired straight down from `height_m` above the origin.
LaserPulse nadir_laser(double height_m, double divergence_rad) {
    LaserPulse laser;
    laser.position_m = {0.0, 0.0, height_m};
    laser.divergence_rad = divergence_rad;
    laser.energy_j = 1e-3;
    return laser;
}

/// A gate opening 6 µs after the pulse, 1500 samples of 1 ns.
constexpr TimeGate kGate{6e-6, 1e-9, 1500};

struct PlateRig {
    explicit PlateRig(double rho, double height_m = 0.0) {
        scene.materials.push_back(model::flat_material("plate", rho, 300.0));
        add_primitive(scene, ground_plane(), 0);
        if (height_m > 0.0) {
            // A 10 m step east of x = 0.
            add_primitive(scene, test::box({0.0, -50.0, 0.0}, {50.0, 50.0, height_m}), 0);
        }
        trajectories = motion::make_instance_trajectories(scene, motion::SceneFrame(), DateTime{});
        geometry.emplace(scene::GeometryScene::build(scene, trajectories, scene::BuildOptions{}));
        materials.emplace(scene.materials, SpectralGrid({1.064}));
    }
    model::Scene scene;
    std::vector<std::unique_ptr<motion::Trajectory>> trajectories;
    std::optional<scene::GeometryScene> geometry;
    std::optional<MaterialTable> materials;
};

TEST(LidarTracer, NadirReturnFromALambertianPlateIsRhoOverPiTimesIOverRSquaredAt2ROverC) {
    constexpr double kRho = 0.3;
    constexpr double kRange = 1000.0;
    PlateRig rig(kRho);
    const PulseShape shape = PulseShape::gaussian(5e-9);
    const TimeGate gate = kGate;
    const LidarTracer tracer(*rig.geometry, *rig.materials, {}, shape, gate);
    const LaserPulse laser = nadir_laser(kRange, 1e-4);
    std::vector<double> h(gate.samples, 0.0);
    std::uint64_t rays = 0;
    RandomStream rng(1, {2});
    tracer.trace({{0.0, 0.0, kRange}, {0.0, 0.0, -1.0}, 0.0, 1.0}, laser, rng, h, rays);
    // L = ρ/π · I(0) cos 0 / R², J/(cm² sr) (10⁴ cm² per m²); the Gaussian's ±6σ hold all but
    // 2e-9 of it.
    const double expected = kRho / std::numbers::pi * laser.intensity_j_per_sr({0.0, 0.0, -1.0}) /
                            (kRange * kRange * 1e4);
    EXPECT_NEAR(std::accumulate(h.begin(), h.end(), 0.0), expected, 1e-8 * expected);
    const std::size_t peak =
        static_cast<std::size_t>(std::max_element(h.begin(), h.end()) - h.begin());
    const double delay = 2.0 * kRange / kSpeedOfLightMPerS;
    EXPECT_EQ(peak, static_cast<std::size_t>(std::floor((delay - gate.start_s) / 1e-9)));
    EXPECT_EQ(peak, 671u);
    EXPECT_GE(rays, 2u);  // the primary ray and the shadow ray to the laser
}

TEST(LidarTracer, AStepGivesTwoPeaksAtTheTwoRanges) {
    // Receiver rays half on the ground (1000 m), half on a 15 m step (985 m).
    PlateRig rig(0.5, 15.0);
    const PulseShape shape = PulseShape::gaussian(2e-9);
    const LidarTracer tracer(*rig.geometry, *rig.materials, {}, shape, kGate);
    const LaserPulse laser = nadir_laser(1000.0, 1e-3);
    std::vector<double> h(kGate.samples, 0.0);
    std::uint64_t rays = 0;
    for (const double x : {-0.1, 0.1}) {
        RandomStream rng(1, {3});
        const Vec3 d = normalized(Vec3{x, 0.0, -1000.0});
        tracer.trace({laser.position_m, d, 0.0, 1.0}, laser, rng, h, rays);
    }
    auto bin_of = [](double range_m) {
        return static_cast<std::size_t>(
            std::floor((2.0 * range_m / kSpeedOfLightMPerS - 6e-6) / 1e-9));
    };
    // Slant ranges √(1000² + 0.1²) and 985/1000 of it: bins 671 and 571.
    const double slant = std::hypot(1000.0, 0.1);
    const std::size_t ground = bin_of(slant);
    const std::size_t step = bin_of(slant * 0.985);
    EXPECT_EQ(ground, 671u);
    EXPECT_EQ(step, 571u);
    for (std::size_t peak : {ground, step}) {
        EXPECT_GT(h[peak], h[peak - 1]) << peak;
        EXPECT_GT(h[peak], h[peak + 1]) << peak;
    }
    // Between the peaks (far from both by 50 σ): nothing.
    EXPECT_EQ(h[621], 0.0);
}

TEST(LidarTracer, ALeafLayerReturnsItsReflectionFirstAndTheGroundThroughIt) {
    // A thin sheet (ρ = 0.3, τ = 0.5) 5 m above a ρ = 0.4 ground, the laser 1000 m up: the
    // sheet's return at 995 m is the opaque plate's ρ/π · I/R², and light transmitted down,
    // reflected by the ground and lit through the sheet's underside returns later (at 1000 m:
    // 1005 m travelled to the underside, 995 m back); an opaque sheet of the same ρ returns
    // nothing there.
    for (const double tau : {0.5, 0.0}) {
        model::Scene scene;
        scene.materials.push_back(
            model::flat_material("leaf", 0.3, 300.0, std::nullopt, model::SpecularLobe{}, tau));
        scene.materials.push_back(model::flat_material("ground", 0.4, 300.0));
        model::Primitive sheet = ground_plane();
        sheet.center_m = {0.0, 0.0, 5.0};
        add_primitive(scene, sheet, 0);
        add_primitive(scene, ground_plane(), 1);
        const auto trajectories =
            motion::make_instance_trajectories(scene, motion::SceneFrame(), DateTime{});
        const scene::GeometryScene geometry =
            scene::GeometryScene::build(scene, trajectories, scene::BuildOptions{});
        const MaterialTable materials(scene.materials, SpectralGrid({1.064}));
        TracerSettings settings;
        settings.max_bounces = 16;
        // A temporary shape: the tracer keeps a copy.
        const LidarTracer tracer(geometry, materials, settings, PulseShape::gaussian(2e-9), kGate);
        const LaserPulse laser = nadir_laser(1000.0, 1e-3);
        std::vector<double> h(kGate.samples, 0.0);
        std::uint64_t rays = 0;
        constexpr int kRays = 4000;
        for (int i = 0; i < kRays; ++i) {
            RandomStream rng(5, {static_cast<std::uint64_t>(i)});
            tracer.trace({laser.position_m, {0.0, 0.0, -1.0}, 0.0, 1.0 / kRays}, laser, rng, h,
                         rays);
        }
        auto bin_of = [](double range_m) {
            return static_cast<std::size_t>(
                std::floor((2.0 * range_m / kSpeedOfLightMPerS - 6e-6) / 1e-9));
        };
        // The sheet's own return: ±10 ns around 995 m holds the first vertex's whole pulse.
        const std::size_t sheet_bin = bin_of(995.0);
        const double first = std::accumulate(h.begin() + static_cast<long>(sheet_bin - 10),
                                             h.begin() + static_cast<long>(sheet_bin + 10), 0.0);
        const double expected = 0.3 / std::numbers::pi *
                                laser.intensity_j_per_sr({0.0, 0.0, -1.0}) / (995.0 * 995.0 * 1e4);
        EXPECT_NEAR(first, expected, 1e-6 * expected) << "tau " << tau;
        // Beyond 997 m (the sheet's pulse ends within 1 m of 995): only light that went
        // through the sheet and came back.
        const double later =
            std::accumulate(h.begin() + static_cast<long>(bin_of(997.0)), h.end(), 0.0);
        if (tau > 0.0) {
            // Weaker than the sheet's own return: only the ground's light that comes back up
            // within the beam's metre-wide spot meets laser light through the sheet.
            EXPECT_GT(later, 0.0);
            EXPECT_LT(later, 0.1 * expected);
        } else {
            EXPECT_EQ(later, 0.0);
        }
    }
}

TEST(LidarTracer, ReturnsAreTheSameForAnyThreadCount) {
    PlateRig rig(0.4, 15.0);
    const PulseShape shape = PulseShape::gaussian(5e-9);
    const LidarTracer tracer(*rig.geometry, *rig.materials, {}, shape, kGate);
    // Wide: the random receiver directions see it.
    const LaserPulse laser = nadir_laser(1000.0, 1.0);
    test::SphereRays rays(laser.position_m);
    ReturnBatch batch;
    batch.key.seed = 11;
    batch.source = &rays;
    batch.count = 40;
    batch.samples = 25;
    Context one;
    one.threads = 1;
    Context many;
    many.threads = 4;
    const Returns a = solve_returns(tracer, laser, batch, one);
    const Returns b = solve_returns(tracer, laser, batch, many);
    EXPECT_EQ(a.energy_j_per_cm2_sr, b.energy_j_per_cm2_sr);
    EXPECT_EQ(a.rays, b.rays);
    EXPECT_GT(std::accumulate(a.energy_j_per_cm2_sr.begin(), a.energy_j_per_cm2_sr.end(), 0.0),
              0.0);
}

}  // namespace lidar_test
}  // namespace glint::radiometry
