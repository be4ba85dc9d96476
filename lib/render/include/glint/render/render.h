// SPDX-License-Identifier: Apache-2.0
// The capture loop of glint-render, after Figure 2 (the API callbacks of one capture) of
// S. D. Brown and A. A. Goodenough, "Plugin-driven sensor modeling of remote sensing imaging
// systems", IGARSS 2017 (docs/references.md): load the simulation (scenes, atmosphere, every
// BasicPlatform's platform, motion and tasks), walk its capture schedule in order, and for
// each capture: build what the capture needs (the Embree scene over the capture window when
// something in the scene moves, the environment — sun, sky, sensor path — at its time), hand
// one problem per pixel to the radiometry core, turn each converged spectral radiance into
// the output units of the focal plane, and append the capture's lines to its ENVI file, which
// is published when its last capture is in. Everything between tools and library goes through
// Context: log lines (the DIRSIG-style "Starting capture" block at info level), progress
// ("captures"), cancellation, threads and the seed.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "glint/atmosphere/atmosphere.h"
#include "glint/core/context.h"
#include "glint/model/processing.h"
#include "glint/model/simulation_inputs.h"
#include "glint/radiometry/path_tracer.h"
#include "glint/radiometry/problem.h"
#include "glint/scene/geometry_scene.h"
#include "glint/schedule/row_band.h"
#include "glint/schedule/schedule.h"

namespace glint::render {

/// Convergence used when neither --convergence nor the focal plane gives one.
inline constexpr radiometry::Convergence kDefaultConvergence{10, 100, 1e-6};

/// What glint-render was asked to do.
struct RenderOptions {
    schedule::ScheduleOptions schedule;  ///< folder, prefix, scale_resolution, seed
    /// --convergence; a focal plane's <convergence> overrides it.
    std::optional<radiometry::Convergence> convergence;
    bool split_channels =
        false;  ///< one spectral state per channel (a .jsim entry's split_channels wins)
    /// --radiance-only: stop at the radiometric product even where a detector model is
    /// configured (for those focal planes it is the photon product glint-detect reads).
    bool radiance_only = false;
    radiometry::TracerSettings tracer;
    scene::DeviceSettings device;
    /// glint's data folder, named in messages about its tables.
    std::filesystem::path data_dir;
    /// glint's data tables read from it (glint/inputs/data_tables.h): the solar spectrum, and
    /// the gas band-model table when the atmosphere needs it.
    atmosphere::DataTables data;
    /// Global capture indices to render (--schedule FILE); empty: all.
    std::set<std::uint64_t> only_captures;
    /// --rows A:B or a --by rows shard: only these lines of every capture (docs/scale.md). A
    /// file that then lacks lines or captures of the whole run is a *part*: its header says
    /// which (`glint part ...` keys) for glint-envi merge. None: every line.
    std::optional<schedule::RowBand> rows;
    /// Provenance written into every header (with the Context's command line).
    std::string version;
    /// DIRSIG's --log_info_filename: the capture list (captures, time windows, files) of the
    /// run, written atomically when the run ends (also for dry_run()); empty: none.
    std::filesystem::path log_info_file;
};

/// Statistics of one rendered capture.
struct CaptureReport {
    std::uint64_t index = 0;  ///< global schedule index
    std::uint64_t pixels = 0;
    std::uint64_t min_samples = 0;
    double mean_samples = 0.0;
    std::uint64_t max_samples = 0;
    std::uint64_t rays = 0;
    double seconds = 0.0;
};

/// What a render did (or, for dry_run(), would do).
struct RenderReport {
    std::vector<CaptureReport> captures;
    std::vector<std::filesystem::path> files;  ///< published (render) or planned (plan)
    std::uint64_t pixels = 0;
    /// Rough peak memory: scene (Embree ≈ 85 B per triangle plus meshes) and the largest band
    /// of lines a capture is rendered in (its pixels × (channels, twice with detection, +
    /// truth bands) × 8 B;
    /// a lidar pulse: pixels × (2 × (1 + gate samples) + bands) × 8 B), bytes.
    std::uint64_t memory_estimate_bytes = 0;
    scene::DeviceInfo device;
    /// The processing events of the focal planes with `<processing>` tasks, in firing order
    /// (docs/processing.md): fired by render(), listed by dry_run().
    std::vector<model::ProcessingEvent> events;
};

/// Receives a render's processing events (the manual's "Inline Processing"). on_plan() is
/// called once, before the first capture, with every event the run will fire; on_event()
/// at each, in order: *_started events before their capture is traced, *_completed ones after
/// its lines are written and its file, when complete, published. An exception thrown by
/// either stops the render (files not yet complete are discarded).
class RenderObserver {
public:
    virtual ~RenderObserver() = default;
    virtual void on_plan(const std::vector<model::ProcessingEvent>& events) = 0;
    virtual void on_event(const model::ProcessingEvent& event) = 0;
};

/// Renders a loaded simulation (glint/inputs/load.h reads the `.jsim` or `.sim` and every file
/// it names). Throws glint::Error: input for inputs glint cannot render (every problem is
/// logged, each with file:line), usage for bad options, io when an output cannot be written,
/// cancelled on an interrupt (every file not yet complete is discarded).
/// `observer`, when given, receives the processing events.
RenderReport render(model::SimulationInputs inputs, const RenderOptions& options,
                    const Context& context, RenderObserver* observer = nullptr);

/// Prepares everything like render() and returns the captures, pixel counts, output files and
/// memory estimate without tracing a ray (--dry-run).
RenderReport dry_run(model::SimulationInputs inputs, const RenderOptions& options,
                     const Context& context);

}  // namespace glint::render
