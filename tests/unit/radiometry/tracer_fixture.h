// SPDX-License-Identifier: Apache-2.0
// Small scenes and ray sources for the path tracer tests: constant-reflectance materials,
// primitives tessellated by the scene reader's own code, a built GeometryScene, and ray
// sources (one fixed ray, random directions from a point, random times in a window).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "glint/core/diagnostics.h"
#include "glint/core/spectral.h"
#include "glint/mesh/mesh.h"
#include "glint/model/scene.h"
#include "glint/radiometry/environment.h"
#include "glint/radiometry/materials.h"
#include "glint/radiometry/path_tracer.h"
#include "glint/radiometry/problem.h"
#include "glint/radiometry/sampling.h"
#include "glint/scene/geometry_scene.h"

namespace glint::radiometry::test {

using model::flat_material;

/// Adds a primitive object of material `material` with one static identity instance, or a
/// dynamic instance moving with `motion`; returns the instance index.
inline std::size_t add_primitive(model::Scene& scene, const model::Primitive& primitive,
                                 std::uint32_t material,
                                 std::optional<model::PlatformMotion> motion = std::nullopt) {
    Diagnostics diagnostics;
    model::GeometryObject object;
    object.name = "object" + std::to_string(scene.objects.size());
    object.primitive = primitive;
    object.mesh = mesh::tessellate_primitive(primitive, material, {}, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors());
    scene.objects.push_back(std::move(object));
    model::Instance instance;
    instance.object_index = scene.objects.size() - 1;
    instance.name = scene.objects.back().name;
    if (motion) instance.motion = std::make_shared<const model::PlatformMotion>(std::move(*motion));
    scene.instances.push_back(std::move(instance));
    return scene.instances.size() - 1;
}

inline model::Primitive ground_plane(double size_m = model::kDefaultGroundPlaneSize_m) {
    model::Primitive p;
    p.kind = model::PrimitiveKind::ground_plane;
    p.size_m = size_m;
    return p;
}

inline model::Primitive box(std::array<double, 3> lower_m, std::array<double, 3> upper_m) {
    model::Primitive p;
    p.kind = model::PrimitiveKind::box;
    p.lower_m = lower_m;
    p.upper_m = upper_m;
    return p;
}

/// Monte Carlo checks at low sample counts: within this many standard errors (a 4σ miss has a
/// probability of 6e-5 for a normal estimate, and the seeds are fixed).
inline constexpr double kSigmas = 4.0;
/// The accuracy asked of the analytic references at high sample counts.
inline constexpr double kHighCountRelative = 0.005;
/// Three visible bands, µm.
inline const SpectralGrid kVisible({0.45, 0.55, 0.65});
/// The sun on kVisible, W/(cm² µm): roughly ASTM at 1 AU.
inline const std::vector<double> kSun{0.20, 0.19, 0.16};
/// A black sky (or sun) on kVisible.
inline const std::vector<double> kBlack(3, 0.0);

/// A scene built for rendering with the tracer over a spectral grid and an environment.
struct Rig {
    Rig(model::Scene scene_in, SpectralGrid grid_in, Environment environment_in,
        TracerSettings settings = {}, scene::TimeWindow window = {})
        : scene(std::move(scene_in)),
          grid(std::move(grid_in)),
          trajectories(motion::make_instance_trajectories(scene, motion::SceneFrame(), DateTime{})),
          geometry(scene::GeometryScene::build(scene, trajectories,
                                               scene::BuildOptions{{}, window, {}})),
          materials(scene.materials, grid),
          environment(std::move(environment_in)),
          tracer(geometry, materials, environment, settings) {}

    model::Scene scene;
    SpectralGrid grid;
    std::vector<std::unique_ptr<motion::Trajectory>> trajectories;
    scene::GeometryScene geometry;
    MaterialTable materials;
    Environment environment;
    PathTracer tracer;
};

/// Every sample is the same ray.
class FixedRay final : public RaySource {
public:
    explicit FixedRay(SampleRay ray) : m_ray(ray) {}
    SampleRay generate(std::uint64_t, std::uint64_t, RandomStream&) const override { return m_ray; }

private:
    SampleRay m_ray;
};

/// Directions uniform over the sphere from one point.
class SphereRays final : public RaySource {
public:
    explicit SphereRays(Vec3 origin_m) : m_origin(origin_m) {}
    SampleRay generate(std::uint64_t, std::uint64_t, RandomStream& rng) const override {
        Vec3 d = sample_uniform_hemisphere(rng.uniform(), rng.uniform());
        if (rng.uniform() < 0.5) d.z = -d.z;
        return {m_origin, d, 0.0, 1.0};
    }

private:
    Vec3 m_origin;
};

/// A fixed origin and direction at times uniform over [begin, end].
class WindowRays final : public RaySource {
public:
    WindowRays(SampleRay ray, double begin_s, double end_s)
        : m_ray(ray), m_begin_s(begin_s), m_end_s(end_s) {}
    SampleRay generate(std::uint64_t, std::uint64_t, RandomStream& rng) const override {
        SampleRay r = m_ray;
        r.time_s = m_begin_s + (m_end_s - m_begin_s) * rng.uniform();
        return r;
    }

private:
    SampleRay m_ray;
    double m_begin_s;
    double m_end_s;
};

/// Problems of a fixed convergence rule with a given sample count.
inline ProblemBatch batch_of(const RaySource& source, std::uint64_t samples,
                             std::uint64_t count = 1, std::uint64_t seed = 7) {
    ProblemBatch b;
    b.key.seed = seed;
    b.source = &source;
    b.convergence = {samples, samples, 0.0};
    b.count = count;
    return b;
}

/// The per-band mean radiance of `runs` independent solutions of one problem (`samples` draws
/// from `source` each, seeds `first_seed`, `first_seed` + 1, …) and the standard error of that
/// mean from their spread: Monte Carlo checks compare against mean ± kSigmas × error.
struct RepeatedRuns {
    std::vector<double> mean;
    std::vector<double> standard_error;
};

inline RepeatedRuns repeated_runs(const PathTracer& tracer, const RaySource& source,
                                  std::uint64_t samples, int runs, std::uint64_t first_seed,
                                  std::size_t bands) {
    std::vector<double> sum(bands, 0.0), sum_sq(bands, 0.0);
    for (int run = 0; run < runs; ++run) {
        const Solutions solved = solve(
            tracer, batch_of(source, samples, 1, first_seed + static_cast<std::uint64_t>(run)),
            Context{});
        for (std::size_t b = 0; b < bands; ++b) {
            const double v = solved.radiance(0)[b];
            sum[b] += v;
            sum_sq[b] += v * v;
        }
    }
    RepeatedRuns out;
    for (std::size_t b = 0; b < bands; ++b) {
        const double mean = sum[b] / runs;
        out.mean.push_back(mean);
        out.standard_error.push_back(
            std::sqrt(std::max(sum_sq[b] / runs - mean * mean, 0.0) / (runs - 1)));
    }
    return out;
}

/// A 2 m square plate at 1.5 m, its normal `n`, as a mesh of material `material`.
inline void add_plate(model::Scene& scene, const Vec3& n, std::uint32_t material) {
    // Two in-plane axes: east, and n × east.
    const Vec3 east{1.0, 0.0, 0.0};
    const Vec3 up{n.y * east.z - n.z * east.y, n.z * east.x - n.x * east.z,
                  n.x * east.y - n.y * east.x};
    const Vec3 c{0.0, 0.0, 1.5};
    model::GeometryObject object;
    object.name = "plate";
    for (const auto& [a, b] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}) {
        const Vec3 p = c + east * a + up * b;
        object.mesh.vertices_m.push_back(
            {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)});
    }
    // Counter-clockwise seen from the front (along −n).
    object.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    object.mesh.triangle_materials = {material, material};
    scene.objects.push_back(std::move(object));
    model::Instance instance;
    instance.object_index = scene.objects.size() - 1;
    instance.name = "plate";
    scene.instances.push_back(std::move(instance));
}

/// The unit direction at zenith angle `zenith_deg` and azimuth `azimuth_deg` (clockwise from
/// north, scene ENU).
inline Vec3 direction_from(double zenith_deg, double azimuth_deg) {
    const double t = zenith_deg * kPi / 180.0;
    const double p = azimuth_deg * kPi / 180.0;
    return {std::sin(t) * std::sin(p), std::sin(t) * std::cos(p), std::cos(t)};
}

}  // namespace glint::radiometry::test
