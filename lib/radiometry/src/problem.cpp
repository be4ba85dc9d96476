// SPDX-License-Identifier: Apache-2.0
// solve(): the per-pixel convergence loop, on one thread or in parallel over problems with
// oneTBB (glint/radiometry/problem.h).
#include "glint/radiometry/problem.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <string>

#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::radiometry {
namespace {

/// Per-thread buffers of the convergence loop (the "arena" of one worker).
struct Workspace {
    Workspace(const PathTracer& tracer, const ProblemBatch& batch)
        : path(tracer.environment().bands()),
          sample(tracer.bands()),
          sum(tracer.bands()),
          radiance(tracer.bands()),
          recorder(batch.observer != nullptr ? batch.observer->make_recorder() : nullptr),
          wants_first_hit(batch.observer != nullptr && batch.observer->wants_first_hit()) {}
    PathScratch path;
    std::vector<double> sample;    ///< one sample's radiance
    std::vector<double> sum;       ///< Σ w L per band
    std::vector<double> radiance;  ///< the problem's result, handed to the receiver
    std::unique_ptr<SampleRecorder> recorder;
    bool wants_first_hit = false;
    FirstHit first_hit;
};

void check_batch(const PathTracer& tracer, const ProblemBatch& batch) {
    const Convergence& c = batch.convergence;
    if (batch.source == nullptr) throw usage_error("a problem batch needs a ray source");
    if (c.min_samples < 1) throw usage_error("the minimum sample count must be at least 1");
    if (c.max_samples < c.min_samples) {
        throw usage_error("the maximum sample count " + std::to_string(c.max_samples) +
                          " is below the minimum " + std::to_string(c.min_samples));
    }
    if (!std::isfinite(c.threshold_w_per_cm2_sr_um)) {
        throw usage_error("the convergence threshold must be a finite number");
    }
    if (!std::isfinite(batch.hypersampling_multiplier) || batch.hypersampling_multiplier < 1.0 ||
        batch.hypersampling_multiplier > 1e9) {
        throw usage_error("the hypersampling multiplier must be a number in [1, 1e9]");
    }
    if (batch.reference_band >= tracer.bands()) {
        throw usage_error("reference band " + std::to_string(batch.reference_band) +
                          " is out of range for " + std::to_string(tracer.bands()) + " bands");
    }
}

/// The batch's convergence, multiplied for a hypersampled problem.
Convergence effective_convergence(const ProblemBatch& batch, std::uint64_t problem) {
    Convergence c = batch.convergence;
    const std::uint64_t slot = problem - batch.first_problem;
    if (problem >= batch.first_problem && slot < batch.hypersampled.size() &&
        batch.hypersampled[slot] != 0 && batch.hypersampling_multiplier > 1.0) {
        const double m = batch.hypersampling_multiplier;
        c.min_samples =
            static_cast<std::uint64_t>(std::ceil(static_cast<double>(c.min_samples) * m));
        c.max_samples =
            static_cast<std::uint64_t>(std::ceil(static_cast<double>(c.max_samples) * m));
    }
    return c;
}

/// Solves `problem` into `radiance` (bands values); returns the sample count and the standard
/// error at the reference band.
std::pair<std::uint64_t, double> solve_into(const PathTracer& tracer, const ProblemBatch& batch,
                                            std::uint64_t problem, Workspace& ws,
                                            std::span<double> radiance) {
    const Convergence c = effective_convergence(batch, problem);
    const StreamKey& k = batch.key;
    std::fill(ws.sum.begin(), ws.sum.end(), 0.0);
    double weight_sum = 0.0;
    double weight_sq_sum = 0.0;
    WeightedMoments reference;  // at the reference band
    std::uint64_t n = 0;
    if (ws.recorder) ws.recorder->begin(problem);
    while (n < c.max_samples) {
        RandomStream rng = sample_stream(k, problem, n);
        const SampleRay ray = batch.source->generate(problem, n, rng);
        if (!(ray.weight > 0.0) || !std::isfinite(ray.weight)) {
            throw input_error("sample " + std::to_string(n) + " of problem " +
                              std::to_string(problem) + " has weight " +
                              format_shortest(ray.weight) + "; weights must be finite and > 0");
        }
        tracer.trace(ray, rng, ws.path, ws.sample, ws.wants_first_hit ? &ws.first_hit : nullptr);
        if (ws.recorder) {
            ws.recorder->add(ray, ws.sample, ws.wants_first_hit ? &ws.first_hit : nullptr);
        }
        for (std::size_t b = 0; b < ws.sum.size(); ++b) ws.sum[b] += ray.weight * ws.sample[b];
        ++n;
        const double previous = reference.mean;
        weight_sum += ray.weight;
        weight_sq_sum += ray.weight * ray.weight;
        reference.add(ws.sample[batch.reference_band], ray.weight, weight_sum);
        if (n >= 2 && n >= c.min_samples && c.threshold_w_per_cm2_sr_um > 0.0 &&
            std::fabs(reference.mean - previous) < c.threshold_w_per_cm2_sr_um) {
            break;
        }
    }
    if (ws.recorder) ws.recorder->end(problem, n);
    for (std::size_t b = 0; b < radiance.size(); ++b) radiance[b] = ws.sum[b] / weight_sum;
    return {n, reference.standard_error(weight_sum, weight_sq_sum)};
}

}  // namespace

double WeightedMoments::standard_error(double weight_sum, double weight_sq_sum) const noexcept {
    const double effective = weight_sum * weight_sum / weight_sq_sum;
    return effective > 1.0 ? std::sqrt(std::max(0.0, spread / weight_sum) / (effective - 1.0))
                           : 0.0;
}

RandomStream sample_stream(const StreamKey& key, std::uint64_t problem, std::uint64_t sample) {
    if (key.spectral_state) {
        return RandomStream(
            key.seed, {key.plugin, key.task, key.capture, problem, sample, *key.spectral_state});
    }
    return RandomStream(key.seed, {key.plugin, key.task, key.capture, problem, sample});
}

std::size_t nearest_band(const SpectralGrid& grid, double wavelength_um) noexcept {
    const auto w = grid.wavelengths_um();
    std::size_t best = 0;
    for (std::size_t i = 1; i < w.size(); ++i) {
        if (std::fabs(w[i] - wavelength_um) < std::fabs(w[best] - wavelength_um)) best = i;
    }
    return best;
}

Solution solve(const PathTracer& tracer, const ProblemBatch& batch, std::uint64_t problem) {
    check_batch(tracer, batch);
    Workspace ws(tracer, batch);
    Solution solution;
    solution.radiance_w_per_cm2_sr_um.resize(tracer.bands());
    const auto [samples, error] =
        solve_into(tracer, batch, problem, ws, solution.radiance_w_per_cm2_sr_um);
    solution.samples = samples;
    solution.standard_error_w_per_cm2_sr_um = error;
    return solution;
}

namespace {

/// The parallel loop of both batch solves: problem i's radiance goes into into(i, ws), and
/// done(i, radiance, samples, error) is called once it is there (on the solving thread).
template <typename Into, typename Done>
std::uint64_t solve_batch(const PathTracer& tracer, const ProblemBatch& batch,
                          const Context& context, const Into& into, const Done& done) {
    check_batch(tracer, batch);
    const int threads =
        context.threads == 0 ? tbb::task_arena::automatic : static_cast<int>(context.threads);
    tbb::task_arena arena(threads);
    tbb::enumerable_thread_specific<Workspace> workspaces([&] { return Workspace(tracer, batch); });
    std::atomic<std::uint64_t> finished_count{0};
    std::mutex progress_mutex;
    const std::uint64_t report_every = std::max<std::uint64_t>(1, batch.count / 100);
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::uint64_t>(0, batch.count, 16),
                          [&](const tbb::blocked_range<std::uint64_t>& range) {
                              Workspace& ws = workspaces.local();
                              for (std::uint64_t i = range.begin(); i != range.end(); ++i) {
                                  if (context.cancel.cancelled()) return;
                                  const std::span<double> radiance = into(i, ws);
                                  const auto [samples, error] = solve_into(
                                      tracer, batch, batch.first_problem + i, ws, radiance);
                                  done(i, radiance, samples, error);
                                  const std::uint64_t finished = ++finished_count;
                                  if (finished % report_every == 0) {
                                      const std::lock_guard lock(progress_mutex);
                                      context.progress.update("radiance", finished, batch.count);
                                  }
                              }
                          });
    });
    context.cancel.throw_if_cancelled();
    std::uint64_t rays = 0;
    for (const Workspace& ws : workspaces) rays += ws.path.rays;
    context.progress.finish("radiance", batch.count);
    return rays;
}

}  // namespace

Solutions solve(const PathTracer& tracer, const ProblemBatch& batch, const Context& context) {
    check_batch(tracer, batch);
    Solutions out;
    out.bands = tracer.bands();
    out.radiance_w_per_cm2_sr_um.assign(batch.count * out.bands, 0.0);
    out.samples.assign(batch.count, 0);
    out.standard_error_w_per_cm2_sr_um.assign(batch.count, 0.0);
    // Each problem solves straight into its slot of the result.
    out.rays = solve_batch(
        tracer, batch, context,
        [&](std::uint64_t i, Workspace&) {
            return std::span<double>(out.radiance_w_per_cm2_sr_um.data() + i * out.bands,
                                     out.bands);
        },
        [&](std::uint64_t i, std::span<double>, std::uint64_t samples, double error) {
            out.samples[i] = samples;
            out.standard_error_w_per_cm2_sr_um[i] = error;
        });
    return out;
}

std::uint64_t solve_each(const PathTracer& tracer, const ProblemBatch& batch,
                         const Context& context, const SolutionReceiver& receive) {
    return solve_batch(
        tracer, batch, context,
        [](std::uint64_t, Workspace& ws) { return std::span<double>(ws.radiance); },
        [&](std::uint64_t i, std::span<double> radiance, std::uint64_t samples, double error) {
            receive(i, radiance, samples, error);
        });
}

}  // namespace glint::radiometry
