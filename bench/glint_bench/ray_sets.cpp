// SPDX-License-Identifier: Apache-2.0
// The camera and the ray sets of glint-bench (ray_sets.h).
#include "ray_sets.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <limits>
#include <optional>

#include "glint/radiometry/sampling.h"

namespace glint::bench {
namespace {

using motion::Vec3;
using radiometry::SampleRay;

template <typename Body>
void parallel(std::size_t count, unsigned threads, const Body& body) {
    tbb::task_arena arena(threads == 0 ? tbb::task_arena::automatic : static_cast<int>(threads));
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 256),
                          [&](const tbb::blocked_range<std::size_t>& range) {
                              for (std::size_t i = range.begin(); i != range.end(); ++i) body(i);
                          });
    });
}

}  // namespace

NadirCamera::NadirCamera(unsigned width, unsigned height, double altitude_m, double half_fov_rad)
    : m_width(width),
      m_height(height),
      m_altitude_m(altitude_m),
      m_tan_half(std::tan(half_fov_rad)) {}

SampleRay NadirCamera::generate(std::uint64_t problem, std::uint64_t, RandomStream& rng) const {
    const double column = double(problem % m_width) + rng.uniform();
    const double row = double(problem / m_width) + rng.uniform();
    const double x = (2.0 * column / m_width - 1.0) * m_tan_half;
    const double y = (1.0 - 2.0 * row / m_height) * m_tan_half * m_height / m_width;
    SampleRay ray;
    ray.origin_m = {0.0, 0.0, m_altitude_m};
    ray.direction = normalized(Vec3{x, y, -1.0});
    return ray;
}

std::vector<SampleRay> primary_rays(const radiometry::RaySource& source, std::uint64_t count,
                                    std::uint64_t samples, const radiometry::StreamKey& key) {
    std::vector<SampleRay> rays(count * samples);
    parallel(count, 0, [&](std::size_t p) {
        for (std::uint64_t n = 0; n < samples; ++n) {
            RandomStream rng = radiometry::sample_stream(key, p, n);
            rays[p * samples + n] = source.generate(p, n, rng);
        }
    });
    return rays;
}

std::vector<SampleRay> incoherent_rays(const scene::GeometryScene& scene,
                                       const std::vector<SampleRay>& primary, std::uint64_t seed,
                                       unsigned threads) {
    std::vector<std::optional<SampleRay>> bounced(primary.size());
    parallel(primary.size(), threads, [&](std::size_t i) {
        const SampleRay& ray = primary[i];
        const auto hit = scene.intersect(ray.origin_m, ray.direction, ray.time_s);
        if (!hit) return;
        const Vec3 normal = dot(hit->normal, ray.direction) > 0.0 ? -hit->normal : hit->normal;
        RandomStream rng(seed, {1, i});
        const double u1 = rng.uniform();
        const double u2 = rng.uniform();
        const Vec3 local = radiometry::sample_cosine_hemisphere(u1, u2);
        const Vec3 direction = normalized(radiometry::Frame::from_normal(normal).to_world(local));
        bounced[i] = SampleRay{scene.spawn_origin(*hit, direction), direction, ray.time_s, 1.0};
    });
    std::vector<SampleRay> out;
    out.reserve(primary.size());
    for (const auto& ray : bounced) {
        if (ray) out.push_back(*ray);
    }
    return out;
}

std::vector<BareRay> to_bare(const std::vector<SampleRay>& rays) {
    std::vector<BareRay> out(rays.size());
    for (std::size_t i = 0; i < rays.size(); ++i) {
        for (std::size_t k = 0; k < 3; ++k) {
            out[i].origin[k] = static_cast<float>(rays[i].origin_m[k]);
            out[i].direction[k] = static_cast<float>(rays[i].direction[k]);
        }
    }
    return out;
}

std::vector<double> scene_distances(const scene::GeometryScene& scene,
                                    const std::vector<SampleRay>& rays, unsigned threads) {
    std::vector<double> out(rays.size(), std::numeric_limits<double>::infinity());
    parallel(rays.size(), threads, [&](std::size_t i) {
        const auto hit = scene.intersect(rays[i].origin_m, rays[i].direction, rays[i].time_s);
        if (hit) out[i] = hit->distance_m;
    });
    return out;
}

}  // namespace glint::bench
