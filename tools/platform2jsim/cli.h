// SPDX-License-Identifier: Apache-2.0
// The command line of glint-platform2jsim: its options, parsed by CLI11 into
// app_platform2jsim::Options, the choice of mode from the options given, and the call of
// the library entry point.
#pragma once

#include <CLI/CLI.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "glint/app_platform2jsim/platform2jsim.h"
#include "glint/core/context.h"

namespace glint::tools::platform2jsim {

/// Everything parsed from the command line.
class Platform2JsimCli {
public:
    /// Adds the options to `app`.
    void configure(CLI::App& app);
    /// Chooses the mode, checks that the options fit it, runs it writing data to `out`;
    /// returns the exit status.
    int execute(Context& ctx, std::ostream& out);

private:
    void choose_mode();

    CLI::App* m_app = nullptr;
    app_platform2jsim::Options m_options;
    std::string m_input;
    std::string m_dump;
    std::vector<std::string> m_check;
    std::string m_platform;
    std::string m_motion;
    std::string m_tasks;
    std::string m_scene;
    std::string m_atmosphere;
    std::string m_output_folder;
    std::string m_output_prefix;
    bool m_append = false;
};

}  // namespace glint::tools::platform2jsim
