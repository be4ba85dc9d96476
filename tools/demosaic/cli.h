// SPDX-License-Identifier: Apache-2.0
// The command line of glint-demosaic: options (with the spellings of the processing-task
// example of the DIRSIG5 BasicPlatform manual, --input_filename= and --output_filename=),
// parsed by CLI11 into app_demosaic::Options.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "glint/app_demosaic/demosaic_tool.h"
#include "glint/core/context.h"

namespace glint::tools::demosaic {

/// Everything parsed from the command line.
class DemosaicCli {
public:
    /// Adds the options to `app`.
    void configure(CLI::App& app);
    /// Checks and converts what was parsed, runs glint-demosaic; returns the exit status.
    int execute(Context& ctx, std::ostream& out);

private:
    void finish();

    CLI::App* m_app = nullptr;
    app_demosaic::Options m_options;
    std::vector<std::string> m_files;
    std::string m_input;
    std::string m_output;
    std::string m_pattern;
    std::string m_phase;
    std::string m_method;
    std::string m_data_type;
    double m_percent = 0.0;
    double m_min = 0.0;
    double m_max = 0.0;
    double m_gamma = 1.0;
    int m_bit_depth = 8;
};

}  // namespace glint::tools::demosaic
