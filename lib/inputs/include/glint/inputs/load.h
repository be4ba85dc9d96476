// SPDX-License-Identifier: Apache-2.0
// The one reading of a simulation's inputs. load() parses the `.jsim` or `.sim` and every file
// it names — scenes (with their glists, OBJ meshes, materials and motion files), the
// atmosphere, and for each BasicPlatform entry its platform, motion and tasks files, the PSD
// tables of their jitter and the trigger files of external clocks — each file opened once
// (ReadOptions::files records the opens; `-vv` logs them), and returns plain model data. The
// layers below (pose services, the schedule, the renderer) take that data and read nothing.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include "glint/core/diagnostics.h"
#include "glint/core/log.h"
#include "glint/dirsig/read_options.h"
#include "glint/inputs/scene_atmosphere.h"
#include "glint/model/simulation_inputs.h"

namespace glint::inputs {

/// What load() reads, and how.
struct LoadOptions {
    /// Path resolution; `read.files` records the files opened (load() makes one, logging to
    /// its `log`, when it is null).
    dirsig::ReadOptions read;
    /// False: the atmosphere file is not read and the default atmosphere is returned (tools
    /// that need no radiometry, such as glint-schedule).
    bool atmosphere = true;
    /// False (tools that need only the scene's origin and its named instances, such as
    /// glint-schedule): when no platform's mount tracks a named target, errors of the files a
    /// scene names (materials, curve files, glists, OBJ files, motion files) are not fatal:
    /// they become one warning per scene file counting them and quoting the first. Errors of
    /// the scene files themselves (the origin) stay errors.
    bool scene_contents = true;
    /// Set: this atmosphere replaces the simulation's, whose BasicAtmosphere file is then
    /// not read (glint-render --atmosphere).
    std::optional<AtmosphereOverride> atmosphere_override;
    /// True (glint-platform2jsim --check): read every file even after errors, and return what
    /// was read instead of throwing for its errors (the caller reads `diagnostics`). Errors in
    /// the simulation file itself still throw: without it nothing else can be found.
    bool keep_going = false;
    /// Told what each scene and atmosphere file held (glint-platform2jsim --check).
    ReadObserver* observer = nullptr;
};

/// Reads `simulation_file` (a `.jsim` holding one simulation, or a `.sim`) and everything it
/// references, in this order: the simulation; its scene_list (merged, inputs::
/// read_simulation_scene); its atmosphere (read_simulation_atmosphere); then each BasicPlatform
/// entry's platform, motion and tasks files (a file two entries name is parsed once and its
/// model shared, so its problems are reported once); then the PSD files named by jitter (filling
/// JitterSpec::psd and JitterSpec::psd) and the trigger files of external clocks (filling
/// Clock::trigger_times_s). Every problem goes to `diagnostics` (file:line); a BasicPlatform
/// entry without one of its three files is an error at the entry. Throws glint::Error (input)
/// when diagnostics has errors after the simulation file, and again after everything.
model::SimulationInputs load(const std::filesystem::path& simulation_file,
                             const LoadOptions& options, const Log& log, Diagnostics& diagnostics);

/// Reads BasicPlatform entry `plugin_index` of `simulation` (its platform, motion and tasks
/// files, their PSD tables and trigger files). Problems go to `diagnostics`; nullopt when the
/// entry does not name one of its three files (an error at the entry). Throws glint::Error
/// (usage) for an index out of range or a plugin that is not a BasicPlatform.
std::optional<model::PlatformInputs> read_platform_entry(const model::Simulation& simulation,
                                                         std::size_t plugin_index,
                                                         const dirsig::ReadOptions& options,
                                                         Diagnostics& diagnostics);

/// load() with its own diagnostics, every one of which is logged to `log` (errors and
/// warnings, in the order found, each once); throws (Diagnostics::log_and_rethrow) when
/// there are errors.
model::SimulationInputs load_logged(const std::filesystem::path& simulation_file,
                                    const LoadOptions& options, const Log& log);

/// Reads the PSD files that `platform`'s mount jitter names (JitterSpec::psd_file) into
/// JitterSpec::psd, each through `options`.
void read_psd_tables(model::Platform& platform, const dirsig::ReadOptions& options,
                     Diagnostics& diagnostics);
/// Reads the PSD files that `motion`'s platform jitter names (JitterSpec::psd_file) into
/// JitterSpec::psd (inline tables are kept).
void read_psd_tables(model::PlatformMotion& motion, const dirsig::ReadOptions& options,
                     Diagnostics& diagnostics);
/// Reads the trigger file of every enabled external-trigger clock of `platform` into its
/// Clock::trigger_times_s.
void read_trigger_files(model::Platform& platform, const dirsig::ReadOptions& options,
                        Diagnostics& diagnostics);

/// Reads a PSF or active-area image (`element`: "<psf><image>" or "<activearea><image>")
/// through OpenImageIO (a grey image of at most 4096 × 4096 pixels; a colour image's first
/// channel) and checks its values as sampling weights (io::weight_image_problem: none
/// negative, none above `max_value`, not all zero). A problem is an error at `where`,
/// `element "file": problem`, and gives nullopt.
std::optional<model::WeightImage> read_weight_image(const model::FileRef& image,
                                                    const std::string& element,
                                                    const ErrorContext& where, double max_value,
                                                    Diagnostics& diagnostics);
/// Reads the PSF and active-area images of every enabled focal plane of `platform` into
/// Psf::weights and CaptureMethod::active_area (read_weight_image; a PSF's values unbounded,
/// a mask's at most 1).
void read_weight_images(model::Platform& platform, Diagnostics& diagnostics);

}  // namespace glint::inputs
