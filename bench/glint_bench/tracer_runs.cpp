// SPDX-License-Identifier: Apache-2.0
// The path tracer rigs and timings of glint-bench (tracer_runs.h).
#include "tracer_runs.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <numbers>
#include <vector>

#include "measurements.h"

namespace glint::bench {
namespace {

/// Sun 35° from the zenith, azimuth 150° (clockwise from north).
constexpr double kSunZenithDeg = 35.0;
constexpr double kSunAzimuthDeg = 150.0;
/// Flat solar irradiance at the surface, W/(cm² µm), and sky radiance, W/(cm² sr µm).
constexpr double kSunIrradiance = 0.15;
constexpr double kSkyRadiance = 0.004;

SpectralGrid make_grid(std::size_t bands) {
    if (bands <= 1) return SpectralGrid(std::vector<double>{0.55});
    std::vector<double> w(bands);
    for (std::size_t i = 0; i < bands; ++i) w[i] = 0.4 + 2.1 * double(i) / double(bands - 1);
    return SpectralGrid(std::move(w));
}

constexpr std::uint64_t kHashStart = 14695981039346656037ull;

/// Folds the bit patterns of `values` into `hash` (FNV-1a over 64-bit words).
std::uint64_t hash_bits(std::uint64_t hash, const std::vector<double>& values) {
    for (const double v : values) {
        std::uint64_t word = 0;
        std::memcpy(&word, &v, sizeof word);
        hash = (hash ^ word) * 1099511628211ull;
    }
    return hash;
}

radiometry::Environment make_environment(const SpectralGrid& grid) {
    const double zenith = kSunZenithDeg * std::numbers::pi / 180.0;
    const double azimuth = kSunAzimuthDeg * std::numbers::pi / 180.0;
    const motion::Vec3 sun{std::sin(zenith) * std::sin(azimuth),
                           std::sin(zenith) * std::cos(azimuth), std::cos(zenith)};
    return radiometry::Environment::uniform(grid, sun,
                                            std::vector<double>(grid.size(), kSunIrradiance),
                                            std::vector<double>(grid.size(), kSkyRadiance));
}

}  // namespace

TracerRig::TracerRig(const model::Scene& scene, const scene::GeometryScene& geometry,
                     std::size_t bands, radiometry::TracerSettings settings)
    : grid(make_grid(bands)),
      materials(scene.materials, grid),
      environment(make_environment(grid)),
      tracer(geometry, materials, environment, settings) {}

namespace {

/// The tile loop of time_tracer and time_reduced: `repeats` runs over problems 0 … count − 1,
/// `tile` at a time, each tile handed to solve_tile(batch, timing) (which adds its seconds,
/// rays, paths and hash); returns the fastest run.
template <typename SolveTile>
TracerTiming time_tiles(const radiometry::RaySource& source, std::uint64_t count,
                        std::uint64_t samples, std::uint64_t tile, const radiometry::StreamKey& key,
                        unsigned repeats, const SolveTile& solve_tile) {
    tile = std::max<std::uint64_t>(1, tile);
    radiometry::ProblemBatch batch;
    batch.key = key;
    batch.source = &source;
    batch.convergence = {samples, samples, 0.0};
    TracerTiming best;
    for (unsigned r = 0; r < std::max(1u, repeats); ++r) {
        TracerTiming t;
        t.radiance_hash = kHashStart;
        for (std::uint64_t first = 0; first < count; first += tile) {
            batch.first_problem = first;
            batch.count = std::min(tile, count - first);
            solve_tile(batch, t);
        }
        if (r == 0 || t.seconds < best.seconds) best = t;
    }
    return best;
}

}  // namespace

TracerTiming time_tracer(const radiometry::PathTracer& tracer, const radiometry::RaySource& source,
                         std::uint64_t count, std::uint64_t samples, std::uint64_t tile,
                         const radiometry::StreamKey& key, unsigned threads, unsigned repeats,
                         const Context& context) {
    Context run = context;
    run.threads = threads;
    return time_tiles(source, count, samples, tile, key, repeats,
                      [&](const radiometry::ProblemBatch& batch, TracerTiming& t) {
                          const auto start = std::chrono::steady_clock::now();
                          radiometry::Solutions solutions = radiometry::solve(tracer, batch, run);
                          t.seconds += seconds_since(start);
                          t.rays += solutions.rays;
                          for (const std::uint64_t n : solutions.samples) t.paths += n;
                          t.radiance_hash =
                              hash_bits(t.radiance_hash, solutions.radiance_w_per_cm2_sr_um);
                          // Freed inside the timed part, as a renderer frees its tiles.
                          const auto release = std::chrono::steady_clock::now();
                          solutions = {};
                          t.seconds += seconds_since(release);
                      });
}

TracerTiming time_reduced(const radiometry::PathTracer& tracer, const radiometry::RaySource& source,
                          std::uint64_t count, std::uint64_t samples, std::uint64_t tile,
                          const radiometry::StreamKey& key, unsigned threads, unsigned repeats,
                          const Context& context) {
    Context run = context;
    run.threads = threads;
    std::vector<double> integrated;
    std::vector<std::uint64_t> taken;
    return time_tiles(source, count, samples, tile, key, repeats,
                      [&](const radiometry::ProblemBatch& batch, TracerTiming& t) {
                          integrated.assign(batch.count, 0.0);
                          taken.assign(batch.count, 0);
                          const auto start = std::chrono::steady_clock::now();
                          t.rays += radiometry::solve_each(
                              tracer, batch, run,
                              [&](std::uint64_t i, std::span<double> radiance,
                                  std::span<const std::uint32_t> nonzero, std::uint64_t n, double) {
                                  // As OutputUnits::apply does: the listed bands only, zero bands
                                  // skipped.
                                  double sum = 0.0;
                                  if (nonzero.empty()) {
                                      for (const double v : radiance) {
                                          if (v != 0.0) sum += v;
                                      }
                                  } else {
                                      for (const std::uint32_t b : nonzero) sum += radiance[b];
                                  }
                                  integrated[i] = sum;
                                  taken[i] = n;
                              });
                          t.seconds += seconds_since(start);
                          for (const std::uint64_t n : taken) t.paths += n;
                          t.radiance_hash = hash_bits(t.radiance_hash, integrated);
                      });
}

TracerTiming time_trace_only(const radiometry::PathTracer& tracer,
                             const radiometry::RaySource& source, std::uint64_t count,
                             std::uint64_t samples, const radiometry::StreamKey& key,
                             unsigned threads, unsigned repeats) {
    struct Workspace {
        explicit Workspace(const radiometry::PathTracer& tracer)
            : scratch(tracer.environment().bands()), radiance(tracer.bands()) {}
        radiometry::PathScratch scratch;
        std::vector<double> radiance;
        double checksum = 0.0;  ///< keeps the compiler from dropping the work
    };
    tbb::task_arena arena(threads == 0 ? tbb::task_arena::automatic : static_cast<int>(threads));
    TracerTiming best;
    for (unsigned r = 0; r < std::max(1u, repeats); ++r) {
        tbb::enumerable_thread_specific<Workspace> workspaces([&] { return Workspace(tracer); });
        const auto start = std::chrono::steady_clock::now();
        arena.execute([&] {
            tbb::parallel_for(tbb::blocked_range<std::uint64_t>(0, count, 16),
                              [&](const tbb::blocked_range<std::uint64_t>& range) {
                                  Workspace& ws = workspaces.local();
                                  for (std::uint64_t p = range.begin(); p != range.end(); ++p) {
                                      for (std::uint64_t n = 0; n < samples; ++n) {
                                          RandomStream rng = radiometry::sample_stream(key, p, n);
                                          const radiometry::SampleRay ray =
                                              source.generate(p, n, rng);
                                          tracer.trace(ray, rng, ws.scratch, ws.radiance);
                                          ws.checksum += ws.radiance[0];
                                      }
                                  }
                              });
        });
        TracerTiming t;
        t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        t.paths = count * samples;
        for (const Workspace& ws : workspaces) t.rays += ws.scratch.rays;
        if (r == 0 || t.seconds < best.seconds) best = t;
    }
    return best;
}

}  // namespace glint::bench
