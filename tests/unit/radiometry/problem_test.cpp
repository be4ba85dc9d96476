// SPDX-License-Identifier: Apache-2.0
// The problem API: convergence rule, standard error, weights, bit-identical results for any
// thread count and run, bad-input errors; and the material table and environment the
// tracer reads.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>
#include <set>
#include <utility>

#include "glint/atmosphere/atmosphere.h"
#include "glint/core/cancel.h"
#include "glint/core/error.h"
#include "glint/core/spectral.h"
#include "glint/io/input_files.h"
#include "glint/test/gas_table.h"
#include "tracer_fixture.h"

namespace glint::radiometry {
namespace problem_test {

using test::batch_of;
using test::direction_from;
using test::FixedRay;
using test::flat_material;
using test::ground_plane;
using test::Rig;
using ::testing::HasSubstr;

using glint::test::gas_table;

const SpectralGrid kGrid({0.45, 0.55, 0.65});
const std::vector<double> kSun{0.20, 0.19, 0.16};
const std::vector<double> kSky{0.01, 0.012, 0.008};

/// A plate with a box on it under sun and sky: paths of several bounces and shadows.
model::Scene busy_scene() {
    model::Scene scene;
    scene.materials.push_back(flat_material("grey", 0.4, 300.0, std::nullopt, {0.3, 0.4}));
    scene.materials.push_back(flat_material("white", 0.9));
    test::add_primitive(scene, ground_plane(), 0);
    test::add_primitive(scene, test::box({-3.0, -3.0, 0.0}, {3.0, 3.0, 4.0}), 1);
    return scene;
}

/// A small pinhole camera: problem p is pixel (p % 8, p / 8) of an 8 × 8 image over the box.
class Pinhole final : public RaySource {
public:
    SampleRay generate(std::uint64_t problem, std::uint64_t, RandomStream& rng) const override {
        const double x = (static_cast<double>(problem % 8) + rng.uniform()) / 8.0 - 0.5;
        const double y = (static_cast<double>(problem / 8) + rng.uniform()) / 8.0 - 0.5;
        return {{0.0, -30.0, 40.0}, normalized(Vec3{x * 0.6, 0.6 + y * 0.6, -0.8}), 0.0, 1.0};
    }
};

Rig busy_rig() {
    return Rig(busy_scene(), kGrid,
               Environment::uniform(kGrid, direction_from(35.0, 200.0), kSun, kSky));
}

std::vector<unsigned char> bytes_of(const Solutions& s) {
    std::vector<unsigned char> out(s.radiance_w_per_cm2_sr_um.size() * sizeof(double) +
                                   s.samples.size() * sizeof(std::uint64_t));
    std::memcpy(out.data(), s.radiance_w_per_cm2_sr_um.data(),
                s.radiance_w_per_cm2_sr_um.size() * sizeof(double));
    std::memcpy(out.data() + s.radiance_w_per_cm2_sr_um.size() * sizeof(double), s.samples.data(),
                s.samples.size() * sizeof(std::uint64_t));
    return out;
}

TEST(Solve, IdenticalBytesForOneAndTwoThreadsAndTwoRuns) {
    Rig rig = busy_rig();
    const Pinhole source;
    ProblemBatch batch = batch_of(source, 64, 64);
    batch.convergence = {4, 256, 1e-4};
    Context one;
    one.threads = 1;
    Context two;
    two.threads = 2;
    const Solutions a = solve(rig.tracer, batch, one);
    const Solutions b = solve(rig.tracer, batch, two);
    const Solutions c = solve(rig.tracer, batch, two);
    EXPECT_EQ(bytes_of(a), bytes_of(b));
    EXPECT_EQ(bytes_of(b), bytes_of(c));
    EXPECT_EQ(a.rays, b.rays);
    EXPECT_GT(a.rays, 64u * 4u);
    // The single-problem solve is the same computation.
    const Solution p17 = solve(rig.tracer, batch, 17);
    for (std::size_t band = 0; band < 3; ++band) {
        EXPECT_EQ(p17.radiance_w_per_cm2_sr_um[band], a.radiance(17)[band]);
    }
    EXPECT_EQ(p17.samples, a.samples[17]);
    // Another seed gives other numbers.
    batch.key.seed = 8;
    EXPECT_NE(bytes_of(solve(rig.tracer, batch, two)), bytes_of(a));
}

TEST(Solve, EqualsTracingEachSampleAloneFromItsStream) {
    // solve() traces the samples of 16 problems side by side, their camera rays as one Embree
    // packet; each problem must still be, bit for bit, its samples traced one by one from
    // sample_stream() (problem.h's promise). 37 problems: two whole groups and a part; the
    // threshold makes the problems of a group stop after different sample counts.
    Rig rig = busy_rig();
    const Pinhole source;
    ProblemBatch batch = batch_of(source, 5, 37);
    batch.convergence = {2, 40, 5e-4};
    batch.first_problem = 5;
    const Solutions s = solve(rig.tracer, batch, Context{});
    PathScratch scratch(3);
    std::vector<double> radiance(3);
    std::set<std::uint64_t> counts;
    for (std::uint64_t i = 0; i < 37; ++i) {
        const std::uint64_t problem = batch.first_problem + i;
        std::vector<double> sum(3, 0.0);
        double weight_sum = 0.0;
        for (std::uint64_t n = 0; n < s.samples[i]; ++n) {
            RandomStream rng = sample_stream(batch.key, problem, n);
            const SampleRay ray = source.generate(problem, n, rng);
            rig.tracer.trace(ray, rng, scratch, radiance);
            for (std::size_t b = 0; b < 3; ++b) sum[b] += ray.weight * radiance[b];
            weight_sum += ray.weight;
        }
        for (std::size_t b = 0; b < 3; ++b) {
            EXPECT_EQ(s.radiance(i)[b], sum[b] / weight_sum) << i << " " << b;
        }
        counts.insert(s.samples[i]);
    }
    EXPECT_GT(counts.size(), 3u);  // the group's problems stopped at different sample counts
}

TEST(Solve, ConvergenceStopsWhenTheMeanSettles) {
    Rig rig = busy_rig();
    const Pinhole source;
    ProblemBatch batch = batch_of(source, 1, 64);
    batch.reference_band = 1;
    batch.convergence = {8, 4096, 2e-4};
    const Solutions s = solve(rig.tracer, batch, Context{});
    for (std::size_t i = 0; i < 64; ++i) {
        EXPECT_GE(s.samples[i], 8u);
        EXPECT_LE(s.samples[i], 4096u);
    }
    // A tighter threshold needs at least as many samples on average.
    batch.convergence.threshold_w_per_cm2_sr_um = 2e-5;
    const Solutions tight = solve(rig.tracer, batch, Context{});
    double loose_total = 0.0;
    double tight_total = 0.0;
    for (std::size_t i = 0; i < 64; ++i) {
        loose_total += static_cast<double>(s.samples[i]);
        tight_total += static_cast<double>(tight.samples[i]);
    }
    EXPECT_GT(tight_total, loose_total);
    // Threshold 0: always the maximum.
    batch.convergence = {1, 33, 0.0};
    for (std::uint64_t n : solve(rig.tracer, batch, Context{}).samples) EXPECT_EQ(n, 33u);
}

TEST(Solve, ConstantRadianceConvergesAtTheMinimumWithZeroError) {
    // A black-sky plate seen at nadir under a zenith sun: every sample is ρ E / π up to the
    // sun disk's cosine spread (< 1e-5 relative), far below the threshold.
    model::Scene scene;
    scene.materials.push_back(flat_material("plate", 0.5));
    test::add_primitive(scene, ground_plane(), 0);
    Rig rig(std::move(scene), kGrid,
            Environment::uniform(kGrid, {0.0, 0.0, 1.0}, kSun, {0.0, 0.0, 0.0}));
    const FixedRay source({{0.0, 0.0, 100.0}, {0.0, 0.0, -1.0}, 0.0, 1.0});
    ProblemBatch batch = batch_of(source, 1);
    batch.convergence = {5, 1000, 1e-6};
    const Solution s = solve(rig.tracer, batch, 0);
    EXPECT_EQ(s.samples, 5u);
    EXPECT_LT(s.standard_error_w_per_cm2_sr_um, 1e-7);
}

TEST(Solve, StandardErrorMatchesTheSpreadOfIndependentEstimates) {
    Rig rig = busy_rig();
    const Pinhole source;
    ProblemBatch batch = batch_of(source, 64, 1);
    batch.first_problem = 27;  // a pixel with the box's edge and shadow in it
    batch.reference_band = 1;
    // 200 independent 64-sample estimates (different seeds): their spread must match the
    // reported standard error within the sampling error of a standard deviation (~5 % for
    // 200 estimates; 25 % allows for the heavy tails of path-traced samples).
    double sum = 0.0;
    double sum_sq = 0.0;
    double reported = 0.0;
    const int runs = 200;
    for (int r = 0; r < runs; ++r) {
        batch.key.seed = 1000 + static_cast<std::uint64_t>(r);
        const Solution s = solve(rig.tracer, batch, 27);
        sum += s.radiance_w_per_cm2_sr_um[1];
        sum_sq += s.radiance_w_per_cm2_sr_um[1] * s.radiance_w_per_cm2_sr_um[1];
        reported += s.standard_error_w_per_cm2_sr_um;
    }
    const double mean = sum / runs;
    const double spread = std::sqrt((sum_sq / runs - mean * mean) * runs / (runs - 1));
    ASSERT_GT(spread, 0.0);
    EXPECT_NEAR(reported / runs, spread, 0.25 * spread);
}

TEST(Solve, WeightsAverageTheSamples) {
    // Two alternating rays, one on a black and one on a white plate, weighted 1 and 3.
    model::Scene scene;
    scene.materials.push_back(flat_material("white", 1.0));
    scene.materials.push_back(flat_material("black", 0.0));
    test::add_primitive(scene, test::box({-100.0, -100.0, -1.0}, {0.0, 100.0, 0.0}), 0);
    test::add_primitive(scene, test::box({0.0, -100.0, -1.0}, {100.0, 100.0, 0.0}), 1);
    Rig rig(std::move(scene), kGrid,
            Environment::uniform(kGrid, {0.0, 0.0, 1.0}, kSun, {0.0, 0.0, 0.0}));
    class Alternating final : public RaySource {
    public:
        SampleRay generate(std::uint64_t, std::uint64_t sample, RandomStream&) const override {
            const bool white = sample % 2 == 0;
            return {{white ? -50.0 : 50.0, 0.0, 10.0}, {0.0, 0.0, -1.0}, 0.0, white ? 1.0 : 3.0};
        }
    } source;
    const Solution s = solve(rig.tracer, batch_of(source, 100), 0);
    EXPECT_NEAR(s.radiance_w_per_cm2_sr_um[0], 0.25 * kSun[0] / kPi, 1e-5 * kSun[0]);
}

TEST(Solve, BadProblemsAreRefused) {
    Rig rig = busy_rig();
    const Pinhole source;
    ProblemBatch batch = batch_of(source, 4);
    batch.convergence = {0, 4, 0.0};
    try {
        solve(rig.tracer, batch, 0);
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::usage);
        EXPECT_EQ(e.message(), "the minimum sample count must be at least 1");
    }
    batch.convergence = {5, 4, 0.0};
    EXPECT_THROW(solve(rig.tracer, batch, 0), Error);
    batch.convergence = {1, 4, 0.0};
    batch.reference_band = 3;
    EXPECT_THROW(solve(rig.tracer, batch, 0), Error);
    batch.reference_band = 0;
    batch.source = nullptr;
    EXPECT_THROW(solve(rig.tracer, batch, Context{}), Error);

    const FixedRay weightless({{0.0, 0.0, 10.0}, {0.0, 0.0, -1.0}, 0.0, 0.0});
    try {
        solve(rig.tracer, batch_of(weightless, 4), 0);
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_THAT(e.message(), HasSubstr("sample 0 of problem 0 has weight 0"));
    }
}

TEST(Solve, CancellationStopsTheBatch) {
    Rig rig = busy_rig();
    const Pinhole source;
    Context context;
    context.cancel.cancel();
    try {
        solve(rig.tracer, batch_of(source, 16, 64), context);
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::cancelled);
    }
}

/// The Pinhole that raises `cancel` at its `cancel_at`-th ray and refuses to go past
/// `give_up_at` rays (so a solve that ignores the flag fails instead of running for hours).
class CancellingPinhole final : public RaySource {
public:
    CancellingPinhole(CancelToken cancel, std::uint64_t cancel_at, std::uint64_t give_up_at)
        : m_cancel(std::move(cancel)), m_cancel_at(cancel_at), m_give_up_at(give_up_at) {}
    SampleRay generate(std::uint64_t problem, std::uint64_t sample,
                       RandomStream& rng) const override {
        const std::uint64_t n = ++m_rays;
        if (n == m_cancel_at) m_cancel.cancel();
        if (n > m_give_up_at) throw Error(ErrorCategory::internal, "the solve ignored the stop");
        return m_pinhole.generate(problem, sample, rng);
    }
    std::uint64_t rays() const { return m_rays.load(); }

private:
    Pinhole m_pinhole;
    CancelToken m_cancel;
    std::uint64_t m_cancel_at;
    std::uint64_t m_give_up_at;
    mutable std::atomic<std::uint64_t> m_rays{0};
};

TEST(Solve, CancellationStopsWithinAGroupOfLongProblems) {
    // 16 problems of 10⁹ samples each: one group of lanes. The stop raised at the 100th ray
    // must end the solve within the round under way (at most 16 more rays), not after the
    // group converges (a SIGINT must not wait for 16 long pixels).
    Rig rig = busy_rig();
    Context context;
    context.threads = 1;
    const CancellingPinhole source(context.cancel, 100, 10000);
    try {
        solve(rig.tracer, batch_of(source, 1000000000, 16), context);
        FAIL() << "not cancelled";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::cancelled) << e.what();
    }
    EXPECT_LE(source.rays(), 100u + 16u);
}

TEST(Solve, HypersampledProblemsTakeMoreSamples) {
    Rig rig = busy_rig();
    const Pinhole source;
    ProblemBatch batch = batch_of(source, 3, 4);
    batch.first_problem = 10;
    const std::vector<std::uint8_t> mask{0, 1, 0, 1};  // problems 11 and 13
    batch.hypersampled = mask;
    batch.hypersampling_multiplier = 2.5;  // 3 × 2.5 = 7.5 → 8
    const Solutions s = solve(rig.tracer, batch, Context{});
    EXPECT_EQ(s.samples, (std::vector<std::uint64_t>{3, 8, 3, 8}));
    EXPECT_EQ(solve(rig.tracer, batch, 13).samples, 8u);
    batch.hypersampling_multiplier = 0.5;
    EXPECT_THROW(solve(rig.tracer, batch, 10), Error);
}

TEST(Solve, NearestBand) {
    const SpectralGrid grid({0.25, 0.5, 0.75});
    EXPECT_EQ(nearest_band(grid, 0.1), 0u);
    EXPECT_EQ(nearest_band(grid, 0.6), 1u);
    EXPECT_EQ(nearest_band(grid, 0.625), 1u);  // a tie takes the lower band
    EXPECT_EQ(nearest_band(grid, 9.0), 2u);
}

// ---- Materials -----------------------------------------------------------------------------

TEST(MaterialTable, SamplesHoldsEndsAndEmits) {
    model::Material m;
    m.id = "m";
    m.reflectance.wavelengths_um = {0.5, 0.6};
    m.reflectance.values = {0.2, 0.4};
    m.emissivity.wavelengths_um = {0.5, 0.6};
    m.emissivity.values = {0.8, 0.6};
    m.temperature_k = 1000.0;
    m.where = {"scene.yaml", 4, "materials[0]"};
    std::vector<std::string> warnings;
    const Log log([&](LogLevel, const std::string& text) { warnings.push_back(text); },
                  LogLevel::warning);
    const SpectralGrid grid({0.4, 0.55, 0.7});
    const MaterialTable table(std::span<const model::Material>(&m, 1), grid, log);
    EXPECT_DOUBLE_EQ(table.reflectance(0)[0], 0.2);
    EXPECT_DOUBLE_EQ(table.reflectance(0)[1], 0.3);
    EXPECT_DOUBLE_EQ(table.reflectance(0)[2], 0.4);
    EXPECT_DOUBLE_EQ(table.emission_w_per_cm2_sr_um(0)[1],
                     0.7 * planck_radiance_w_per_cm2_sr_um(0.55, 1000.0));
    EXPECT_TRUE(table.emits(0));
    EXPECT_TRUE(table.reflects(0));
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_THAT(warnings[0], HasSubstr("scene.yaml: material 'm': its curves do not cover"));
}

TEST(MaterialTable, RefusesMoreThanABlackbody) {
    model::Material m = flat_material("bright", 0.6, 300.0, 0.6);
    m.where = {"scene.yaml", 9, "materials[1]"};
    try {
        MaterialTable(std::span<const model::Material>(&m, 1), kGrid);
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_EQ(e.context().line, 9);
        EXPECT_THAT(e.message(), HasSubstr("emissivity 0.6 + reflectance 0.6 exceed 1"));
    }
}

TEST(MaterialTable, SumWithinRoundingOfOneLowersTheReflectanceSilently) {
    // ε + ρ = 1 + 5e-7 (decimals rounded on writing): accepted, ρ lowered to 1 − ε; 2e-6
    // above 1 is refused (model::check_material refused it first).
    model::Material m = flat_material("rounded", 0.1000005, 300.0, 0.9);
    const MaterialTable table(std::span<const model::Material>(&m, 1), kGrid);
    for (std::size_t b = 0; b < kGrid.size(); ++b) {
        EXPECT_DOUBLE_EQ(table.reflectance(0)[b], 1.0 - 0.9);
    }
    model::Material over = flat_material("over", 0.100002, 300.0, 0.9);
    EXPECT_THROW(MaterialTable(std::span<const model::Material>(&over, 1), kGrid), Error);
}

// ---- Environment ---------------------------------------------------------------------------

TEST(Environment, NoAtmosphereIsTheExoAtmosphericSunAndABlackSky) {
    const glint::atmosphere::NoAtmosphere none;
    const glint::atmosphere::SolarSpectrum sun(SpectralCurve({0.3, 1.0, 4.0}, {0.2, 0.1, 0.001}));
    EnvironmentInputs inputs;
    inputs.sun_direction_begin = inputs.sun_direction_end = direction_from(50.0, 90.0);
    inputs.sun_distance_au = 1.01;
    inputs.sensor_altitude_m = 5000.0;
    const Environment env = Environment::make(kGrid, none, sun, inputs);
    EXPECT_FALSE(env.has_sensor_path());
    EXPECT_TRUE(env.sky_black());
    const std::vector<double> toa = sun.resample(kGrid, 1.01);
    for (std::size_t b = 0; b < 3; ++b) {
        EXPECT_DOUBLE_EQ(env.sun_irradiance_w_per_cm2_um()[b], toa[b]);
    }
}

TEST(Environment, SensorPathInterpolatesTheAtmosphereAtItsNodes) {
    const model::ParametricAtmosphere parameters;  // with gas absorption
    const glint::atmosphere::ParametricAtmosphereModel atmosphere(parameters, gas_table());
    const glint::atmosphere::SolarSpectrum sun(SpectralCurve({0.3, 1.0, 4.0}, {0.2, 0.1, 0.001}));
    EnvironmentInputs inputs;
    inputs.sun_direction_begin = inputs.sun_direction_end = direction_from(30.0, 90.0);
    inputs.sensor_altitude_m = 2000.0;
    const Environment env = Environment::make(kGrid, atmosphere, sun, inputs);
    // At a node (view zenith 20°, 45° from the sun's azimuth) the table is the model.
    glint::atmosphere::AtmosphereGeometry g;
    g.sun_zenith_deg = 30.0;
    g.sun_azimuth_deg = 90.0;
    g.sensor_altitude_m = 2000.0;
    g.view_zenith_deg = 20.0;
    g.view_azimuth_deg = 135.0;
    const std::vector<double> toa = sun.resample(kGrid);
    const auto t_model = atmosphere.sensor_transmittance(kGrid, g);
    const auto l_model = atmosphere.path_radiance_w_per_cm2_sr_um(kGrid, g, toa);
    std::vector<double> t(3), l(3);
    env.sensor_path(direction_from(20.0, 135.0), 0.0, t, l);
    for (std::size_t b = 0; b < 3; ++b) {
        EXPECT_NEAR(t[b], t_model[b], 1e-12);
        EXPECT_NEAR(l[b], l_model[b], 1e-9 * l_model[b]);
    }
    // Symmetric about the sun's vertical plane.
    std::vector<double> t2(3), l2(3);
    env.sensor_path(direction_from(20.0, 45.0), 0.0, t2, l2);
    for (std::size_t b = 0; b < 3; ++b) EXPECT_NEAR(l2[b], l[b], 1e-9 * l[b]);
    // Longer slant paths transmit less.
    std::vector<double> t_slant(3), l_slant(3);
    env.sensor_path(direction_from(70.0, 135.0), 0.0, t_slant, l_slant);
    for (std::size_t b = 0; b < 3; ++b) EXPECT_LT(t_slant[b], t[b]);
}

TEST(Environment, ParametricTendsToNoneAsTheOpticalDepthVanishes) {
    model::ParametricAtmosphere clear;
    clear.aerosol_optical_depth_550 = 0.0;
    clear.sea_level_pressure_hpa = 0.0;
    clear.air_temperature_k = 0.0;
    clear.gas_absorption = false;
    const glint::atmosphere::ParametricAtmosphereModel atmosphere(clear);
    const glint::atmosphere::SolarSpectrum sun(SpectralCurve({0.3, 1.0, 4.0}, {0.2, 0.1, 0.001}));
    EnvironmentInputs inputs;
    inputs.sun_direction_begin = inputs.sun_direction_end = direction_from(30.0, 90.0);
    inputs.sensor_altitude_m = 2000.0;
    const Environment env = Environment::make(kGrid, atmosphere, sun, inputs);
    const std::vector<double> toa = sun.resample(kGrid);
    for (std::size_t b = 0; b < 3; ++b) {
        EXPECT_NEAR(env.sun_irradiance_w_per_cm2_um()[b], toa[b], 1e-12);
        EXPECT_NEAR(env.sky_radiance_w_per_cm2_sr_um()[b], 0.0, 1e-15);
    }
    std::vector<double> t(3), l(3);
    env.sensor_path(direction_from(40.0, 10.0), 0.0, t, l);
    for (std::size_t b = 0; b < 3; ++b) {
        EXPECT_NEAR(t[b], 1.0, 1e-12);
        EXPECT_NEAR(l[b], 0.0, 1e-15);
    }
}

TEST(Environment, SensorPathTablesAreSharedByRoundedGeometry) {
    const model::ParametricAtmosphere parameters;  // with gas absorption
    const glint::atmosphere::ParametricAtmosphereModel atmosphere(parameters, gas_table());
    const glint::atmosphere::SolarSpectrum sun(SpectralCurve({0.3, 1.0, 4.0}, {0.2, 0.1, 0.001}));
    EnvironmentInputs a;
    a.sun_direction_begin = a.sun_direction_end = direction_from(30.0, 90.0);
    a.sensor_altitude_m = 2000.0;
    // The sun 0.01° lower, the sensor 0.3 m higher, the sun 10⁻⁶ AU farther (a second
    // later): same rounding, and the same tables whichever capture filled the cache.
    EnvironmentInputs b = a;
    b.sun_direction_begin = b.sun_direction_end = direction_from(30.01, 90.0);
    b.sensor_altitude_m = 2000.3;
    b.sun_distance_au = a.sun_distance_au + 1e-6;
    SensorPathCache cache;
    const Environment ea = Environment::make(kGrid, atmosphere, sun, a, &cache);
    const Environment eb = Environment::make(kGrid, atmosphere, sun, b, &cache);
    EXPECT_EQ(cache.size(), 1u);
    const Environment fresh = Environment::make(kGrid, atmosphere, sun, b);  // no cache
    std::vector<double> t1(3), l1(3), t2(3), l2(3);
    eb.sensor_path(direction_from(25.0, 10.0), 0.0, t1, l1);
    fresh.sensor_path(direction_from(25.0, 10.0), 0.0, t2, l2);
    EXPECT_EQ(t1, t2);  // the cache changes nothing
    EXPECT_EQ(l1, l2);
    EnvironmentInputs c = a;
    c.sensor_altitude_m = 2500.0;
    Environment::make(kGrid, atmosphere, sun, c, &cache);
    EXPECT_EQ(cache.size(), 2u);
}

TEST(Environment, RefusesBadInputs) {
    EXPECT_THROW(Environment::uniform(kGrid, {0.0, 0.0, 0.0}, kSun, kSky), Error);
    EXPECT_THROW(Environment::uniform(kGrid, {0.0, 0.0, 1.0}, {1.0, 2.0}, kSky), Error);
    EXPECT_THROW(Environment::uniform(kGrid, {0.0, 0.0, 1.0}, kSun, {0.0, -1.0, 0.0}), Error);
    const glint::atmosphere::NoAtmosphere none;
    const glint::atmosphere::SolarSpectrum sun(SpectralCurve({0.3, 1.0, 4.0}, {0.2, 0.1, 0.001}));
    EnvironmentInputs inputs;
    inputs.window_begin_s = 2.0;
    inputs.window_end_s = 1.0;
    EXPECT_THROW(Environment::make(kGrid, none, sun, inputs), Error);
}

TEST(Environment, SunDirectionFollowsTheWindow) {
    EnvironmentInputs inputs;
    inputs.sun_direction_begin = {1.0, 0.0, 1.0};
    inputs.sun_direction_end = {0.0, 1.0, 1.0};
    inputs.window_begin_s = 10.0;
    inputs.window_end_s = 20.0;
    const Environment env = Environment::make(
        kGrid, glint::atmosphere::NoAtmosphere(),
        glint::atmosphere::SolarSpectrum(SpectralCurve({0.3, 4.0}, {0.1, 0.001})), inputs);
    const Vec3 mid = env.sun_direction(15.0);
    EXPECT_NEAR(mid.x, mid.y, 1e-15);
    EXPECT_NEAR(norm(mid), 1.0, 1e-15);
    EXPECT_NEAR(env.sun_direction(0.0).y, 0.0, 1e-15);  // clamped to the begin
}

}  // namespace problem_test
}  // namespace glint::radiometry
