// SPDX-License-Identifier: Apache-2.0
// glint-schedule: writes the time-ordered capture schedule of a .jsim (or .sim) as JSON, a
// text table or DIRSIG's capture_list, filtered and sharded, or summarises it. A thin main
// over lib/app_schedule; the option wiring is in cli.cpp.
#include <unistd.h>

#include <iostream>

#include "cli.h"
#include "glint/core/runner.h"

int main(int argc, char** argv) {
    glint::tools::schedule::ScheduleCli cli(argc, argv);
    const glint::ToolSpec spec{
        "schedule",
        "Write the capture schedule of a .jsim or .sim (JSON, text table or DIRSIG "
        "capture_list): poses, sun angles and output files per capture; filter, shard or "
        "--summary it",
        glint::kCommonSeed};
    const glint::ToolStreams streams{std::cout, std::cerr, ::isatty(STDERR_FILENO) != 0};
    return glint::run_tool(
        spec, argc, argv, streams, [&](CLI::App& app) { cli.configure(app); },
        [&](glint::Context& ctx) { return cli.execute(ctx, std::cout); });
}
