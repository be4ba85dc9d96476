// SPDX-License-Identifier: Apache-2.0
// What glint-bench measures and reports: it builds the procedural scene twice (GeometryScene
// for the tracer, a bare two-level Embree scene for the baseline), then, on the same threads,
// times bare rtcIntersect1 on the camera's primary rays and on incoherent bounce rays, the
// path tracer on the same camera, both again on one thread, and the tracer at 1, 16, 256 and 2,100
// bands. The result is one JSON document (docs/performance.md explains every figure).
#pragma once

#include <chrono>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "glint/core/context.h"
#include "procedural_scene.h"

namespace glint::bench {

/// Seconds of wall-clock time since `start` (the steady clock every timing here uses).
inline double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Options of glint-bench.
struct BenchOptions {
    unsigned image_size = 1024;  ///< the camera's image is image_size × image_size pixels
    unsigned samples = 1;        ///< samples per pixel
    /// Pixels per solve() call (a 64 × 64 tile); each call allocates its own result arrays.
    unsigned tile = 4096;
    unsigned bands = 16;  ///< band count of the ratio and thread-scaling runs
    /// Wavelengths per path of the spectrally sampled band-cost runs (--spectral-samples).
    unsigned spectral_samples = 4;
    unsigned repeats = 1;           ///< tracer runs: the fastest of this many
    double min_bare_seconds = 2.0;  ///< bare Embree: passes over the rays for at least this long
    SceneParameters scene;
    std::string command_line;  ///< for the provenance
};

/// The tiny sizes of --quick (a smoke run of a second or two).
BenchOptions quick_options();

/// Runs every measurement with context.threads threads (0: all hardware threads) and the
/// seed context.seed; returns the report. Throws glint::Error from the scene build or the
/// tracer.
nlohmann::ordered_json run_benchmark(const BenchOptions& options, const Context& context);

}  // namespace glint::bench
