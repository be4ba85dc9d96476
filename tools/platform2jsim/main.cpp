// SPDX-License-Identifier: Apache-2.0
// glint-platform2jsim: converts DIRSIG4 inputs (.sim, or .platform/.ppd/.tasks parts) into a
// DIRSIG5 .jsim, checks a simulation and every file it references, and dumps platforms as
// normalized JSON. A thin main over lib/app_platform2jsim; the option wiring is in cli.cpp.
#include <unistd.h>

#include <iostream>

#include "cli.h"
#include "glint/core/runner.h"

int main(int argc, char** argv) {
    glint::tools::platform2jsim::Platform2JsimCli cli;
    const glint::ToolSpec spec{
        "platform2jsim",
        "Convert DIRSIG4 inputs (.sim, or --platform/--motion/--tasks) into a DIRSIG5 .jsim, "
        "--check a simulation and every file it references, --dump-platform as JSON",
        glint::kCommonBasic};
    const glint::ToolStreams streams{std::cout, std::cerr, ::isatty(STDERR_FILENO) != 0};
    return glint::run_tool(
        spec, argc, argv, streams, [&](CLI::App& app) { cli.configure(app); },
        [&](glint::Context& ctx) { return cli.execute(ctx, std::cout); });
}
