// SPDX-License-Identifier: Apache-2.0
// Time-resolved laser returns for a lidar receiver (docs/lidar.md, "Model").
//
// The laser is a point source at the transmitter's position firing one pulse of energy E along
// its axis. Its far-field radiant exposure intensity is a Gaussian beam of full divergence θ
// (at 1/e² of the peak), I(α) = E · 2/(π w²) · exp(−2 α²/w²) J/sr with w = θ/2 and α the angle
// off the axis, which integrates to E over the sphere for small θ. A receiver path is traced
// from a pixel like the passive path tracer's (the same lobe sampling and Russian roulette), but
// at every surface vertex it looks at the laser by next-event estimation — one shadow ray — and
// adds the energy radiance the vertex returns, β ρ f(ωo, ωi) I(α) cos θi / r² [J/(cm² sr)], at
// the delay (receiver → … → vertex → laser path length) / c. That delay is spread over the
// gate's time samples by the pulse's temporal shape: sample j, covering [t_j, t_j+1) after the
// pulse's reference time, receives the share C(t_j+1 − delay) − C(t_j − delay), C the shape's
// cumulative energy fraction. The laser line is monochromatic for the path (ρ at its centre
// wavelength: a one-band material table).
//
// solve_returns() averages each problem's (pixel's) samples, weighted like the passive
// solve(), at a fixed number of samples, in parallel over problems; sample n of problem p
// draws from sample_stream(key, p, n), so results are the same for any thread count.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "glint/core/context.h"
#include "glint/core/rng.h"
#include "glint/core/units.h"
#include "glint/radiometry/materials.h"
#include "glint/radiometry/path_tracer.h"
#include "glint/radiometry/problem.h"
#include "glint/scene/geometry_scene.h"

namespace glint::radiometry {

/// The temporal shape of a pulse: the fraction C(t) of its energy emitted before t (s after
/// the pulse's reference time, its nominal firing time).
class PulseShape {
public:
    /// A Gaussian of full width at half maximum `fwhm_s`, centred on the reference time.
    /// Throws glint::Error (input) for a width that is not positive and finite.
    static PulseShape gaussian(double fwhm_s);
    /// A tabulated power P(t) (any scale: normalised to unit energy), linear between the
    /// points and 0 outside them; t in s after the reference time. Throws glint::Error
    /// (input) for fewer than 2 points, sizes that differ, times not increasing, negative or
    /// non-finite values, or no energy.
    static PulseShape tabulated(std::vector<double> time_s, std::vector<double> power);

    /// C(t): 0 before the pulse, 1 after it.
    double cumulative(double t_s) const noexcept;
    /// The pulse's extent: C is 0 (to 1e-9 for a Gaussian, 6 σ) before begin and 1 after end.
    double begin_s() const noexcept { return m_begin_s; }
    double end_s() const noexcept { return m_end_s; }

private:
    PulseShape() = default;
    double m_sigma_s = 0.0;            ///< Gaussian; 0: tabulated
    std::vector<double> m_time_s;      ///< tabulated nodes
    std::vector<double> m_power;       ///< normalised: ∫P dt = 1
    std::vector<double> m_cumulative;  ///< C at the nodes
    double m_begin_s = 0.0;
    double m_end_s = 0.0;
};

/// The receiver's time samples: sample j covers [start + j·width, start + (j + 1)·width) after
/// the pulse's reference time.
struct TimeGate {
    double start_s = 0.0;
    double sample_width_s = 0.0;
    std::size_t samples = 0;
};

/// Adds `value` arriving at `delay_s`, spread by `shape`, to `histogram` (gate.samples values):
/// sample j gets value · (C(t_j+1 − delay) − C(t_j − delay)). Shares outside the gate are
/// lost.
void deposit(const PulseShape& shape, const TimeGate& gate, double delay_s, double value,
             std::span<double> histogram) noexcept;

/// One pulse of the laser.
struct LaserPulse {
    Vec3 position_m;              ///< scene ENU, the transmitter's origin
    Vec3 axis{0.0, 0.0, -1.0};    ///< unit, scene ENU, the direction it fires
    double divergence_rad = 0.0;  ///< full angle at 1/e²
    double energy_j = 0.0;

    /// I(α), J/sr, towards the unit direction `d` (from the laser).
    double intensity_j_per_sr(const Vec3& d) const noexcept;
};

/// Traces receiver paths through a built scene with the laser as their light.
class LidarTracer {
public:
    /// `materials` hold one band: the laser's centre wavelength. Kept by reference (they and
    /// the scene must outlive the tracer); the pulse shape is copied. Throws glint::Error (input)
    /// for a table of another band count, (usage) for max_bounces above the tracer's limit or a
    /// gate without samples.
    LidarTracer(const scene::GeometryScene& scene, const MaterialTable& materials,
                TracerSettings settings, const PulseShape& shape, TimeGate gate);

    const TimeGate& gate() const noexcept { return m_gate; }

    /// Adds one path's returns from `ray` (a receiver sample), times its weight, to
    /// `histogram` (gate().samples values, J/(cm² sr)). Draws from `rng` only; counts its
    /// rays in `rays`.
    void trace(const SampleRay& ray, const LaserPulse& laser, RandomStream& rng,
               std::span<double> histogram, std::uint64_t& rays) const;

private:
    const scene::GeometryScene& m_scene;
    const MaterialTable& m_materials;
    TracerSettings m_settings;
    PulseShape m_shape;  ///< a copy: a temporary shape may be passed
    TimeGate m_gate;
};

/// The problems (pixels) of a pulse.
struct ReturnBatch {
    StreamKey key;
    const RaySource* source = nullptr;
    std::uint64_t count = 0;    ///< problems 0 … count − 1
    std::uint64_t samples = 1;  ///< per problem, ≥ 1
};

/// Each problem's weighted mean return (J/(cm² sr) per time sample), problems in order:
/// count × gate().samples values.
struct Returns {
    std::size_t samples_per_problem = 0;  ///< the gate's time samples
    std::vector<double> energy_j_per_cm2_sr;
    std::uint64_t rays = 0;
};

/// Solves a batch in parallel on context.threads threads (0: all), stopping with glint::Error
/// (cancelled) when context.cancel is raised. Throws glint::Error (usage) for a null source or
/// no samples, (input) for a sample of non-positive or non-finite weight.
Returns solve_returns(const LidarTracer& tracer, const LaserPulse& laser, const ReturnBatch& batch,
                      const Context& context);

}  // namespace glint::radiometry
