// SPDX-License-Identifier: Apache-2.0
// Spectral sampling (glint/radiometry/spectral_draw.h, TracerSettings::spectral_samples): the
// stratified draw gives every band but the reference exactly the probability it is weighted
// by; a path traced at a list of bands is the whole-spectrum path at those bands; the
// estimator is unbiased against the analytic answers and against the full-spectrum estimator
// on the atmosphere plate and the isothermal box; the bytes do not depend on the thread
// count; and every path carries the reference band.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numeric>
#include <vector>

#include "glint/atmosphere/atmosphere.h"
#include "glint/core/error.h"
#include "glint/core/spectral.h"
#include "glint/radiometry/spectral_draw.h"
#include "tracer_fixture.h"

namespace glint::radiometry {
namespace spectral_sampling_test {

using test::batch_of;
using test::direction_from;
using test::FixedRay;
using test::flat_material;
using test::ground_plane;
using test::Rig;

using test::kSigmas;

SpectralGrid even_grid(double first_um, double last_um, std::size_t bands) {
    std::vector<double> w(bands);
    for (std::size_t i = 0; i < bands; ++i) {
        w[i] = first_um + (last_um - first_um) * double(i) / double(bands - 1);
    }
    return SpectralGrid(std::move(w));
}

/// The isotropic sky: a Lambertian plate reflects it exactly with every draw
/// (directional_sky_test.cpp tests the directional one).
Environment parametric_environment(const SpectralGrid& grid) {
    model::ParametricAtmosphere parameters;
    parameters.gas_absorption = false;  // scattering only: the gases have their own tests
    parameters.directional_sky = false;
    const glint::atmosphere::ParametricAtmosphereModel atmosphere(parameters);
    const glint::atmosphere::SolarSpectrum sun(
        SpectralCurve({0.3, 0.5, 1.0, 2.5}, {0.15, 0.2, 0.1, 0.01}));
    EnvironmentInputs inputs;
    inputs.sun_direction_begin = inputs.sun_direction_end = direction_from(40.0, 160.0);
    inputs.sensor_altitude_m = 3000.0;
    return Environment::make(grid, atmosphere, sun, inputs);
}

model::Scene plate_scene(double reflectance) {
    model::Scene scene;
    scene.materials.push_back(flat_material("plate", reflectance));
    test::add_primitive(scene, ground_plane(), 0);
    return scene;
}

/// Per band, the mean of the problems' radiances and its standard error (from their spread).
struct BandMeans {
    std::vector<double> mean;
    std::vector<double> standard_error;
};

BandMeans band_means(const Solutions& s, std::size_t problems) {
    BandMeans m;
    m.mean.assign(s.bands, 0.0);
    m.standard_error.assign(s.bands, 0.0);
    for (std::size_t b = 0; b < s.bands; ++b) {
        double sum = 0.0;
        double sum_sq = 0.0;
        for (std::size_t p = 0; p < problems; ++p) {
            const double v = s.radiance(p)[b];
            sum += v;
            sum_sq += v * v;
        }
        const double n = static_cast<double>(problems);
        m.mean[b] = sum / n;
        const double variance = std::max(0.0, (sum_sq - sum * sum / n) / (n - 1.0));
        m.standard_error[b] = std::sqrt(variance / n);
    }
    return m;
}

TEST(SpectralDraw, EveryOtherBandIsDrawnWithProbabilityExactlyTheInverseOfItsWeight) {
    for (const std::size_t bands : {3u, 4u, 7u, 32u, 301u}) {
        for (const unsigned k : {2u, 3u, 4u, 8u}) {
            if (k >= bands) continue;
            for (const std::size_t reference : {std::size_t{0}, bands / 2, bands - 1}) {
                const std::size_t first = 5;
                const SpectralDraw draw(first, bands, reference, k);
                ASSERT_TRUE(draw.active());
                ASSERT_EQ(draw.size(), k);
                const std::size_t remaining = bands - 1;
                EXPECT_DOUBLE_EQ(draw.weight(), double(remaining) / double(k - 1));
                // Every offset once (u at the middle of each of the M equal intervals): each
                // band but the reference must be drawn exactly K - 1 times in M draws.
                std::vector<std::size_t> count(bands, 0);
                std::vector<std::uint32_t> grid(k), relative(k);
                for (std::size_t o = 0; o < remaining; ++o) {
                    draw.draw((double(o) + 0.5) / double(remaining), grid, relative);
                    EXPECT_EQ(relative[0], reference);
                    for (std::size_t j = 0; j < k; ++j) {
                        ASSERT_LT(relative[j], bands);
                        EXPECT_EQ(grid[j], first + relative[j]);
                        ++count[relative[j]];
                        for (std::size_t i = 0; i < j; ++i) EXPECT_NE(relative[i], relative[j]);
                    }
                }
                for (std::size_t b = 0; b < bands; ++b) {
                    EXPECT_EQ(count[b], b == reference ? remaining : k - 1)
                        << bands << " bands, K " << k << ", reference " << reference << ", band "
                        << b;
                }
                // The ends of [0, 1) stay inside the bands.
                draw.draw(0.0, grid, relative);
                draw.draw(std::nextafter(1.0, 0.0), grid, relative);
                for (const std::uint32_t b : relative) EXPECT_LT(b, bands);
            }
        }
    }
}

TEST(SpectralDraw, EveryBandWhenOffAndOneIsRefused) {
    EXPECT_FALSE(SpectralDraw(0, 10, 3, 0).active());
    EXPECT_FALSE(SpectralDraw(0, 10, 3, 10).active());
    EXPECT_FALSE(SpectralDraw(0, 10, 3, 50).active());
    EXPECT_EQ(SpectralDraw(0, 10, 3, 0).size(), 10u);
    EXPECT_TRUE(SpectralDraw(0, 10, 3, 9).active());
    try {
        SpectralDraw(0, 10, 3, 1);
        FAIL() << "1 sample was accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::usage);
        EXPECT_NE(std::string(e.what()).find("use 0 (every band) or at least 2"),
                  std::string::npos);
    }
    EXPECT_THROW(SpectralDraw(0, 10, 10, 4), Error);

    const SpectralGrid grid({0.45, 0.55});
    TracerSettings one;
    one.spectral_samples = 1;
    EXPECT_THROW(Rig(plate_scene(0.3), grid,
                     Environment::uniform(grid, {0.0, 0.0, 1.0}, {0.1, 0.1}, {0.0, 0.0}), one),
                 Error);
}

TEST(SpectralSampling, TraceBandsIsTheWholeSpectrumPathAtThoseBands) {
    // Without Russian roulette (the only place the bands meet) a path traced at a list of
    // bands is the whole-spectrum path at them, through the sun, emission, a point source,
    // bounces between a box and the plate, the sky and the sensor path.
    const SpectralGrid grid = even_grid(0.45, 2.2, 9);
    model::Scene scene = plate_scene(0.3);
    scene.materials.push_back(flat_material("warm box", 0.5, 330.0, 0.4));
    test::add_primitive(scene, test::box({-1.0, -1.0, 0.0}, {1.0, 1.0, 1.5}), 1);
    TracerSettings settings;
    settings.roulette_start_bounce = 1'000;
    Rig rig(std::move(scene), grid, parametric_environment(grid), settings);
    PointLights lights(grid.size());
    lights.add("lamp", {2.5, 1.0, 3.0}, std::vector<double>(grid.size(), 40.0));
    const PathTracer tracer(rig.geometry, rig.materials, rig.environment, settings, &lights);

    const test::SphereRays source({1.8, -0.4, 0.7});
    PathScratch scratch(grid.size());
    std::vector<double> whole(grid.size());
    const std::vector<std::uint32_t> list{7, 0, 4, 8};
    std::vector<double> some(list.size());
    double seen = 0.0;
    for (std::uint64_t n = 0; n < 500; ++n) {
        RandomStream a(11, {n});
        RandomStream b(11, {n});
        FirstHit hit_a, hit_b;
        tracer.trace(source.generate(0, n, a), a, scratch, whole, &hit_a);
        tracer.trace_bands(source.generate(0, n, b), b, scratch, list, some, &hit_b);
        for (std::size_t j = 0; j < list.size(); ++j) {
            EXPECT_EQ(some[j], whole[list[j]]) << "sample " << n << " band " << list[j];
        }
        EXPECT_EQ(hit_a.hit, hit_b.hit);
        EXPECT_EQ(hit_a.distance_m, hit_b.distance_m);
        EXPECT_EQ(a.position(), b.position());
        seen += some[0];
    }
    EXPECT_GT(seen, 0.0);
    std::vector<double> wrong(3);
    RandomStream rng(1, {1});
    EXPECT_THROW(tracer.trace_bands(source.generate(0, 0, rng), rng, scratch, list, wrong), Error);
}

/// Solves `problems` independent problems of `samples` samples each with `settings`.
Solutions solve_problems(const Rig& rig, const RaySource& source, TracerSettings settings,
                         std::uint64_t problems, std::uint64_t samples, std::size_t reference) {
    const PathTracer tracer(rig.geometry, rig.materials, rig.environment, settings);
    ProblemBatch batch = batch_of(source, samples, problems, 23);
    batch.reference_band = reference;
    return solve(tracer, batch, Context{});
}

TEST(SpectralSampling, UnbiasedOnTheAtmospherePlate) {
    // The plate under the parametric atmosphere: L = T_v (ρ (E_sun cos θs / π + L_sky)) + L_p
    // at every band, which differ (the sun, the sky and the path all vary with λ). 4 of 24
    // bands per path; every band's mean over 48 independent problems must lie within 4
    // standard errors of the answer and of the full-spectrum estimator's mean.
    const SpectralGrid grid = even_grid(0.4, 2.4, 24);
    const double rho = 0.3;
    Rig rig(plate_scene(rho), grid, parametric_environment(grid));
    const FixedRay source({{0.0, 0.0, 1000.0}, {0.0, 0.0, -1.0}, 0.0, 1.0});
    TracerSettings hero;
    hero.spectral_samples = 4;
    constexpr std::uint64_t kProblems = 48;
    const BandMeans sampled =
        band_means(solve_problems(rig, source, hero, kProblems, 1500, 5), kProblems);
    const BandMeans full =
        band_means(solve_problems(rig, source, {}, kProblems, 200, 5), kProblems);

    std::vector<double> t_v(grid.size()), l_p(grid.size());
    rig.environment.sensor_path({0.0, 0.0, 1.0}, 0.0, t_v, l_p);
    double relative_sum = 0.0;
    for (std::size_t b = 0; b < grid.size(); ++b) {
        const double surface = rho * (rig.environment.sun_irradiance_w_per_cm2_um()[b] *
                                          std::cos(40.0 * kPi / 180.0) / kPi +
                                      rig.environment.sky_radiance_w_per_cm2_sr_um()[b]);
        const double expected = t_v[b] * surface + l_p[b];
        // 1e-4: the full estimator's own bias on this plate (the sun disk's mean cosine and
        // the plate's edge), as in the path tracer's plate test.
        EXPECT_NEAR(sampled.mean[b], expected,
                    kSigmas * sampled.standard_error[b] + 1e-4 * expected)
            << "band " << b;
        EXPECT_NEAR(sampled.mean[b], full.mean[b],
                    kSigmas * std::hypot(sampled.standard_error[b], full.standard_error[b]) + 1e-12)
            << "band " << b;
        EXPECT_GT(sampled.standard_error[b], 0.0) << "band " << b;
        relative_sum += (sampled.mean[b] - expected) / expected;
    }
    // Spread over the bands, the mean relative error is ~sqrt(24) times smaller still.
    EXPECT_LT(std::fabs(relative_sum / double(grid.size())), 0.01);
}

TEST(SpectralSampling, UnbiasedInTheIsothermalBox) {
    // Kirchhoff's furnace: inside a closed enclosure at one temperature the radiance is B(T)
    // at every wavelength, built up over ~1/(1 − ρ) bounces with Russian roulette watching
    // the drawn bands' throughput. 3 of 12 thermal bands per path.
    const SpectralGrid grid = even_grid(8.0, 13.0, 12);
    const double t_k = 300.0;
    model::Scene scene;
    scene.materials.push_back(flat_material("wall", 0.6, t_k));
    test::add_primitive(scene, test::box({-5.0, -4.0, -3.0}, {5.0, 4.0, 3.0}), 0);
    TracerSettings settings;
    settings.max_bounces = 10'000;
    Rig rig(std::move(scene), grid,
            Environment::uniform(grid, {0.0, 0.0, 1.0}, std::vector<double>(12, 0.0),
                                 std::vector<double>(12, 0.0)),
            settings);
    const test::SphereRays source({0.5, -0.3, 0.2});
    TracerSettings hero = settings;
    hero.spectral_samples = 3;
    constexpr std::uint64_t kProblems = 40;
    const BandMeans sampled =
        band_means(solve_problems(rig, source, hero, kProblems, 2000, 6), kProblems);
    const BandMeans full =
        band_means(solve_problems(rig, source, settings, kProblems, 500, 6), kProblems);
    for (std::size_t b = 0; b < grid.size(); ++b) {
        const double expected = planck_radiance_w_per_cm2_sr_um(grid.wavelength_um(b), t_k);
        EXPECT_NEAR(sampled.mean[b], expected, kSigmas * sampled.standard_error[b]) << "band " << b;
        EXPECT_NEAR(sampled.mean[b], full.mean[b],
                    kSigmas * std::hypot(sampled.standard_error[b], full.standard_error[b]))
            << "band " << b;
        EXPECT_LT(sampled.standard_error[b], 0.02 * expected) << "band " << b;
    }
}

/// Checks every sample a recorder sees: exactly K bands non-zero, the reference among them.
class CountingObserver final : public SampleObserver {
public:
    CountingObserver(std::size_t reference, std::size_t k) : m_reference(reference), m_k(k) {}
    bool wants_first_hit() const noexcept override { return false; }
    std::unique_ptr<SampleRecorder> make_recorder() const override {
        return std::make_unique<Recorder>(*this);
    }
    mutable std::uint64_t samples = 0;
    mutable std::uint64_t bad = 0;

private:
    class Recorder final : public SampleRecorder {
    public:
        explicit Recorder(const CountingObserver& o) : m_o(o) {}
        void begin(std::uint64_t) override {}
        void add(const SampleRay&, std::span<const double> radiance, const FirstHit*) override {
            const auto nonzero =
                std::count_if(radiance.begin(), radiance.end(), [](double v) { return v != 0.0; });
            ++m_o.samples;
            if (static_cast<std::size_t>(nonzero) != m_o.m_k || radiance[m_o.m_reference] <= 0.0) {
                ++m_o.bad;
            }
        }
        void end(std::uint64_t, std::uint64_t) override {}

    private:
        const CountingObserver& m_o;
    };
    std::size_t m_reference;
    std::size_t m_k;
};

TEST(SpectralSampling, RecordersSeeTheDrawnBandsAndEveryPathCarriesTheReference) {
    const SpectralGrid grid = even_grid(0.4, 2.4, 16);
    Rig rig(plate_scene(0.3), grid, parametric_environment(grid));
    const FixedRay source({{0.0, 0.0, 1000.0}, {0.0, 0.0, -1.0}, 0.0, 1.0});
    TracerSettings hero;
    hero.spectral_samples = 5;
    const PathTracer tracer(rig.geometry, rig.materials, rig.environment, hero);
    CountingObserver observer(9, 5);
    ProblemBatch batch = batch_of(source, 300, 2);
    batch.reference_band = 9;
    batch.observer = &observer;
    Context one;
    one.threads = 1;
    solve(tracer, batch, one);
    EXPECT_EQ(observer.samples, 600u);
    EXPECT_EQ(observer.bad, 0u);
}

TEST(SpectralSampling, SameBytesForOneAndTwoThreads) {
    const SpectralGrid grid = even_grid(0.4, 2.4, 40);
    model::Scene scene = plate_scene(0.3);
    scene.materials.push_back(flat_material("white", 0.9));
    test::add_primitive(scene, test::box({-3.0, -3.0, 0.0}, {3.0, 3.0, 4.0}), 1);
    Rig rig(std::move(scene), grid, parametric_environment(grid));
    TracerSettings hero;
    hero.spectral_samples = 6;
    const PathTracer tracer(rig.geometry, rig.materials, rig.environment, hero);
    const test::SphereRays source({0.0, -8.0, 2.0});
    ProblemBatch batch = batch_of(source, 8, 64);
    Context one;
    one.threads = 1;
    Context two;
    two.threads = 2;
    const Solutions a = solve(tracer, batch, one);
    const Solutions b = solve(tracer, batch, two);
    ASSERT_EQ(a.radiance_w_per_cm2_sr_um.size(), b.radiance_w_per_cm2_sr_um.size());
    EXPECT_EQ(std::memcmp(a.radiance_w_per_cm2_sr_um.data(), b.radiance_w_per_cm2_sr_um.data(),
                          a.radiance_w_per_cm2_sr_um.size() * sizeof(double)),
              0);
    // And not the full-spectrum bytes.
    const PathTracer full(rig.geometry, rig.materials, rig.environment, TracerSettings{});
    const Solutions c = solve(full, batch, one);
    EXPECT_NE(std::memcmp(a.radiance_w_per_cm2_sr_um.data(), c.radiance_w_per_cm2_sr_um.data(),
                          a.radiance_w_per_cm2_sr_um.size() * sizeof(double)),
              0);
}

}  // namespace spectral_sampling_test
}  // namespace glint::radiometry
