// SPDX-License-Identifier: Apache-2.0
// glint-render's command line: the simulation and the options of the "Usage" and "Options"
// sections of the DIRSIG5 BasicPlatform manual (docs/references.md) (DIRSIG's underscore
// spellings and dashed ones), plus glint's.
#pragma once

#include <CLI/CLI.hpp>
#include <ostream>
#include <string>

#include "glint/app_render/render_tool.h"
#include "glint/core/context.h"

namespace glint::tools::render {

class RenderCli {
public:
    /// Adds the options to `app`.
    void configure(CLI::App& app);
    /// Turns the parsed values into options and renders; returns the exit status.
    int execute(Context& ctx, std::ostream& out);

private:
    CLI::App* m_app = nullptr;
    app_render::Options m_options;
    std::string m_output_folder;
    std::string m_output_prefix;
    std::string m_convergence;
    std::string m_max_memory;
    std::string m_isa;
    std::string m_rows;
    double m_processing_timeout_s = 3600.0;
};

}  // namespace glint::tools::render
