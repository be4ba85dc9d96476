// SPDX-License-Identifier: Apache-2.0
// Readers of the DIRSIG inputs into the model, and the `.jsim` writer. Every reader reports
// each problem of the file to `diagnostics` (errors and warnings, with file:line and element
// path) and carries on as far as it can; the caller fails when diagnostics has errors. A
// file that cannot be read or parsed at all is an error diagnostic too (nothing thrown).
#pragma once

#include <filesystem>
#include <string>
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

/// Formats simulations as `.jsim` JSON (2-space indent, DIRSIG5 key names, plugin order kept,
/// other plugins verbatim). File paths are written relative to `output_folder` when they
/// resolve inside or beside it (relative with `..`), absolute otherwise; Windows paths as
/// written.
std::string format_jsim(const std::vector<model::Simulation>& simulations,
                        const std::filesystem::path& output_folder);

}  // namespace glint::dirsig
