// SPDX-License-Identifier: Apache-2.0
// Where an installed glint finds its data: the running executable's own path (Linux
// /proc/self/exe) and the data folder next to it, <exe dir>/../share/glint, as
// `cmake --install` and the .deb lay it out (docs/install.md). No globals: every lookup reads
// what it needs when called.
#pragma once

#include <filesystem>
#include <string_view>

namespace glint {

/// The running executable's absolute path (the target of /proc/self/exe); empty when it
/// cannot be read.
std::filesystem::path executable_path();

/// The data folder an installed executable `executable` would use: <its dir>/../share/glint,
/// lexically normalized. Empty for an empty path.
std::filesystem::path installed_data_dir(const std::filesystem::path& executable);

/// What data_dir_lookup chooses between.
struct DataDirCandidates {
    std::string_view environment;      ///< $GLINT_DATA_DIR's value (empty: unset or empty)
    std::filesystem::path executable;  ///< the running executable (executable_path())
    std::filesystem::path built_in;    ///< the source tree's data/ compiled in (may be empty)
    /// A file that an installed data folder must hold, relative to it.
    std::filesystem::path marker = "solar/astm_g173.csv";
};

/// The data folder, first of: `environment` when non-empty; installed_data_dir(executable)
/// when it holds `marker`; `built_in`.
std::filesystem::path data_dir_lookup(const DataDirCandidates& candidates);

}  // namespace glint
