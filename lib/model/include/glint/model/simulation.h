// SPDX-License-Identifier: Apache-2.0
// Simulation: one entry of a DIRSIG5 `.jsim` (a JSON array of these), or what a DIRSIG4
// `.sim` converts to. Plugins keep their order: a BasicPlatform's index among the plugins
// breaks ties in the capture schedule and numbers its outputs.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "glint/model/common.h"

namespace glint::model {

/// `scene_list` entry.
struct SceneEntry {
    FileRef file;        ///< "inputs": the .scene (or glint YAML scene)
    std::string offset;  ///< optional "offset" text as written (e.g. "0,0,0"), else ""
    ErrorContext offset_where;  ///< where the offset is written (its key), when it is
};

/// Inputs of a `BasicPlatform` plugin entry.
struct BasicPlatformInputs {
    FileRef platform_file;  ///< platform_filename
    FileRef motion_file;    ///< motion_filename (.ppd GenericMotion or .motion FlexMotion)
    FileRef tasks_file;     ///< tasks_filename
    std::optional<std::string> output_folder;  ///< output_folder (overrides the CLI's)
    std::optional<std::string> output_prefix;  ///< output_prefix (overrides the CLI's)
    /// split_channels when the entry has it (it takes precedence over --split_channels)
    std::optional<bool> split_channels;
};

/// Inputs of a `BasicAtmosphere` plugin entry.
struct BasicAtmosphereInputs {
    FileRef atmosphere_file;  ///< atmosphere_filename
};

/// One `plugin_list` entry. Exactly one of the optionals is set for the two plugins glint
/// runs; any other plugin is kept verbatim (`inputs_json`) so a rewrite preserves it.
struct Plugin {
    std::string name;
    std::optional<BasicPlatformInputs> basic_platform;
    std::optional<BasicAtmosphereInputs> basic_atmosphere;
    std::string inputs_json;  ///< the "inputs" object as compact JSON (every plugin)
    ErrorContext where;
};

/// One simulation object of a `.jsim`.
struct Simulation {
    std::string file;  ///< the .jsim or .sim as named to the reader
    std::vector<SceneEntry> scenes;
    std::vector<Plugin> plugins;
    std::string medium_list_json = "[]";  ///< kept verbatim

    /// Indices into `plugins` of the BasicPlatform entries, in order.
    std::vector<std::size_t> basic_platform_indices() const;
    /// The BasicAtmosphere inputs, if there is such a plugin (the first one).
    const BasicAtmosphereInputs* atmosphere() const;
};

}  // namespace glint::model
