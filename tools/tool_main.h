// SPDX-License-Identifier: Apache-2.0
// The main of every glint tool, written once: a `Cli` (options wired to CLI11 in configure,
// the library entry point called in execute) run under glint::run_tool with the process's
// stdout and stderr. Each tools/<name>/main.cpp is one call of tool_main.
#pragma once

#include <unistd.h>

#include <iostream>

#include "glint/core/runner.h"

namespace glint::tools {

/// Runs the tool `spec` whose command line `Cli` parses: `Cli` is default-constructible and
/// has `void configure(CLI::App&)` and `int execute(Context&, std::ostream& out)`. Returns
/// the exit status.
template <typename Cli>
int tool_main(const ToolSpec& spec, int argc, char** argv) {
    Cli cli;
    const ToolStreams streams{std::cout, std::cerr, ::isatty(STDERR_FILENO) != 0};
    return run_tool(
        spec, argc, argv, streams, [&](CLI::App& app) { cli.configure(app); },
        [&](Context& ctx) { return cli.execute(ctx, std::cout); });
}

}  // namespace glint::tools
