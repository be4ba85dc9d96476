// SPDX-License-Identifier: Apache-2.0
// solve_group (problem_group.h): a group of pixel problems advanced side by side, one sample
// of each per round, the round's camera rays and first-vertex sun shadow rays traced as Embree
// packets; each problem keeps its own streams, so it gets the bits it gets when solved alone.
#include "problem_group.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/radiometry/mixture_draw.h"

namespace glint::radiometry::group {
namespace {

/// φ − 1, the golden ratio's fractional part: the step of the samples' spectral offsets.
constexpr double kGoldenRatioConjugate = 0.6180339887498948482;
/// The last stream id of a problem's spectral offset stream (no sample has this index).
constexpr std::uint64_t kSpectralDrawId = 0x5350454354524100ull;

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

}  // namespace

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

void solve_group(const PathTracer& tracer, const ProblemBatch& batch, std::uint64_t first_problem,
                 std::size_t count, Workspace& ws, const CancelToken* cancel, const GroupInto& into,
                 const GroupDone& done) {
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
            if (ws.hits[r]) draw_mixture_material(scene, *ws.hits[r], *lane.rng);
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

}  // namespace glint::radiometry::group
