// SPDX-License-Identifier: Apache-2.0
// Loading a simulation and every file it references, collecting every problem: the shared
// first stage of all glint-platform2jsim modes. --check reads a simulation with glint-render's
// own loader (inputs::load, going on past errors) and builds its schedule as a render does,
// so it refuses what a render refuses; a file checked alone is read with its reader. The
// conversions read `.platform` and `.tasks` files with their readers and check that the other
// files exist. A file referenced several times is read once.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "glint/core/diagnostics.h"
#include "glint/core/log.h"
#include "glint/dirsig/read_options.h"
#include "glint/model/atmosphere.h"
#include "glint/model/motion.h"
#include "glint/model/platform.h"
#include "glint/model/scene.h"
#include "glint/model/simulation.h"
#include "glint/model/tasks.h"

namespace glint::app_platform2jsim {

/// Everything loaded, and every problem found.
struct LoadedInputs {
    std::vector<model::Simulation> simulations;
    /// Platforms and task lists that were read, by resolved path.
    std::map<std::filesystem::path, model::Platform> platforms;
    std::map<std::filesystem::path, model::TaskList> task_lists;
    /// Motion files that were read (--check, as a render reads them).
    std::map<std::filesystem::path, model::PlatformMotion> motions;
    /// Scenes and atmospheres that were read (--check), by resolved path.
    std::map<std::filesystem::path, model::Scene> scenes;
    std::map<std::filesystem::path, model::Atmosphere> atmospheres;
    /// One line per scene or atmosphere read, or default atmosphere used, in reading order:
    /// what it holds (e.g. "scene /d/site.scene: 2 materials, 3 objects, 4 instances").
    std::vector<std::string> contents;
    /// Every distinct file read or checked (the count in the check summary).
    std::set<std::filesystem::path> files;
    Diagnostics diagnostics;

    /// The platform of a BasicPlatform entry, if it was read.
    const model::Platform* platform_of(const model::BasicPlatformInputs& inputs) const;
    /// The key a file is kept under: its absolute, lexically normal path.
    static std::filesystem::path key_of(const std::filesystem::path& file);
};

/// How far load_references goes.
enum class LoadDepth {
    platforms,   ///< the platforms only, not the files they name (what --dump-platform needs)
    everything,  ///< platforms, task lists and the existence of every other file
};

/// Reads a `.sim` or `.jsim` into inputs.simulations (appended).
void load_simulation_file(const std::filesystem::path& file, LoadedInputs& inputs,
                          const dirsig::ReadOptions& options);

/// Reads or checks the files referenced by one BasicPlatform entry.
void load_basic_platform(const model::BasicPlatformInputs& entry, LoadedInputs& inputs,
                         const dirsig::ReadOptions& options, LoadDepth depth);

/// Reads or checks the files referenced by every simulation in inputs (scenes, BasicPlatform
/// and BasicAtmosphere entries; other plugins are not looked into), and reports
/// BasicPlatform entries whose output names clash.
void load_references(LoadedInputs& inputs, const dirsig::ReadOptions& options, LoadDepth depth);

/// Reads a `.platform` (once) and, with `check_references`, checks that the files it names
/// exist. Returns the platform as read (partial when it has errors: see inputs.diagnostics).
const model::Platform* load_platform_file(const std::filesystem::path& file, LoadedInputs& inputs,
                                          const dirsig::ReadOptions& options,
                                          bool check_references = true);

/// What --check adds about the truth collections of the platforms of each simulation read
/// with its scenes: the errors and warnings glint-render gives for
/// their Abundance targets (a material the scene does not have, a tag no instance carries).
void check_truth_targets(LoadedInputs& inputs);

/// What --check does with one file, by extension (any case): alone, as a render reads it —
/// `.platform` (and the files it names), `.tasks`, `.ppd`/`.motion` (and their PSD tables),
/// `.scene` (with its `.mat`, `.glist`s, OBJ and curve files), `.atm`, `.mat` (with its curve
/// files); anything else as a simulation, read by inputs::load as glint-render reads it (going
/// on past errors to report them all) and given the schedule's own checks (Schedule::build).
/// `log` gets the debug line of every file opened.
void check_file(const std::filesystem::path& file, LoadedInputs& inputs,
                const dirsig::ReadOptions& options, const Log& log = {});

/// Warnings for BasicPlatform entries of `simulation` that share output folder and prefix
/// (their outputs may overwrite each other).
void check_output_names(const model::Simulation& simulation, Diagnostics& diagnostics);

/// The output prefix and folder of a BasicPlatform entry as compared for clashes.
std::string describe_output_name(const model::BasicPlatformInputs& entry);

/// "2 errors, 3 warnings in 4 files" (singular where 1).
std::string summary_text(std::size_t errors, std::size_t warnings, std::size_t files);

}  // namespace glint::app_platform2jsim
