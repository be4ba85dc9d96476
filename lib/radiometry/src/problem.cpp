// SPDX-License-Identifier: Apache-2.0
// solve(), solve_each(): pixel problems solved on one thread or in parallel over groups of
// problems with oneTBB (glint/radiometry/problem.h); a group's convergence loop is
// problem_group.cpp's. Also the sample statistics and streams the loop uses.
#include "glint/radiometry/problem.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <mutex>
#include <optional>
#include <string>

#include "glint/core/cancel.h"
#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/radiometry/spectral_draw.h"
#include "problem_group.h"

namespace glint::radiometry {

using group::check_batch;
using group::kLanes;
using group::solve_group;
using group::Workspace;

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
    solve_group(
        tracer, batch, problem, 1, ws, nullptr,
        [&](std::size_t, Workspace&) {
            return std::span<double>(solution.radiance_w_per_cm2_sr_um);
        },
        [&](std::size_t, std::span<double>, std::span<const std::uint32_t>, std::uint64_t samples,
            double error) {
            solution.samples = samples;
            solution.standard_error_w_per_cm2_sr_um = error;
        });
    return solution;
}

namespace {

/// The parallel loop of both batch solves: problem i's radiance goes into into(i, ws), and
/// done(i, radiance, nonzero bands, samples, error) is called once it is there (on the
/// solving thread).
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
    // Groups of kLanes consecutive problems, each solved by one worker: the same groups
    // whatever the thread count.
    const std::uint64_t groups = (batch.count + kLanes - 1) / kLanes;
    arena.execute([&] {
        tbb::parallel_for(
            tbb::blocked_range<std::uint64_t>(0, groups, 1),
            [&](const tbb::blocked_range<std::uint64_t>& range) {
                Workspace& ws = workspaces.local();
                for (std::uint64_t g = range.begin(); g != range.end(); ++g) {
                    if (context.cancel.cancelled()) return;
                    const std::uint64_t first = g * kLanes;
                    const auto count = static_cast<std::size_t>(
                        std::min<std::uint64_t>(kLanes, batch.count - first));
                    solve_group(
                        tracer, batch, batch.first_problem + first, count, ws, &context.cancel,
                        [&](std::size_t j, Workspace& w) { return into(first + j, w); },
                        [&](std::size_t j, std::span<double> radiance,
                            std::span<const std::uint32_t> bands, std::uint64_t samples,
                            double error) { done(first + j, radiance, bands, samples, error); });
                    const std::uint64_t before = finished_count.fetch_add(count);
                    if ((before + count) / report_every != before / report_every) {
                        const std::lock_guard lock(progress_mutex);
                        context.progress.update("radiance", before + count, batch.count);
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
        [&](std::uint64_t i, std::span<double>, std::span<const std::uint32_t>,
            std::uint64_t samples, double error) {
            out.samples[i] = samples;
            out.standard_error_w_per_cm2_sr_um[i] = error;
        });
    return out;
}

std::uint64_t solve_each(const PathTracer& tracer, const ProblemBatch& batch,
                         const Context& context, const SolutionReceiver& receive) {
    return solve_batch(
        tracer, batch, context,
        [](std::uint64_t, Workspace& ws) { return std::span<double>(ws.radiance); }, receive);
}

}  // namespace glint::radiometry
