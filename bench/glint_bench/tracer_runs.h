// SPDX-License-Identifier: Apache-2.0
// The path tracer side of glint-bench: a tracer over the benchmark scene for a spectral grid
// of a given band count (spectrally flat materials, a flat sun and sky, so the paths and
// their ray counts do not depend on the band count and only the per-band work changes), and
// the timing of solve() over every pixel of the camera.
#pragma once

#include <cstddef>
#include <cstdint>

#include "glint/core/context.h"
#include "glint/core/spectral.h"
#include "glint/model/scene.h"
#include "glint/radiometry/environment.h"
#include "glint/radiometry/materials.h"
#include "glint/radiometry/path_tracer.h"
#include "glint/radiometry/problem.h"
#include "glint/scene/geometry_scene.h"

namespace glint::bench {

/// A path tracer of the scene on a grid of `bands` bands (one band: 0.55 µm; more: evenly
/// spaced over 0.4–2.5 µm). Neither copyable nor movable (the tracer holds references).
struct TracerRig {
    TracerRig(const model::Scene& scene, const scene::GeometryScene& geometry, std::size_t bands,
              radiometry::TracerSettings settings = {});
    TracerRig(const TracerRig&) = delete;
    TracerRig& operator=(const TracerRig&) = delete;

    SpectralGrid grid;
    radiometry::MaterialTable materials;
    radiometry::Environment environment;
    radiometry::PathTracer tracer;
};

/// One timed solve() of a whole image.
struct TracerTiming {
    double seconds = 0.0;
    std::uint64_t rays = 0;   ///< Solutions::rays: primary, bounce and shadow rays
    std::uint64_t paths = 0;  ///< samples traced
    /// A hash of every radiance value's bits (time_tracer only): equal hashes, equal results.
    std::uint64_t radiance_hash = 0;
    double rays_per_s() const noexcept { return seconds > 0.0 ? double(rays) / seconds : 0.0; }
    double paths_per_s() const noexcept { return seconds > 0.0 ? double(paths) / seconds : 0.0; }
};

/// Solves problems 0 … count − 1 of `source` with `samples` samples each (a fixed count, no
/// convergence test) on `threads` threads, one solve() call per `tile` problems (as a
/// renderer solves an image tile by tile), and does that `repeats` times; returns the fastest
/// run. `context` supplies the log, progress and cancel flag; its thread count is replaced.
/// The radiance hash is computed outside the timed calls.
TracerTiming time_tracer(const radiometry::PathTracer& tracer, const radiometry::RaySource& source,
                         std::uint64_t count, std::uint64_t samples, std::uint64_t tile,
                         const radiometry::StreamKey& key, unsigned threads, unsigned repeats,
                         const Context& context);

/// Like time_tracer, but the way glint-render solves a capture: solve_each() hands each
/// pixel's spectrum to a receiver that integrates it into one value (a channel over every
/// band, as the render reduces spectra to channels) and keeps that alone, so no spectrum of
/// the image is stored. The radiance hash covers the integrated values.
TracerTiming time_reduced(const radiometry::PathTracer& tracer, const radiometry::RaySource& source,
                          std::uint64_t count, std::uint64_t samples, std::uint64_t tile,
                          const radiometry::StreamKey& key, unsigned threads, unsigned repeats,
                          const Context& context);

/// Like time_tracer, but calls PathTracer::trace() directly (one RandomStream per sample,
/// keyed as solve() keys it, so the same paths), keeping no sums and writing no output: the
/// tracer's own cost, without solve()'s accumulation and result buffers.
TracerTiming time_trace_only(const radiometry::PathTracer& tracer,
                             const radiometry::RaySource& source, std::uint64_t count,
                             std::uint64_t samples, const radiometry::StreamKey& key,
                             unsigned threads, unsigned repeats);

}  // namespace glint::bench
