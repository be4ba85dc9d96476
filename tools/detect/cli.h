// SPDX-License-Identifier: Apache-2.0
// glint-detect's command line: the input, -o, the focal plane (--platform, --instrument,
// --focal-plane) and the overrides of its detector model, TDI and mosaic.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "glint/app_detect/detect_tool.h"
#include "glint/core/context.h"

namespace glint::tools::detect {

class DetectCli {
public:
    /// Adds the options to `app`.
    void configure(CLI::App& app);
    /// Turns the parsed values into options and runs; returns the exit status.
    int execute(Context& ctx, std::ostream& out);

private:
    CLI::App* m_app = nullptr;
    app_detect::Options m_options;
    double m_qe = 0, m_read_noise = 0, m_dark = 0, m_min_e = 0, m_max_e = 0, m_time = 0;
    int m_bits = 0;
    std::string m_data_type;
    std::string m_mosaic;
    std::string m_phase;
    std::string m_tdi_mode;
};

}  // namespace glint::tools::detect
