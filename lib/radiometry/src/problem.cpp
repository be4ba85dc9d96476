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
#include "glint/radiometry/spectral_draw.h"

namespace glint::radiometry {
namespace {

/// φ − 1, the golden ratio's fractional part: the step of the samples' spectral offsets.
constexpr double kGoldenRatioConjugate = 0.6180339887498948482;
/// The last stream id of a problem's spectral offset stream (no sample has this index).
constexpr std::uint64_t kSpectralDrawId = 0x5350454354524100ull;

/// Per-thread buffers of the convergence loop (the "arena" of one worker).
struct Workspace {
    Workspace(const PathTracer& tracer, const ProblemBatch& batch)
        : path(tracer.environment().bands()),
          sample(tracer.bands()),
          sum(tracer.bands()),
          radiance(tracer.bands()),
          recorder(batch.observer != nullptr ? batch.observer->make_recorder() : nullptr),
          wants_first_hit(batch.observer != nullptr && batch.observer->wants_first_hit()),
          draw(tracer.range().first, tracer.range().count, batch.reference_band,
               tracer.settings().spectral_samples),
          grid_bands(draw.active() ? draw.size() : 0),
          bands(grid_bands.size()),
          values(grid_bands.size()) {}
    PathScratch path;
    std::vector<double> sample;    ///< one sample's radiance
    std::vector<double> sum;       ///< Σ w L per band
    std::vector<double> radiance;  ///< the problem's result, handed to the receiver
    std::unique_ptr<SampleRecorder> recorder;
    bool wants_first_hit = false;
    FirstHit first_hit;
    SpectralDraw draw;                      ///< the wavelengths of a path (spectral sampling)
    std::vector<std::uint32_t> grid_bands;  ///< a path's drawn bands, grid indices
    std::vector<std::uint32_t> bands;       ///< the same, relative to the tracer's range
    std::vector<double> values;             ///< the path's radiance at them
    /// Spectral sampling: the bands of `sum` the problem's samples reached so far (each once,
    /// flagged in `reached`); the others are still 0.
    std::vector<std::uint32_t> touched;
    std::vector<std::uint8_t> reached = std::vector<std::uint8_t>(draw.active() ? sum.size() : 0);
};

/// Traces one sample into ws.sum (weighted by the ray's weight) and returns its radiance at the
/// reference band; hands it to the recorder, if any, as a whole spectrum.
double trace_sample(const PathTracer& tracer, const SampleRay& ray, RandomStream& rng,
                    std::size_t reference_band, double spectral_u, Workspace& ws) {
    FirstHit* first_hit = ws.wants_first_hit ? &ws.first_hit : nullptr;
    if (!ws.draw.active()) {
        tracer.trace(ray, rng, ws.path, ws.sample, first_hit);
        if (ws.recorder) ws.recorder->add(ray, ws.sample, first_hit);
        for (std::size_t b = 0; b < ws.sum.size(); ++b) ws.sum[b] += ray.weight * ws.sample[b];
        return ws.sample[reference_band];
    }
    // Spectral sampling: the reference band (weight 1), then the drawn ones.
    ws.draw.draw(spectral_u, ws.grid_bands, ws.bands);
    tracer.trace_bands(ray, rng, ws.path, ws.grid_bands, ws.values, first_hit);
    const double drawn = ws.draw.weight();
    for (std::size_t j = 1; j < ws.values.size(); ++j) ws.values[j] *= drawn;
    for (std::size_t j = 0; j < ws.values.size(); ++j) {
        const std::uint32_t b = ws.bands[j];
        ws.sum[b] += ray.weight * ws.values[j];
        if (ws.reached[b] == 0) {
            ws.reached[b] = 1;
            ws.touched.push_back(b);
        }
    }
    if (ws.recorder) {
        std::fill(ws.sample.begin(), ws.sample.end(), 0.0);
        for (std::size_t j = 0; j < ws.values.size(); ++j) ws.sample[ws.bands[j]] = ws.values[j];
        ws.recorder->add(ray, ws.sample, first_hit);
    }
    return ws.values[0];
}

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
    if (!ws.draw.active()) {
        std::fill(ws.sum.begin(), ws.sum.end(), 0.0);
    } else {
        ws.touched.clear();  // the sums are kept at 0 between problems
    }
    double weight_sum = 0.0;
    double weight_sq_sum = 0.0;
    WeightedMoments reference;  // at the reference band
    std::uint64_t n = 0;
    if (ws.recorder) ws.recorder->begin(problem);
    // The samples' streams share (seed, plugin, task, capture, problem): keyed once here,
    // each stream is the one sample_stream() gives.
    const StreamPrefix pixel =
        StreamPrefix(k.seed, {k.plugin, k.task, k.capture}).extended(problem);
    // Spectral sampling: sample n's wavelengths come from u_n = (u_0 + n φ) mod 1, u_0 drawn
    // once per problem: each u_n is uniform (so each band is drawn with its probability), and
    // successive samples cover the spectrum evenly instead of at random.
    double spectral_u = 0.0;
    if (ws.draw.active()) {
        RandomStream start = k.spectral_state ? pixel.stream({kSpectralDrawId, *k.spectral_state})
                                              : pixel.stream({kSpectralDrawId});
        spectral_u = start.uniform();
    }
    while (n < c.max_samples) {
        RandomStream rng =
            k.spectral_state ? pixel.stream({n, *k.spectral_state}) : pixel.stream({n});
        const SampleRay ray = batch.source->generate(problem, n, rng);
        if (!(ray.weight > 0.0) || !std::isfinite(ray.weight)) {
            throw input_error("sample " + std::to_string(n) + " of problem " +
                              std::to_string(problem) + " has weight " +
                              format_shortest(ray.weight) + "; weights must be finite and > 0");
        }
        const double at_reference =
            trace_sample(tracer, ray, rng, batch.reference_band, spectral_u, ws);
        spectral_u += kGoldenRatioConjugate;
        if (spectral_u >= 1.0) spectral_u -= 1.0;
        ++n;
        const double previous = reference.mean;
        weight_sum += ray.weight;
        weight_sq_sum += ray.weight * ray.weight;
        reference.add(at_reference, ray.weight, weight_sum);
        if (n >= 2 && n >= c.min_samples && c.threshold_w_per_cm2_sr_um > 0.0 &&
            std::fabs(reference.mean - previous) < c.threshold_w_per_cm2_sr_um) {
            break;
        }
    }
    if (ws.recorder) ws.recorder->end(problem, n);
    if (ws.draw.active()) {
        // Only the reached bands are not 0 (0 / Σw is 0): divided, and their sums reset; the
        // list stays (ascending) for the receiver until the next problem.
        std::sort(ws.touched.begin(), ws.touched.end());
        std::fill(radiance.begin(), radiance.end(), 0.0);
        for (const std::uint32_t b : ws.touched) {
            radiance[b] = ws.sum[b] / weight_sum;
            ws.sum[b] = 0.0;
            ws.reached[b] = 0;
        }
    } else {
        for (std::size_t b = 0; b < radiance.size(); ++b) radiance[b] = ws.sum[b] / weight_sum;
    }
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
    arena.execute([&] {
        tbb::parallel_for(
            tbb::blocked_range<std::uint64_t>(0, batch.count, 16),
            [&](const tbb::blocked_range<std::uint64_t>& range) {
                Workspace& ws = workspaces.local();
                for (std::uint64_t i = range.begin(); i != range.end(); ++i) {
                    if (context.cancel.cancelled()) return;
                    const std::span<double> radiance = into(i, ws);
                    const auto [samples, error] =
                        solve_into(tracer, batch, batch.first_problem + i, ws, radiance);
                    done(i, radiance, std::span<const std::uint32_t>(ws.touched), samples, error);
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
        [](std::uint64_t, Workspace& ws) { return std::span<double>(ws.radiance); },
        [&](std::uint64_t i, std::span<double> radiance, std::span<const std::uint32_t>,
            std::uint64_t samples, double error) { receive(i, radiance, samples, error); });
}

std::uint64_t solve_each(const PathTracer& tracer, const ProblemBatch& batch,
                         const Context& context, const SparseSolutionReceiver& receive) {
    return solve_batch(
        tracer, batch, context,
        [](std::uint64_t, Workspace& ws) { return std::span<double>(ws.radiance); }, receive);
}

}  // namespace glint::radiometry
