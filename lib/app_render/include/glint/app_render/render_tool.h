// SPDX-License-Identifier: Apache-2.0
// glint-render's entry point: renders a .jsim or .sim (glint/render/render.h) or, with
// --dry-run, prints the plan; on stdout it lists the files written (one path per line) or
// the plan. docs/tools/glint-render.md documents every option.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "glint/core/context.h"
#include "glint/dirsig/read_options.h"
#include "glint/process/processing_runner.h"
#include "glint/render/render.h"

namespace glint::app_render {

struct Options {
    std::filesystem::path input;          ///< the .jsim or .sim
    std::filesystem::path schedule_file;  ///< --schedule FILE (empty: the whole schedule)
    bool dry_run = false;                 ///< print the plan, trace nothing
    bool radiance_only = false;           ///< --radiance-only: write radiance, no detector stage
    render::RenderOptions render;         ///< everything else
    dirsig::ReadOptions read;             ///< how the input files are resolved
    /// --atmosphere none|parametric|FILE: replaces the simulation's atmosphere (whose file is
    /// then not read); empty: the simulation's
    std::string atmosphere;
    /// --no-processing: the focal planes' <processing> tasks are not run (said once).
    bool no_processing = false;
    /// --keep-going, --processing-timeout; `tools_dir` defaults to glint-render's folder.
    process::ProcessingOptions processing;
};

/// Parses --convergence's "min,max,threshold" (threshold in W/(cm² sr µm)). Throws
/// glint::Error (usage) naming the option.
radiometry::Convergence parse_convergence(const std::string& text);

/// The data folder: $GLINT_DATA_DIR when set, else <exe dir>/../share/glint when it holds
/// solar/astm_g173.csv (an installed glint), else the source tree's data/ this build was
/// configured from (glint::data_dir_lookup, glint/core/install_paths.h).
std::filesystem::path default_data_dir();

/// Runs glint-render; returns the exit status.
int run(const Options& options, Context& ctx, std::ostream& out);

}  // namespace glint::app_render
