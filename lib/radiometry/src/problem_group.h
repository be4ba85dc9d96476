// SPDX-License-Identifier: Apache-2.0
// A group of pixel problems solved side by side by one worker (problem_group.cpp): the
// convergence loop of glint/radiometry/problem.h, one round of samples at a time, each
// round's rays traced as one Embree packet. problem.cpp drives the groups (one thread, or
// oneTBB over the batch).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "glint/core/cancel.h"
#include "glint/core/rng.h"
#include "glint/radiometry/path_tracer.h"
#include "glint/radiometry/problem.h"
#include "glint/radiometry/spectral_draw.h"
#include "glint/scene/geometry_scene.h"

namespace glint::radiometry::group {

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

/// Refuses a batch that cannot be solved: no ray source, a bad convergence or hypersampling
/// multiplier, a reference band out of range. Throws glint::Error (usage).
void check_batch(const PathTracer& tracer, const ProblemBatch& batch);

/// Where problem j of a group puts its radiance (a span of bands values).
using GroupInto = std::function<std::span<double>(std::size_t j, Workspace& ws)>;
/// Receives problem j of a group: its radiance, the bands that may be non-zero, its sample
/// count and standard error at the reference band.
using GroupDone = std::function<void(std::size_t j, std::span<double> radiance,
                                     std::span<const std::uint32_t> nonzero_bands,
                                     std::uint64_t samples, double standard_error)>;

/// Solves the `count` (≤ kLanes) problems first_problem … side by side, in rounds of one
/// sample each whose rays are traced as one packet; then, in order, problem j's radiance goes
/// into into(j) and done(j, radiance, nonzero bands, samples, error) is called. `cancel` (may
/// be null) is polled every round: once raised, the group returns with no problem done, so a
/// stop never waits for 16 long problems to converge.
void solve_group(const PathTracer& tracer, const ProblemBatch& batch, std::uint64_t first_problem,
                 std::size_t count, Workspace& ws, const CancelToken* cancel, const GroupInto& into,
                 const GroupDone& done);

}  // namespace glint::radiometry::group
