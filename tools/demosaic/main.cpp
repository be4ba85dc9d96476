// SPDX-License-Identifier: Apache-2.0
// glint-demosaic: a Bayer or TrueSense colour filter array mosaic to R, G, B (ENVI or an
// image). A thin main over lib/app_demosaic; the option wiring is in cli.cpp.
#include <unistd.h>

#include <iostream>

#include "cli.h"
#include "glint/core/runner.h"
#include "glint/process/process.h"

int main(int argc, char** argv) {
    std::vector<std::string> args{"glint-demosaic"};
    for (int i = 1; i < argc; ++i) args.emplace_back(argv[i]);
    glint::tools::demosaic::DemosaicCli cli(glint::process::format_command_line(args));
    const glint::ToolSpec spec{
        "demosaic",
        "Demosaic a Bayer or TrueSense colour filter array image into R, G, B "
        "(ENVI, PNG, TIFF, JPEG, EXR, PPM)",
        glint::kCommonBasic};
    const glint::ToolStreams streams{std::cout, std::cerr, ::isatty(STDERR_FILENO) != 0};
    return glint::run_tool(
        spec, argc, argv, streams, [&](CLI::App& app) { cli.configure(app); },
        [&](glint::Context& ctx) { return cli.execute(ctx); });
}
