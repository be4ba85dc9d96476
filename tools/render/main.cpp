// SPDX-License-Identifier: Apache-2.0
// glint-render: renders the captures of a .jsim or DIRSIG4 .sim into ENVI images in the units
// the DIRSIG5 BasicPlatform manual promises. A thin main over lib/app_render; the options are
// in cli.cpp.
#include <unistd.h>

#include <iostream>

#include "cli.h"
#include "glint/core/runner.h"

int main(int argc, char** argv) {
    glint::tools::render::RenderCli cli(argc, argv);
    const glint::ToolSpec spec{
        "render",
        "Render the captures of a .jsim or .sim with the spectral path tracer into ENVI "
        "images (radiance in the units of each focal plane's <imagefile>)",
        glint::kCommonSeed | glint::kCommonThreads};
    const glint::ToolStreams streams{std::cout, std::cerr, ::isatty(STDERR_FILENO) != 0};
    return glint::run_tool(
        spec, argc, argv, streams, [&](CLI::App& app) { cli.configure(app); },
        [&](glint::Context& ctx) { return cli.execute(ctx, std::cout); });
}
