// SPDX-License-Identifier: Apache-2.0
// The command line of glint-envi: the subcommands' options, parsed by CLI11 into the option
// structs of lib/app_envi, and the dispatch to their entry points.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "glint/app_envi/envi_tool.h"
#include "glint/core/context.h"

namespace glint::tools::envi {

/// Everything parsed from the command line.
class EnviCli {
public:
    /// Adds the subcommands and their options to `app`.
    void configure(CLI::App& app);
    /// Runs the chosen subcommand; returns the exit status.
    int execute(Context& ctx, std::ostream& out);

private:
    void finish_convert();

    CLI::App* m_info = nullptr;
    CLI::App* m_stats = nullptr;
    CLI::App* m_convert = nullptr;
    CLI::App* m_encode = nullptr;
    CLI::App* m_merge = nullptr;

    app_envi::Options m_options;
    std::string m_info_format = "text";
    std::string m_stats_format = "text";

    std::vector<std::string> m_convert_files;
    std::string m_output;
    std::string m_bands;
    std::string m_data_type;
    std::string m_colormap = "auto";
    double m_gamma = 1.0;
    double m_percent = 0.0;
    double m_min = 0.0;
    double m_max = 0.0;
    std::size_t m_band = 0;
    std::size_t m_pulse = 0;
    int m_bit_depth = 8;

    int m_crf = 23;
    double m_timeout_s = 0;
};

}  // namespace glint::tools::envi
