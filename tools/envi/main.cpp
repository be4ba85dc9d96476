// SPDX-License-Identifier: Apache-2.0
// glint-envi: inspect and convert ENVI files (info, stats, convert, encode). A thin main over
// lib/app_envi; the option wiring is in cli.cpp.
#include <unistd.h>

#include <iostream>

#include "cli.h"
#include "glint/core/runner.h"
#include "glint/process/process.h"

int main(int argc, char** argv) {
    std::vector<std::string> args{"glint-envi"};
    for (int i = 1; i < argc; ++i) args.emplace_back(argv[i]);
    glint::tools::envi::EnviCli cli(glint::process::format_command_line(args));
    const glint::ToolSpec spec{
        "envi",
        "Inspect and convert ENVI files: info, stats, convert (to and from images), "
        "encode (frames to video)",
        glint::kCommonBasic};
    const glint::ToolStreams streams{std::cout, std::cerr, ::isatty(STDERR_FILENO) != 0};
    return glint::run_tool(
        spec, argc, argv, streams, [&](CLI::App& app) { cli.configure(app); },
        [&](glint::Context& ctx) { return cli.execute(ctx); });
}
