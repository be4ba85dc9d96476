// SPDX-License-Identifier: Apache-2.0
// Internal pieces of the capture loop (glint/render/render.h): the render plan (plan_render:
// the loaded inputs, the selected captures, one state per focal plane that writes a file,
// then the output files), read-only while the captures are solved, reduced, detected and
// written.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "glint/core/spectral.h"
#include "glint/detect/chain.h"
#include "glint/io/envi.h"
#include "glint/model/atmosphere.h"
#include "glint/model/processing.h"
#include "glint/model/scene.h"
#include "glint/model/simulation.h"
#include "glint/model/simulation_inputs.h"
#include "glint/motion/frames.h"
#include "glint/radiometry/environment.h"
#include "glint/radiometry/illumination.h"
#include "glint/radiometry/lidar.h"
#include "glint/radiometry/materials.h"
#include "glint/radiometry/point_lights.h"
#include "glint/render/image_outputs.h"
#include "glint/render/render.h"
#include "glint/scene/facet_temperatures.h"
#include "glint/scene/geometry_scene.h"
#include "glint/scene/scene_motion.h"
#include "glint/sensor/camera.h"
#include "glint/sensor/hypersampling.h"
#include "glint/sensor/output_units.h"
#include "glint/sensor/pixel_ray_source.h"
#include "glint/sensor/point_sources_seen.h"
#include "glint/sensor/truth.h"

namespace glint::render::detail {

/// Everything read before the first capture.
struct RenderInputs {
    model::Simulation simulation;
    model::Scene scene;
    model::Atmosphere atmosphere;
    model::Weather weather;  ///< the simulation's weather history (THERM); empty: none
    motion::SceneFrame frame;
    std::optional<schedule::Schedule> schedule;
    /// The scene instances' trajectories: the Embree scene once, or per capture when
    /// something moves.
    std::optional<scene::SceneMotion> scene_motion;
    /// The sun or moon through the atmosphere, and the point sources.
    std::optional<radiometry::Illumination> light;
};

/// Takes over a loaded simulation (glint/inputs/load.h) and builds what the captures share:
/// the schedule (placed at the scene's origin), the scene's motion and the light (the
/// atmosphere model with options.data's solar spectrum and gas table, the point sources). Logs
/// every problem of the schedule; throws glint::Error (input) when there are errors.
RenderInputs make_render_inputs(model::SimulationInputs loaded, const RenderOptions& options,
                                const Context& context);

/// A spectral state, as the DIRSIG5 BasicPlatform manual's "Split Channels into States" has
/// it: the bands of the focal plane's grid that one set of sample paths follows, and the
/// band its convergence watches. A focal plane is one state (all its bands, all channels),
/// or, with split channels, one state per channel (the bands its response covers), each with
/// its own random streams (docs/camera.md, "Spectral states").
struct SpectralState {
    BandRange bands;
    std::size_t reference_band = 0;      ///< index into the focal plane's grid
    std::optional<std::size_t> channel;  ///< the channel it alone renders, when split
};

/// What a lidar receiver needs for every pulse (docs/lidar.md, "Model"): the transmitter's
/// pulse, the gate's time samples, the materials at the laser line and the factors that turn
/// the solved radiances into photons per pixel.
struct LidarState {
    const model::Transmitter* transmitter = nullptr;
    radiometry::PulseShape shape;
    radiometry::TimeGate gate;  ///< bins × samples per bin samples
    model::SignalGate signal_gate;
    SpectralGrid laser_grid;  ///< one band at the laser's centre wavelength
    radiometry::MaterialTable laser_materials;
    /// Detected photons per J/(cm² sr) of mean energy radiance at the aperture: the element
    /// area (cm²) / G# × QE × λ/(h c), times the active area's mean sensitivity.
    double photons_per_energy_radiance = 0.0;
    /// Passive photons/s per photons/s/cm² at the focal plane (the OutputUnits value): the
    /// element area (cm²) × QE × the active area's mean sensitivity.
    double passive_per_focal_plane_rate = 0.0;
    std::uint64_t samples_per_pixel = 1;  ///< the active returns' (the convergence maximum)
};

/// Builds the lidar state of a lidar receiver (its FocalPlaneState's grid, camera, units and
/// convergence already made). Throws glint::Error (input, at the element) for what glint
/// cannot render: a receiver without an aperture (focal length and aperture diameter), truth
/// collections on it, a bad pulse shape table.
LidarState make_lidar_state(const schedule::ClockedFocalPlane& source, const model::Scene& scene,
                            const sensor::CameraModel& camera,
                            const radiometry::Convergence& convergence, const Context& context);

/// What one focal plane needs for every capture.
struct FocalPlaneState {
    SpectralGrid grid;
    std::vector<SpectralState> spectral_states;  ///< one, or one per channel when split
    radiometry::MaterialTable materials;
    sensor::CameraModel camera;
    sensor::OutputUnits units;
    radiometry::Convergence convergence;
    io::EnviHeader header;  ///< header template (lines set when planned)
    /// In-render detection (detector model or colour filter array, unless --radiance-only):
    /// the chain glint-detect applies, fed with the capture's photon product line by line.
    std::optional<detect::DetectionChain> detection;
    /// The focal plane's <psf>, when it has one.
    std::optional<sensor::PsfSampler> psf;
    /// The focal plane's <activearea> mask, when it has one (each pixel's values are
    /// multiplied by its mean sensitivity).
    std::optional<sensor::ActiveArea> mask;
    /// Its truth collections that write a file (empty: none).
    sensor::TruthLayout truth;
    /// The band of `grid` nearest its centre: the reference wavelength of the convergence of
    /// an unsplit focal plane and of the Reflectance truth.
    std::size_t reference_band = 0;
    /// A lidar receiver's (docs/lidar.md); its `units` give the passive photon rate.
    std::optional<LidarState> lidar;
};

/// Builds the state of schedule source `source` (frame, pushbroom and TDI focal planes alike).
/// Throws glint::Error (input, at the element) for what glint cannot render: an instrument
/// without a focal length (CameraModel), a bad `<convergence>`, and, when the focal plane
/// detects (detector model, TDI or colour filter array, unless --radiance-only), what
/// detect::resolve_detection refuses.
FocalPlaneState make_focal_plane_state(const RenderInputs& inputs, std::size_t source,
                                       const RenderOptions& options, const Context& context);

/// Whether the channels of the focal planes of plugin entry `plugin_index` are split: the
/// BasicPlatform entry's split_channels when it has one, else the option.
bool splits_channels(const RenderInputs& inputs, std::size_t plugin_index,
                     const RenderOptions& options);

/// Whether a schedule source produces an image glint renders (a generic instrument's
/// enabled focal plane with an image file); `why` gets the reason when not.
bool renders(const schedule::ClockedFocalPlane& source, std::string& why);

/// A capture of the selection with what the loop needs about it.
/// The most captures one glint-render run plans (the plan keeps each, ~200 bytes); more is
/// refused before planning, with the advice to shard (docs/tools/glint-render.md).
inline constexpr std::uint64_t kMaxCapturesPerRender = 1'000'000;

struct PlannedCapture {
    schedule::Capture capture;
    std::filesystem::path file;
    /// The files of its focal plane's truth collections, as FocalPlaneState::truth.files.
    std::vector<std::filesystem::path> truth_files;
    std::uint64_t event_number = 0;  ///< DIRSIG's "Event #N of M" within its plugin's task
    std::uint64_t event_count = 0;
    /// The lines first_line … end_line − 1 of the capture to render (all of them unless
    /// RenderOptions::rows says otherwise).
    std::uint64_t first_line = 0;
    std::uint64_t end_line = 0;

    /// The pixel problems of its lines: per line × lines.
    std::uint64_t problems(const schedule::ClockedFocalPlane& source) const {
        return source.problems_per_capture / source.lines_per_capture() * (end_line - first_line);
    }
    /// The first pixel problem of its first line.
    std::uint64_t first_problem(const schedule::ClockedFocalPlane& source) const {
        return source.problems_per_capture / source.lines_per_capture() * first_line;
    }
};

/// A data recorder of the run and its two files (glint/sensor/telemetry.h).
struct PlannedTelemetry {
    std::size_t plugin = 0;      ///< index into the schedule's plugins
    std::size_t instrument = 0;  ///< its pose service's instrument index
    const model::Instrument* recorder = nullptr;
    std::filesystem::path csv;
    std::filesystem::path jsonl;
    std::uint64_t samples = 0;  ///< counted when planned (the clock checked then)
};

/// The data recorders the run writes: none in a --schedule run (one warning each). Throws
/// glint::Error (input, at the recorder) when two would write the same file.
std::vector<PlannedTelemetry> plan_telemetry(const RenderInputs& inputs,
                                             const RenderOptions& options, const Context& context);

/// Everything loaded and planned before the first capture (shared by render and dry_run),
/// read-only while the captures are rendered.
struct RenderPlan {
    RenderInputs inputs;
    std::vector<PlannedTelemetry> telemetry;
    std::vector<PlannedCapture> captures;
    std::map<std::size_t, FocalPlaneState> states;  ///< by schedule source
    RenderReport report;                            ///< files planned, pixels, memory estimate
};

/// A planned render: the plan, and the output files it planned — the one thing the captures
/// change as they are written.
struct PlannedRender {
    std::unique_ptr<const RenderPlan> plan;
    ImageOutputs outputs;
};

/// Whether a material of `scene` uses THERM.
bool uses_therm(const model::Scene& scene) noexcept;
/// Solves THERM (glint/thermal/therm.h) for every triangle of `geometry`'s static instances
/// whose material uses it, at the planned captures' times, the shadows traced in `geometry`
/// (render_therm.cpp); warns once naming the dynamic instances with such a material, which
/// keep its constant temperature. Null without such a material or capture; throws
/// glint::Error (input) when one exists and the simulation names no weather.
std::shared_ptr<const scene::FacetTemperatures> solve_therm(const RenderPlan& plan,
                                                            const scene::GeometryScene& geometry,
                                                            const Context& context);

/// Takes over the loaded inputs, selects the captures (--schedule), builds the state of every
/// focal plane that writes a file, then plans every output file. Throws what
/// make_render_inputs and make_focal_plane_state throw.
PlannedRender plan_render(model::SimulationInputs loaded, const RenderOptions& options,
                          const Context& context);

/// The processing events of a run, by planned capture: those fired before it (collection,
/// task and capture started) and after it has been written (capture, task and collection
/// completed). Only focal planes with processing tasks at an event have events.
struct EventPlan {
    std::vector<std::vector<model::ProcessingEvent>> before;  ///< one list per planned capture
    std::vector<std::vector<model::ProcessingEvent>> after;

    /// Every event in firing order.
    std::vector<model::ProcessingEvent> in_order() const;
};

/// The processing events of `render_plan`'s captures (docs/processing.md, "Events").
EventPlan plan_events(const RenderPlan& render_plan);

/// Samples every planned data recorder and writes its files atomically.
void write_telemetry(const RenderPlan& plan, const RenderOptions& options, const Context& context);

/// Writes the capture list of the run (--log_info_filename), atomically; nothing when the
/// option is empty.
void write_log_info(const RenderPlan& plan, const RenderOptions& options, const Context& context);

/// Renders one capture of `plan` into its file in `outputs`; `geometry` is built for its
/// window, `path_cache` is its focal plane's. Returns its statistics.
CaptureReport render_capture(const RenderPlan& plan, ImageOutputs& outputs,
                             const PlannedCapture& planned, const scene::GeometryScene& geometry,
                             radiometry::SensorPathCache& path_cache, const RenderOptions& options,
                             const Context& context, std::vector<double>& image);

/// Fires one pulse of a lidar receiver (a planned capture of a lidar focal plane, its tick the
/// pulse time) and writes it to its BIN file: the passive photon rate by the path tracer on
/// the receiver's band, the returns by the lidar tracer. `path_cache` is the receiver's,
/// `laser_cache` its laser line's.
CaptureReport render_pulse(const RenderPlan& plan, ImageOutputs& outputs,
                           const PlannedCapture& planned, const scene::GeometryScene& geometry,
                           radiometry::SensorPathCache& path_cache,
                           radiometry::SensorPathCache& laser_cache, const RenderOptions& options,
                           const Context& context);

/// Plans the BIN file `path` of lidar receiver `source` holding `captures` (its pulses, in
/// schedule order).
void plan_bin_file(const RenderInputs& inputs, const FocalPlaneState& state, std::size_t source,
                   const std::filesystem::path& path,
                   const std::vector<const PlannedCapture*>& captures, const RenderOptions& options,
                   ImageOutputs& outputs);

/// Pixels a capture is solved, reduced and written in at a time (render_capture.cpp): a band of
/// whole lines of about this many.
inline constexpr std::uint64_t kBlockPixels = std::uint64_t{1} << 16;
/// The lines of such a band of a capture of `source` (at least one).
inline std::uint64_t block_lines(const schedule::ClockedFocalPlane& source) {
    const std::uint64_t per_line = source.problems_per_capture / source.lines_per_capture();
    return std::max<std::uint64_t>(1, kBlockPixels / std::max<std::uint64_t>(1, per_line));
}

/// The values held per pixel of a band of lines of an image capture: its channels (twice with a
/// detection chain: before and after) and its truth bands.
inline std::uint64_t band_values(const FocalPlaneState& state) {
    return state.units.channels() * (state.detection ? 2 : 1) + state.truth.bands.size();
}

/// The bands of lines an image capture of `source` holds at once: two when it has more than
/// one (one is written while the next is solved), else one.
inline std::uint64_t bands_held(const schedule::ClockedFocalPlane& source) {
    return block_lines(source) < source.lines_per_capture() ? 2 : 1;
}

/// The memory of the bands of lines an image capture of `source` holds at once (bands_held ×
/// band_values × 8 bytes per pixel).
inline std::uint64_t band_bytes(const schedule::ClockedFocalPlane& source,
                                const FocalPlaneState& state) {
    const std::uint64_t per_line = source.problems_per_capture / source.lines_per_capture();
    const std::uint64_t lines =
        std::min<std::uint64_t>(block_lines(source), source.lines_per_capture());
    return bands_held(source) * per_line * lines * band_values(state) * 8;
}

/// The height above the scene's origin of a capture's instrument at mid-window, m.
double capture_sensor_height_m(const RenderInputs& in, const schedule::Capture& capture,
                               const schedule::ClockedFocalPlane& source);

/// The environment of a capture on `grid` (the sun at both ends of its window seen from the
/// scene origin, the sensor altitude from the instrument's position at mid-window, the levels
/// of `geometry`'s surfaces); its sensor-path tables, when not in `cache`, are computed on
/// `threads` threads (0: all).
radiometry::Environment capture_environment(const RenderInputs& in, const SpectralGrid& grid,
                                            const schedule::Capture& capture,
                                            const schedule::ClockedFocalPlane& source,
                                            const scene::GeometryScene& geometry,
                                            radiometry::SensorPathCache& cache, unsigned threads);

/// The Embree build options of a window.
scene::BuildOptions build_options(const RenderOptions& options, double t0_s, double t1_s);

}  // namespace glint::render::detail
