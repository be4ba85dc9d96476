// SPDX-License-Identifier: Apache-2.0
// The command line of glint-schedule: its options (CLI11; DIRSIG5's --output_folder,
// --output_prefix, --scale_resolution and --log_info_filename spellings), parsed into
// app_schedule::Options, and the call of the library entry point.
#pragma once

#include <CLI/CLI.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "glint/app_schedule/schedule_tool.h"
#include "glint/core/context.h"

namespace glint::tools::schedule {

/// Everything parsed from the command line.
class ScheduleCli {
public:
    /// Adds the options to `app`.
    void configure(CLI::App& app);
    /// Turns the parsed values into options and runs the tool writing data to `out`;
    /// returns the exit status.
    int execute(Context& ctx, std::ostream& out);

private:
    CLI::App* m_app = nullptr;
    app_schedule::Options m_options;
    std::string m_format = "json";
    std::string m_captures;
    std::string m_shard;
    std::string m_by = "captures";
    std::size_t m_task = 0;
    std::string m_focal_plane;
    std::string m_output_folder;
    std::string m_output_prefix;
};

}  // namespace glint::tools::schedule
