// SPDX-License-Identifier: Apache-2.0
// Jitter synthesis: the deterministic time series of unprogrammed motion. One JitterSeries is
// one degree of freedom — uncorrelated normal deviates keyed by the sample time, or a
// correlated series synthesised from a one-sided PSD with an inverse FFT — and the samplers
// bundle the six of platform jitter (model::PlatformJitter) and the three of mount jitter
// (model::RotationDeviates). Everything is keyed by (seed, stream ids), so the same inputs give
// the same values on any thread. docs/motion.md ("Jitter") has the formulas.
//
// Parameters read from the model (units as the model stores them):
//
// | field | type | unit | meaning |
// |---|---|---|---|
// | `kind` | none, normal, psd | | none: 0 everywhere |
// | `mean` / `mean_rad` | number | m or rad | added to both kinds |
// | `stddev` / `stddev_rad` | number ≥ 0 | m or rad | normal: σ of each sample |
// | `psd` (inline) or `psd_file` | PSD table | unit²/Hz, Hz | psd: see psd_reader.h |
//
// Stream ids: a sampler appends {domain, axis} to the caller's ids (e.g. {plugin} or
// {plugin, mount index}); domain is kJitterDomainPlatformLocation, …Orientation or …Mount and
// axis 0, 1, 2 for x, y, z.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "glint/core/rng.h"
#include "glint/model/jitter.h"
#include "glint/model/platform.h"
#include "glint/motion/geometry.h"

namespace glint::motion {

/// Stream-id domains appended by the samplers.
inline constexpr std::uint64_t kJitterDomainPlatformLocation = 1;
inline constexpr std::uint64_t kJitterDomainPlatformOrientation = 2;
inline constexpr std::uint64_t kJitterDomainMount = 3;

/// Time quantum of uncorrelated jitter: times closer than this share a deviate.
inline constexpr double kJitterTimeQuantumS = 1e-9;

/// One degree of freedom of jitter, independent of where it was read from.
struct JitterModel {
    enum class Kind { none, normal, psd };
    Kind kind = Kind::none;
    double mean = 0.0;                     ///< m or rad; added for normal and psd
    double stddev = 0.0;                   ///< normal: σ per sample (m or rad)
    const model::PsdTable* psd = nullptr;  ///< psd: the table (must outlive construction only)
    ErrorContext where;                    ///< where the jitter was specified, for errors
};

/// How a PSD series is sampled (see docs/motion.md ("Jitter"), "Sampling").
struct JitterSynthesisOptions {
    double oversampling = 10.0;          ///< preferred sample rate / highest PSD frequency
    double min_oversampling = 2.5;       ///< the least accepted when the span needs more samples
    std::size_t min_samples = 4096;      ///< the fewest samples synthesised (a power of two)
    std::size_t max_samples = 1u << 22;  ///< the most (a power of two); beyond it is an error
};

/// The one-sided PSD of `table` at `frequency_hz`: log-log interpolation between neighbouring
/// rows where both PSD values and both frequencies are positive, linear otherwise; 0 outside
/// [first, last] frequency. The table must be valid (model::validate_psd_table).
double psd_at(const model::PsdTable& table, double frequency_hz) noexcept;

/// The phase of `table` at `frequency_hz` (rad): linear interpolation of the phase column,
/// held constant beyond the ends; 0 when the table has no phases.
double psd_phase_at(const model::PsdTable& table, double frequency_hz) noexcept;

/// ∫ S(f) df of the interpolated PSD over [f0_hz, f1_hz], exact for both interpolation laws.
double psd_integral(const model::PsdTable& table, double f0_hz, double f1_hz) noexcept;

/// The jitter of one degree of freedom over a time span. Immutable after construction:
/// value_at is thread-safe and allocates nothing.
///
/// - none: value_at gives 0.
/// - normal: value_at(t) = mean + σ·z, z the first standard normal of the RandomStream
///   (seed, ids) positioned at block q = round(t / 1 ns) (as a two's-complement 64-bit
///   integer), so equal times give equal values on any thread and times ≥ 1 ns apart are
///   independent. The span is not used.
/// - psd: a real series of N samples at rate fs covering at least [t0, t1], synthesised once
///   (random-phase spectral synthesis, variance Σ S(f_k)·Δf ≈ ∫S df), plus the mean;
///   value_at interpolates linearly between samples, and the series repeats with period
///   N / fs outside [t0, t0 + N/fs).
class JitterSeries {
public:
    using Kind = JitterModel::Kind;

    /// A series that is 0 everywhere.
    JitterSeries() = default;

    /// Builds the series of `model` for times [t0_s, t1_s] from the stream (seed, stream_ids).
    /// Throws glint::Error (input) for a non-finite mean, a negative or non-finite σ, a
    /// missing or invalid PSD table (at the table's file:line), t1 < t0 or non-finite times,
    /// or a span that needs more than options.max_samples samples even at the minimum
    /// oversampling.
    JitterSeries(const JitterModel& model, std::uint64_t seed,
                 const std::vector<std::uint64_t>& stream_ids, double t0_s, double t1_s,
                 const JitterSynthesisOptions& options = {});

    /// The jitter at time `t_s` (m or rad). NaN for a non-finite time.
    double value_at(double t_s) const noexcept;

    Kind kind() const noexcept { return m_kind; }
    double mean() const noexcept { return m_mean; }
    /// normal: σ; psd: the standard deviation of the synthesised series.
    double stddev() const noexcept;

    /// psd: the synthesised samples (mean included), sample n at time t0 + n / fs.
    const std::vector<double>& samples() const noexcept { return m_samples; }
    /// psd: the sample rate fs (Hz); 0 otherwise.
    double sample_rate_hz() const noexcept { return m_sample_rate_hz; }
    /// psd: the period N / fs (s) after which the series repeats; 0 otherwise.
    double period_s() const noexcept;
    /// psd: the start of the series (s).
    double t0_s() const noexcept { return m_t0_s; }
    /// psd: the variance put into the series, Σ S(f_k)·Δf over bins 1 … N/2 − 1.
    double synthesized_variance() const noexcept { return m_synthesized_variance; }
    /// psd: ∫ S(f) df of the whole table (what synthesized_variance approximates; content
    /// below 1/period or at and above fs/2 is not represented).
    double psd_variance() const noexcept { return m_psd_variance; }

private:
    Kind m_kind = Kind::none;
    double m_mean = 0.0;
    double m_stddev = 0.0;
    RandomStream m_stream{0, {}};  ///< normal: the base stream, copied per call
    std::vector<double> m_samples;
    double m_sample_rate_hz = 0.0;
    double m_t0_s = 0.0;
    double m_synthesized_variance = 0.0;
    double m_psd_variance = 0.0;
};

/// Converts a model::JitterSpec into a JitterModel, pointing at its PSD table (given inline, or
/// read from its file by the input loader). Throws glint::Error (input) for a psd spec
/// without a table.
/// without a table. Platform jitter axes and mount jitter axes alike.
JitterModel jitter_model(const model::JitterSpec& spec);

/// Samples six-degree-of-freedom platform jitter.
class PlatformJitterSampler {
public:
    /// No jitter.
    PlatformJitterSampler() = default;
    /// Builds the six series over [t0_s, t1_s]; axis i of location uses stream ids
    /// stream_ids + {kJitterDomainPlatformLocation, i}, orientation likewise. Throws as
    /// JitterSeries and jitter_model do.
    PlatformJitterSampler(const model::PlatformJitter& jitter, std::uint64_t seed,
                          const std::vector<std::uint64_t>& stream_ids, double t0_s, double t1_s,
                          const JitterSynthesisOptions& options = {});

    /// Location offset (m, scene ENU) and orientation offset (rad, about vehicle x, y, z).
    struct Sample {
        Vec3 location_m;
        Vec3 orientation_rad;
    };
    /// The jitter at `t_s`; thread-safe.
    Sample at(double t_s) const noexcept;

    /// True when any axis jitters.
    bool any() const noexcept;
    const JitterSeries& location(std::size_t axis) const { return m_location.at(axis); }
    const JitterSeries& orientation(std::size_t axis) const { return m_orientation.at(axis); }

private:
    std::array<JitterSeries, 3> m_location;
    std::array<JitterSeries, 3> m_orientation;
};

/// Samples the pointing jitter of one mount (`<rotationdeviates>`: x = along-track,
/// y = across-track, z).
class MountJitterSampler {
public:
    /// No jitter.
    MountJitterSampler() = default;
    /// Builds the three series over [t0_s, t1_s]; axis i uses stream ids
    /// stream_ids + {kJitterDomainMount, i} (put the mount's identity in stream_ids). Throws as
    /// JitterSeries and jitter_model do.
    MountJitterSampler(const model::RotationDeviates& deviates, std::uint64_t seed,
                       const std::vector<std::uint64_t>& stream_ids, double t0_s, double t1_s,
                       const JitterSynthesisOptions& options = {});

    /// Rotation offsets about x, y, z (rad) at `t_s`; thread-safe.
    Vec3 at(double t_s) const noexcept;

    /// True when any axis jitters.
    bool any() const noexcept;
    const JitterSeries& axis(std::size_t axis) const { return m_axes.at(axis); }

private:
    std::array<JitterSeries, 3> m_axes;
};

}  // namespace glint::motion
