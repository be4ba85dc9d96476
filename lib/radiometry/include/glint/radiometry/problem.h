// SPDX-License-Identifier: Apache-2.0
// Pixel problems, as DIRSIG5's sensor plugins hand them to the core: a problem is a pixel
// (or any radiometric measurement) whose sample rays a RaySource generates, with a
// convergence rule; solve() traces sample after sample until the rule is met and returns the
// weighted mean spectral radiance, the sample count and the standard error at the reference
// wavelength.
//
// Convergence (docs/physics.md, "Pixel problems and convergence"): after at least
// min_samples, stop when the weighted mean radiance at the reference band changed by less
// than threshold (absolute, W/(cm² sr µm)) between N − 1 and N samples; always stop at
// max_samples. The weighted mean is Σ wᵢ Lᵢ / Σ wᵢ; its standard error uses the weighted
// variance and Kish's effective sample size (Σw)²/Σw².
//
// Determinism: sample n of problem p draws every random number (the RaySource's first, then
// the tracer's) from RandomStream(seed, {plugin, task, capture, p, n}), or, for a spectral
// state s of a focal plane whose channels are split, RandomStream(seed, {plugin, task,
// capture, p, n, s}). A problem is solved by one thread in sample order, so the results are
// bit-identical for any thread count.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "glint/core/context.h"
#include "glint/core/rng.h"
#include "glint/radiometry/path_tracer.h"

namespace glint::radiometry {

/// Where a set of problems sits in a simulation: the stream key's leading parts.
struct StreamKey {
    std::uint64_t seed = kDefaultSeed;
    std::uint64_t plugin = 0;
    std::uint64_t task = 0;
    std::uint64_t capture = 0;
    /// The spectral state when a focal plane's channels are split (one state per channel);
    /// none when the focal plane is one state.
    std::optional<std::uint64_t> spectral_state;
};

/// The random stream of sample `sample` of problem `problem` (the Determinism rule above).
RandomStream sample_stream(const StreamKey& key, std::uint64_t problem, std::uint64_t sample);

/// The convergence rule of a problem.
struct Convergence {
    std::uint64_t min_samples = 1;
    std::uint64_t max_samples = 1;
    double threshold_w_per_cm2_sr_um = 0.0;  ///< ≤ 0: always max_samples
};

/// Generates the sample rays of problems. generate() is called concurrently from many
/// threads and must depend only on its arguments (and draw only from `rng`).
class RaySource {
public:
    virtual ~RaySource() = default;
    /// Sample `sample` (0-based) of problem `problem`.
    virtual SampleRay generate(std::uint64_t problem, std::uint64_t sample,
                               RandomStream& rng) const = 0;
};

/// The result of one problem.
struct Solution {
    std::vector<double> radiance_w_per_cm2_sr_um;  ///< weighted mean, one per band
    std::uint64_t samples = 0;
    double standard_error_w_per_cm2_sr_um = 0.0;  ///< at the reference band
};

/// The results of problems first … first + count − 1, flat: radiance[i · bands + b].
struct Solutions {
    std::size_t bands = 0;
    std::vector<double> radiance_w_per_cm2_sr_um;
    std::vector<std::uint64_t> samples;
    std::vector<double> standard_error_w_per_cm2_sr_um;
    std::uint64_t rays = 0;  ///< rays traced in all (primary, bounce and shadow; statistics)

    std::span<const double> radiance(std::size_t i) const noexcept {
        return {radiance_w_per_cm2_sr_um.data() + i * bands, bands};
    }
};

/// The running weighted mean and spread of one value over a problem's samples (West 1979),
/// the statistic the convergence rule and the standard error use.
struct WeightedMoments {
    double mean = 0.0;
    double spread = 0.0;  ///< Σ w (x − mean)² so far
    /// Adds `x` of weight `weight`; `weight_sum` is Σ w including it.
    void add(double x, double weight, double weight_sum) noexcept {
        const double previous = mean;
        mean += (weight / weight_sum) * (x - previous);
        spread += weight * (x - previous) * (x - mean);
    }
    /// The standard error of the weighted mean, √(spread / Σw / (n_eff − 1)) with Kish's
    /// effective sample size n_eff = (Σw)² / Σw²; 0 when n_eff ≤ 1.
    double standard_error(double weight_sum, double weight_sq_sum) const noexcept;
};

/// Sees every sample of the problems of one thread, in sample order (truth collection,
/// docs/truth.md). A recorder is used by one thread at a time.
class SampleRecorder {
public:
    virtual ~SampleRecorder() = default;
    /// A problem starts.
    virtual void begin(std::uint64_t problem) = 0;
    /// One sample: its ray (and weight), its radiance (the tracer's bands), its first hit
    /// when the observer wants it (else null).
    virtual void add(const SampleRay& ray, std::span<const double> radiance,
                     const FirstHit* first_hit) = 0;
    /// The problem took `samples` samples.
    virtual void end(std::uint64_t problem, std::uint64_t samples) = 0;
};

/// Makes the recorders of a batch's threads; recorders of different threads run at once on
/// different problems.
class SampleObserver {
public:
    virtual ~SampleObserver() = default;
    /// Whether the recorders need each sample's first hit.
    virtual bool wants_first_hit() const noexcept = 0;
    /// A recorder for one thread.
    virtual std::unique_ptr<SampleRecorder> make_recorder() const = 0;
};

/// A batch of problems that share a ray source and a convergence rule.
struct ProblemBatch {
    StreamKey key;
    const RaySource* source = nullptr;
    Convergence convergence;
    std::size_t reference_band = 0;  ///< the band the convergence rule watches
    std::uint64_t first_problem = 0;
    std::uint64_t count = 0;
    /// Hypersampling (the ::IMPORTANT:: targets of the DIRSIG5 BasicPlatform manual,
    /// docs/references.md): problems whose entry is non-zero (indexed by problem −
    /// first_problem; empty: none) take min and max samples × hypersampling_multiplier
    /// (rounded up), the threshold unchanged.
    std::span<const std::uint8_t> hypersampled;
    double hypersampling_multiplier = 1.0;
    /// Sees every sample (truth collection); none: nothing is recorded. It does not change
    /// the radiance or the random numbers.
    const SampleObserver* observer = nullptr;
};

/// Index of the band nearest to `wavelength_um` (the lower one on a tie).
std::size_t nearest_band(const SpectralGrid& grid, double wavelength_um) noexcept;

/// Solves one problem on the calling thread. Throws glint::Error (usage) for min_samples
/// < 1, max_samples < min_samples, a reference band out of range, or a null source; (input)
/// for a sample with a non-positive or non-finite weight.
Solution solve(const PathTracer& tracer, const ProblemBatch& batch, std::uint64_t problem);

/// Solves a batch in parallel on context.threads threads (0: all), reporting progress as
/// "radiance" and stopping with glint::Error (cancelled) when context.cancel is raised.
/// Same errors as the single-problem solve.
Solutions solve(const PathTracer& tracer, const ProblemBatch& batch, const Context& context);

/// Receives each solved problem of a batch (solve_each): its index in the batch (0 … count −
/// 1), its radiance (one value per band, in a buffer of the solving thread that the receiver
/// may change and must not keep), the bands that may be non-zero (under spectral sampling,
/// TracerSettings::spectral_samples, the bands the problem's samples reached, ascending:
/// radiance is exactly 0 at every other band; empty when every band may be non-zero), its
/// sample count and its standard error at the reference band. Called from the solving
/// threads, once per index; calls for different indices run at the same time.
using SolutionReceiver =
    std::function<void(std::uint64_t index, std::span<double> radiance_w_per_cm2_sr_um,
                       std::span<const std::uint32_t> nonzero_bands, std::uint64_t samples,
                       double standard_error_w_per_cm2_sr_um)>;

/// Solves a batch like solve(tracer, batch, context) — the same numbers for every problem —
/// but hands each problem to `receive` as soon as it is solved instead of keeping it, so the
/// memory is the threads' buffers (bands values each), whatever the batch's size. Returns
/// the rays traced.
std::uint64_t solve_each(const PathTracer& tracer, const ProblemBatch& batch,
                         const Context& context, const SolutionReceiver& receive);

}  // namespace glint::radiometry
