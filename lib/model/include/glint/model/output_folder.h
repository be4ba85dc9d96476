// SPDX-License-Identifier: Apache-2.0
// Where a simulation writes. A BasicPlatform's `output_folder` is kept as written and counts
// from where the run starts; a .jsim someone hands you can name any folder (`/anywhere`), so
// the tools show every output folder (glint-render --dry-run, glint-platform2jsim --check)
// and a run warns where a folder the simulation chose lies outside both the simulation's
// folder and the working folder (docs/processing.md, "Which programs run"; docs/formats.md).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/error.h"
#include "glint/model/simulation.h"

namespace glint::model {

/// The output folder of one BasicPlatform entry.
struct OutputFolder {
    std::size_t plugin_index = 0;     ///< index in Simulation::plugins
    std::filesystem::path folder;     ///< absolute and lexically normal
    bool from_simulation = false;     ///< the entry's own output_folder (not the command line's)
    ErrorContext where;               ///< the plugin entry
};

/// Where each BasicPlatform of `simulation` writes, in plugin order: its output_folder, else
/// `command_line` (--output-folder), else the working folder; relative folders count from
/// `working_folder`.
std::vector<OutputFolder> output_folders(const Simulation& simulation,
                                         const std::optional<std::string>& command_line,
                                         const std::filesystem::path& working_folder);

/// True when `path` is `folder` or lies inside it (both absolute and lexically normal; no
/// link is followed).
bool lies_inside(const std::filesystem::path& path, const std::filesystem::path& folder);

/// The warning for a folder the simulation chose outside both the simulation's folder and
/// `working_folder`, or nullopt when it lies inside one of them (or came from the command
/// line).
std::optional<std::string> unexpected_output_folder(const OutputFolder& output,
                                                    const Simulation& simulation,
                                                    const std::filesystem::path& working_folder);

}  // namespace glint::model
