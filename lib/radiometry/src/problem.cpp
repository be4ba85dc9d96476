// SPDX-License-Identifier: Apache-2.0
// solve(): the per-pixel convergence loop, on one thread or in parallel over problems with
// oneTBB (glint/radiometry/problem.h).
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

namespace glint::radiometry {
namespace {

/// φ − 1, the golden ratio's fractional part: the step of the samples' spectral offsets.
constexpr double kGoldenRatioConjugate = 0.6180339887498948482;
/// The last stream id of a problem's spectral offset stream (no sample has this index).
constexpr std::uint64_t kSpectralDrawId = 0x5350454354524100ull;

/// Problems one worker solves side by side: their samples advance in rounds, and each round's
/// sample rays go to Embree as one packet (GeometryScene::intersect_packet), which traces a
/// camera's coherent rays about twice as fast as one at a time, and so do the sun shadow rays
/// of their first hits (GeometryScene::occluded_packet). Every problem gets the same
/// bits as when solved alone (its samples, streams and draws are its own).
constexpr std::size_t kLanes = scene::kPacketSize;

/// One problem's state in a group.
struct Lane {
    Lane(const PathTracer& tracer, const ProblemBatch& batch, bool spectral_sampling)
        : sum(tracer.bands()),
          recorder(batch.observer != nullptr ? batch.observer->make_recorder() : nullptr),
          reached(spectral_sampling ? tracer.bands() : 0) {}
    std::uint64_t problem = 0;
    Convergence convergence;
    std::optional<StreamPrefix> pixel;  ///< the streams of the problem's samples
    std::vector<double> sum;            ///< Σ w L per band
    double weight_sum = 0.0;
    double weight_sq_sum = 0.0;
    WeightedMoments reference;  ///< at the reference band
    std::uint64_t samples = 0;  ///< traced so far
    bool active = false;        ///< more samples to trace
    double spectral_u = 0.0;    ///< the next sample's spectral offset
    std::unique_ptr<SampleRecorder> recorder;
    /// Spectral sampling: the bands of `sum` the problem's samples reached so far (each once,
    /// flagged in `reached`); the others are still 0.
    std::vector<std::uint32_t> touched;
    std::vector<std::uint8_t> reached;
    /// The sample of the current round.
    std::optional<RandomStream> rng;
    SampleRay ray;
};

/// Per-thread buffers of the convergence loop (the "arena" of one worker).
struct Workspace {
    Workspace(const PathTracer& tracer, const ProblemBatch& batch)
        : path(tracer.environment().bands()),
          sample(tracer.bands()),
          radiance(tracer.bands()),
          wants_first_hit(batch.observer != nullptr && batch.observer->wants_first_hit()),
          draw(tracer.range().first, tracer.range().count, batch.reference_band,
               tracer.settings().spectral_samples),
          grid_bands(draw.active() ? draw.size() : 0),
          bands(grid_bands.size()),
          values(grid_bands.size()) {
        lanes.reserve(kLanes);
        for (std::size_t k = 0; k < kLanes; ++k) lanes.emplace_back(tracer, batch, draw.active());
    }
    PathScratch path;
    std::vector<double> sample;    ///< one sample's radiance
    std::vector<double> radiance;  ///< a problem's result, handed to the receiver
    bool wants_first_hit = false;
    FirstHit first_hit;
    SpectralDraw draw;                            ///< the wavelengths of a path (spectral sampling)
    std::vector<std::uint32_t> grid_bands;        ///< a path's drawn bands, grid indices
    std::vector<std::uint32_t> bands;             ///< the same, relative to the tracer's range
    std::vector<double> values;                   ///< the path's radiance at them
    std::vector<Lane> lanes;                      ///< the problems of the group being solved
    std::array<scene::PacketRay, kLanes> packet;  ///< a round's sample rays
    std::array<std::optional<scene::RayHit>, kLanes> hits;  ///< and their first hits
    std::array<std::size_t, kLanes> packet_lane{};          ///< the lane of each packet ray
    std::array<FirstSun, kLanes> suns;                      ///< the first vertices' sun draws
    std::array<scene::PacketRay, kLanes> shadows;           ///< the shadow rays they ask for
    std::array<bool, kLanes> blocked{};                     ///< and the answers
    std::array<std::size_t, kLanes> shadow_ray{};           ///< the packet ray of each shadow ray
};

/// Traces one sample of `lane` into its sums (weighted by the ray's weight) and returns its
/// radiance at the reference band; hands it to the recorder, if any, as a whole spectrum.
/// `primary_hit` is the ray's first hit and `sun` its first vertex's sun, already traced.
double trace_sample(const PathTracer& tracer, std::size_t reference_band,
                    const std::optional<scene::RayHit>& primary_hit, const FirstSun& sun,
                    Workspace& ws, Lane& lane) {
    FirstHit* first_hit = ws.wants_first_hit ? &ws.first_hit : nullptr;
    const SampleRay& ray = lane.ray;
    RandomStream& rng = *lane.rng;
    if (!ws.draw.active()) {
        tracer.trace(ray, rng, ws.path, ws.sample, first_hit, &primary_hit, &sun);
        if (lane.recorder) lane.recorder->add(ray, ws.sample, first_hit);
        for (std::size_t b = 0; b < lane.sum.size(); ++b) lane.sum[b] += ray.weight * ws.sample[b];
        return ws.sample[reference_band];
    }
    // Spectral sampling: the reference band (weight 1), then the drawn ones.
    ws.draw.draw(lane.spectral_u, ws.grid_bands, ws.bands);
    tracer.trace_bands(ray, rng, ws.path, ws.grid_bands, ws.values, first_hit, &primary_hit, &sun);
    const double drawn = ws.draw.weight();
    for (std::size_t j = 1; j < ws.values.size(); ++j) ws.values[j] *= drawn;
    for (std::size_t j = 0; j < ws.values.size(); ++j) {
        const std::uint32_t b = ws.bands[j];
        lane.sum[b] += ray.weight * ws.values[j];
        if (lane.reached[b] == 0) {
            lane.reached[b] = 1;
            lane.touched.push_back(b);
        }
    }
    if (lane.recorder) {
        std::fill(ws.sample.begin(), ws.sample.end(), 0.0);
        for (std::size_t j = 0; j < ws.values.size(); ++j) ws.sample[ws.bands[j]] = ws.values[j];
        lane.recorder->add(ray, ws.sample, first_hit);
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

/// Starts `problem` in `lane`.
void begin_problem(const ProblemBatch& batch, std::uint64_t problem, const SpectralDraw& draw,
                   Lane& lane) {
    const StreamKey& k = batch.key;
    lane.problem = problem;
    lane.convergence = effective_convergence(batch, problem);
    if (!draw.active()) {
        std::fill(lane.sum.begin(), lane.sum.end(), 0.0);
    } else {
        lane.touched.clear();  // the sums are kept at 0 between problems
    }
    lane.weight_sum = 0.0;
    lane.weight_sq_sum = 0.0;
    lane.reference = WeightedMoments{};
    lane.samples = 0;
    lane.active = lane.convergence.max_samples > 0;
    if (lane.recorder) lane.recorder->begin(problem);
    // The samples' streams share (seed, plugin, task, capture, problem): keyed once here,
    // each stream is the one sample_stream() gives.
    lane.pixel = StreamPrefix(k.seed, {k.plugin, k.task, k.capture}).extended(problem);
    // Spectral sampling: sample n's wavelengths come from u_n = (u_0 + n φ) mod 1, u_0 drawn
    // once per problem: each u_n is uniform (so each band is drawn with its probability), and
    // successive samples cover the spectrum evenly instead of at random.
    lane.spectral_u = 0.0;
    if (draw.active()) {
        RandomStream start = k.spectral_state
                                 ? lane.pixel->stream({kSpectralDrawId, *k.spectral_state})
                                 : lane.pixel->stream({kSpectralDrawId});
        lane.spectral_u = start.uniform();
    }
}

/// Draws the lane's next sample ray (from the sample's own stream).
void next_ray(const ProblemBatch& batch, Lane& lane) {
    const std::uint64_t n = lane.samples;
    const StreamKey& k = batch.key;
    lane.rng =
        k.spectral_state ? lane.pixel->stream({n, *k.spectral_state}) : lane.pixel->stream({n});
    lane.ray = batch.source->generate(lane.problem, n, *lane.rng);
    if (!(lane.ray.weight > 0.0) || !std::isfinite(lane.ray.weight)) {
        throw input_error("sample " + std::to_string(n) + " of problem " +
                          std::to_string(lane.problem) + " has weight " +
                          format_shortest(lane.ray.weight) + "; weights must be finite and > 0");
    }
}

/// Adds the traced sample (radiance `at_reference` at the reference band) to the lane's
/// moments and decides whether the problem has converged.
void count_sample(double at_reference, Lane& lane) {
    const Convergence& c = lane.convergence;
    lane.spectral_u += kGoldenRatioConjugate;
    if (lane.spectral_u >= 1.0) lane.spectral_u -= 1.0;
    const std::uint64_t n = ++lane.samples;
    const double previous = lane.reference.mean;
    lane.weight_sum += lane.ray.weight;
    lane.weight_sq_sum += lane.ray.weight * lane.ray.weight;
    lane.reference.add(at_reference, lane.ray.weight, lane.weight_sum);
    if (n >= c.max_samples ||
        (n >= 2 && n >= c.min_samples && c.threshold_w_per_cm2_sr_um > 0.0 &&
         std::fabs(lane.reference.mean - previous) < c.threshold_w_per_cm2_sr_um)) {
        lane.active = false;
    }
}

/// The lane's mean radiance into `radiance` (bands values); returns the sample count and the
/// standard error at the reference band. With spectral sampling, lane.touched then lists the
/// bands that are not 0, ascending.
std::pair<std::uint64_t, double> finish_problem(const SpectralDraw& draw, Lane& lane,
                                                std::span<double> radiance) {
    if (lane.recorder) lane.recorder->end(lane.problem, lane.samples);
    if (draw.active()) {
        // Only the reached bands are not 0 (0 / Σw is 0): divided, and their sums reset; the
        // list stays for the receiver until the lane's next problem.
        std::sort(lane.touched.begin(), lane.touched.end());
        std::fill(radiance.begin(), radiance.end(), 0.0);
        for (const std::uint32_t b : lane.touched) {
            radiance[b] = lane.sum[b] / lane.weight_sum;
            lane.sum[b] = 0.0;
            lane.reached[b] = 0;
        }
    } else {
        for (std::size_t b = 0; b < radiance.size(); ++b) {
            radiance[b] = lane.sum[b] / lane.weight_sum;
        }
    }
    return {lane.samples, lane.reference.standard_error(lane.weight_sum, lane.weight_sq_sum)};
}

/// Solves the `count` (≤ kLanes) problems first_problem … side by side, in rounds of one
/// sample each whose rays are traced as one packet; then, in order, problem j's radiance goes
/// into into(j) and done(j, radiance, nonzero bands, samples, error) is called. `cancel` (may
/// be null) is polled every round: once raised, the group returns with no problem done, so a
/// stop never waits for 16 long problems to converge.
template <typename Into, typename Done>
void solve_group(const PathTracer& tracer, const ProblemBatch& batch, std::uint64_t first_problem,
                 std::size_t count, Workspace& ws, const CancelToken* cancel, const Into& into,
                 const Done& done) {
    for (std::size_t j = 0; j < count; ++j) {
        begin_problem(batch, first_problem + j, ws.draw, ws.lanes[j]);
    }
    for (;;) {
        if (cancel != nullptr && cancel->cancelled()) return;
        std::size_t rays = 0;
        for (std::size_t j = 0; j < count; ++j) {
            Lane& lane = ws.lanes[j];
            if (!lane.active) continue;
            next_ray(batch, lane);
            ws.packet[rays] =
                scene::PacketRay{lane.ray.origin_m, lane.ray.direction, lane.ray.time_s};
            ws.packet_lane[rays] = j;
            ++rays;
        }
        if (rays == 0) break;
        const scene::GeometryScene& scene = tracer.scene();
        scene.intersect_packet(std::span(ws.packet).first(rays), std::span(ws.hits).first(rays));
        // The first vertices' sun shadow rays (towards one direction from neighbouring points)
        // as a second packet.
        std::size_t shadows = 0;
        for (std::size_t r = 0; r < rays; ++r) {
            Lane& lane = ws.lanes[ws.packet_lane[r]];
            ws.suns[r] = tracer.first_sun(lane.ray, ws.hits[r], *lane.rng, ws.wants_first_hit);
            if (!ws.suns[r].query) continue;
            ws.shadows[shadows] = ws.suns[r].ray;
            ws.shadow_ray[shadows] = r;
            ++shadows;
        }
        if (shadows > 0) {
            scene.occluded_packet(std::span(ws.shadows).first(shadows),
                                  std::span(ws.blocked).first(shadows));
            for (std::size_t q = 0; q < shadows; ++q)
                ws.suns[ws.shadow_ray[q]].blocked = ws.blocked[q];
        }
        for (std::size_t r = 0; r < rays; ++r) {
            Lane& lane = ws.lanes[ws.packet_lane[r]];
            count_sample(
                trace_sample(tracer, batch.reference_band, ws.hits[r], ws.suns[r], ws, lane), lane);
        }
    }
    for (std::size_t j = 0; j < count; ++j) {
        const std::span<double> radiance = into(j, ws);
        const auto [samples, error] = finish_problem(ws.draw, ws.lanes[j], radiance);
        done(j, radiance, std::span<const std::uint32_t>(ws.lanes[j].touched), samples, error);
    }
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
