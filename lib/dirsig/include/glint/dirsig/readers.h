// SPDX-License-Identifier: Apache-2.0
// Readers of the DIRSIG inputs into the model, and the `.jsim` writer. Every reader reports
// each problem of the file to `diagnostics` (errors and warnings, with file:line and element
// path) and carries on as far as it can; the caller fails when diagnostics has errors. A
// file that cannot be read or parsed at all is an error diagnostic too (nothing thrown).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "glint/core/diagnostics.h"
#include "glint/dirsig/read_options.h"
#include "glint/model/platform.h"
#include "glint/model/simulation.h"
#include "glint/model/tasks.h"

namespace glint::dirsig {

/// Reads a `.platform` file.
model::Platform read_platform(const std::filesystem::path& file, const ReadOptions& options,
                              Diagnostics& diagnostics);
/// Reads a `.tasks` file.
model::TaskList read_tasks(const std::filesystem::path& file, const ReadOptions& options,
                           Diagnostics& diagnostics);
/// Reads a DIRSIG4 `.sim` into the simulation it describes: its scene, a BasicAtmosphere
/// entry for `atmosphericconditions` and one BasicPlatform entry (platform, platformmotion,
/// tasklist).
model::Simulation read_sim(const std::filesystem::path& file, const ReadOptions& options,
                           Diagnostics& diagnostics);
/// Reads a DIRSIG5 `.jsim` (a JSON array of simulations; a single object is accepted too).
std::vector<model::Simulation> read_jsim(const std::filesystem::path& file,
                                         const ReadOptions& options, Diagnostics& diagnostics);
/// Reads a `.jsim` or `.sim`, told apart by content (JSON or XML).
std::vector<model::Simulation> read_simulation(const std::filesystem::path& file,
                                               const ReadOptions& options,
                                               Diagnostics& diagnostics);

/// What a `.jsim` plugin is, told by its name: the two glint runs, and for the others
/// (kept, not run) the kind their name says ("NewAtmosphere", "SpiceEphemeris",
/// "ThermWeather": "atmosphere", "ephemeris", "weather"/"therm"/"temperature", any case).
enum class PluginKind { basic_platform, basic_atmosphere, atmosphere, ephemeris, thermal, other };
PluginKind plugin_kind(std::string_view name);

/// What glint does in place of the plugin `name` it does not run, as a clause for a message
/// ("glint uses its default parametric atmosphere (...)"); `has_basic_atmosphere`: the
/// simulation has a BasicAtmosphere entry, whose atmosphere is used.
std::string unsupported_plugin_fallback(std::string_view name, bool has_basic_atmosphere);

/// Formats simulations as `.jsim` JSON (2-space indent, DIRSIG5 key names, plugin order kept).
/// File paths are written relative to `output_folder` when they resolve inside or beside it
/// (relative with `..`), absolute otherwise; Windows paths as written. Other plugins' inputs
/// are written as read except their relative paths, rewritten likewise from the folder of
/// Simulation::file: the values of keys ending in "filename", "filenames", "_file" or
/// "_files" (any case, at any depth, array elements too) and any other string naming an
/// existing file from that folder. Absolute paths and paths with variables are kept.
std::string format_jsim(const std::vector<model::Simulation>& simulations,
                        const std::filesystem::path& output_folder);

}  // namespace glint::dirsig
