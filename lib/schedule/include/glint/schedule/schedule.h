// SPDX-License-Identifier: Apache-2.0
// The capture schedule, after Figure 1 of S. D. Brown and A. A. Goodenough, "Plugin-driven
// sensor modeling of remote sensing imaging systems", IGARSS 2017 (docs/references.md): every
// enabled focal plane of every instrument of every BasicPlatform entry has a clock; its ticks
// inside each task window are captures; all captures are sorted by start time (ties: plugin,
// instrument, focal plane) and numbered. Schedules can be huge (a 10-hour task at a 10 kHz
// line rate is 3.6e8 captures), so captures are generated in order by a streaming generator
// and counted analytically; nothing holds them all in memory.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/diagnostics.h"
#include "glint/core/log.h"
#include "glint/model/platform.h"
#include "glint/model/scene.h"
#include "glint/model/simulation.h"
#include "glint/model/simulation_inputs.h"
#include "glint/model/tasks.h"
#include "glint/motion/pose_service.h"
#include "glint/schedule/clock_ticks.h"

namespace glint::schedule {

/// Run options that shape the schedule (the "Options" of the DIRSIG5 BasicPlatform manual's
/// "Usage" section, docs/references.md: `.jsim` values of output_folder/output_prefix take
/// precedence over these).
struct ScheduleOptions {
    std::optional<std::string> output_folder;  ///< --output_folder
    std::optional<std::string> output_prefix;  ///< --output_prefix
    double scale_resolution = 1.0;             ///< --scale_resolution: pixel counts × this
    std::uint64_t seed = 1;                    ///< jitter in the poses
    /// The scene origin the poses are placed about; when not set, the scene's origin
    /// (kDefaultSceneOrigin when it gives none).
    std::optional<motion::Geodetic> scene_origin;
};

/// One BasicPlatform entry of the simulation, loaded.
struct PluginSchedule {
    std::size_t plugin_index = 0;  ///< index in the .jsim's plugin_list
    std::string output_folder;     ///< effective (jsim value, else option, else "")
    std::string output_prefix;     ///< effective (jsim value, else option, else "")
    std::shared_ptr<const model::Platform> platform;
    model::TaskList tasks;
    std::shared_ptr<const motion::PoseService> poses;
};

/// One capturing focal plane (a clock): an enabled focal plane of any instrument (generic,
/// lidar, or a data recorder's: its clock is the recorder's sample clock). A data recorder
/// without a focal plane has no clock in the model and is skipped with a warning.
struct ClockedFocalPlane {
    std::size_t plugin = 0;             ///< index into Schedule::plugins()
    std::size_t instrument_index = 0;   ///< list_instruments order within the platform
    std::size_t focal_plane_index = 0;  ///< index within the instrument
    const model::Instrument* instrument = nullptr;
    /// Never null once loaded: every source is an enabled focal plane (a data recorder's
    /// own clock makes no source; docs/data-recorder.md).
    const model::FocalPlane* focal_plane = nullptr;
    std::size_t x_count = 0;  ///< pixel counts after scale_resolution
    std::size_t y_count = 0;  ///< rows; for TDI the stages (never scaled)
    /// Problems (pixels rendered) per capture: x_count · y_count, or x_count for TDI (the
    /// stages of one output pixel are one problem).
    std::uint64_t problems_per_capture = 0;
    double integration_time_s = 0.0;  ///< of one row, or of one TDI stage
    /// TDI stages (y_count) for a `tdi="true"` focal plane, else 1. Stage k integrates
    /// during [t0 + k·time, t0 + (k + 1)·time]: the capture's window is stages × time.
    std::size_t tdi_stages = 1;
    /// Lines of one capture's image: 1 for TDI, else y_count.
    std::size_t lines_per_capture() const { return tdi_stages > 1 ? 1 : y_count; }
    /// Length of a capture's integration window: integration_time_s × tdi_stages.
    double window_s() const { return integration_time_s * static_cast<double>(tdi_stages); }
    /// The rolling readout's line time (row j starts j × it after the tick); nullopt for a
    /// global shutter and for TDI arrays, whose stages are read once per capture.
    std::optional<double> rolling_line_time_s() const {
        if (tdi_stages > 1) return std::nullopt;
        return focal_plane->detector_array.rolling_line_time_s;
    }
    /// Trigger times (s after the reference) of an external clock, one period of them.
    std::vector<double> trigger_times_s;
    /// The focal plane's clock (same as focal_plane->detector_array.clock).
    const model::Clock& clock() const { return focal_plane->detector_array.clock; }
};

/// One capture.
struct Capture {
    std::uint64_t index = 0;          ///< global, over the whole schedule, in order
    std::size_t task_index = 0;       ///< within its plugin's task list
    std::uint64_t capture_index = 0;  ///< within its task, counting its own source's captures
    std::size_t source = 0;           ///< index into Schedule::sources()
    double t0_s = 0.0;                ///< integration window [t0, t1], s after the reference
    double t1_s = 0.0;
};

/// The loaded simulation: plugins, sources, and how to enumerate and name captures.
class Schedule {
public:
    /// The schedule of a loaded simulation (glint/inputs/load.h): a pose service per
    /// BasicPlatform entry (placed in the scene's frame, tracking the scene's instances), its
    /// sources, output names and clock ranges. The schedule shares the platforms and copies
    /// what else it needs: `inputs` may go away afterwards. Problems go to `diagnostics`;
    /// throws glint::Error (input) summarising them when there are errors, (usage) for a bad
    /// scale_resolution.
    static Schedule build(const model::SimulationInputs& inputs, const ScheduleOptions& options,
                          const Log& log, Diagnostics& diagnostics);

    const std::filesystem::path& simulation_file() const;
    /// The scene frame the poses are placed in (ScheduleOptions::scene_origin, else the
    /// scenes' origin, else kDefaultSceneOrigin).
    const motion::SceneFrame& frame() const;
    const std::vector<PluginSchedule>& plugins() const;
    const std::vector<ClockedFocalPlane>& sources() const;

    /// Number of captures of `source` in task `task` of its plugin (analytic: O(1) here, the
    /// clock ranges are computed at load). Throws glint::Error (usage) for an index out of
    /// range.
    std::uint64_t count(std::size_t source, std::size_t task) const;
    /// The ticks of `source` in task `task` of its plugin (capture i starts at time_s(i)).
    const ClockTicks& ticks(std::size_t source, std::size_t task) const;
    /// Total captures and total problems (pixels) over the schedule, without enumerating.
    std::uint64_t total_captures() const;
    std::uint64_t total_problems() const;

    /// Output file of a capture's image (`<imagefile>` schedule simulation/task/capture:
    /// `<folder>/<prefix><basename>[-tTTTT[-cCCCC]].<ext>`, 4-digit zero-based indices);
    /// empty when the capture method has no image file (a lidar without `<imagefile>`).
    std::filesystem::path image_file(const Capture& capture) const;
    /// Output files of the capture's enabled truth collections that have collectors, in order.
    std::vector<std::filesystem::path> truth_files(const Capture& capture) const;

    /// Streams the captures in schedule order: start time, then plugin, instrument, focal
    /// plane (i.e. source index), then task. One cursor per (source, task) with captures in
    /// a binary min-heap: O(log cursors) per capture, no allocation after captures().
    class Generator {
    public:
        /// Next capture, or nullopt at the end.
        std::optional<Capture> next();
        ~Generator();
        Generator(Generator&&) noexcept;

    private:
        friend class Schedule;
        struct State;
        explicit Generator(std::unique_ptr<State> state);
        std::unique_ptr<State> m_state;
    };
    /// A generator from the first capture. It refers to this schedule: keep the schedule
    /// alive (moving the schedule is fine) while it is used.
    Generator captures() const;

    Schedule(Schedule&&) noexcept;
    Schedule& operator=(Schedule&&) noexcept;
    ~Schedule();

private:
    Schedule();
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

/// Tick times of `clock` inside [start_s, stop_s] (both ends included; a tick within
/// kTickTolerance_s = 1e-9 s of either end counts as inside), in order, for a rate clock
/// (independent, or synchronous resolved against `clock_table`) or a trigger list (repeated
/// with the period trigger_period_s: the list's span plus its mean spacing; a single trigger
/// fires once). A zero-length window (start == stop) gives the one tick at start. Streaming
/// callers use ClockTicks; this helper materialises them (tests, small windows).
std::vector<double> clock_ticks(const model::Clock& clock,
                                const std::vector<model::MasterClock>& clock_table,
                                const std::vector<double>& trigger_times_s, double start_s,
                                double stop_s);

/// Output file name of `image` for capture `capture_index` of task `task_index`, with the
/// effective folder and prefix: `<folder>/<prefix><basename>.<ext>` (schedule simulation),
/// `…<basename>-tTTTT.<ext>` (task) or `…<basename>-tTTTT-cCCCC.<ext>` (capture); indices
/// zero-based, zero-padded to 4 digits and written in full beyond (t10000); no folder when
/// `folder` is empty; no `.` when the extension is empty.
std::filesystem::path output_file(const model::ImageFile& image, const std::string& folder,
                                  const std::string& prefix, std::size_t task_index,
                                  std::uint64_t capture_index);

}  // namespace glint::schedule
