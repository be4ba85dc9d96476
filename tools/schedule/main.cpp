// SPDX-License-Identifier: Apache-2.0
// glint-schedule: writes the time-ordered capture schedule of a .jsim (or .sim) as JSON, a
// text table or DIRSIG's capture_list, filtered and sharded, or summarises it. A thin main
// over lib/app_schedule; the option wiring is in cli.cpp.
#include "../tool_main.h"
#include "cli.h"

int main(int argc, char** argv) {
    return glint::tools::tool_main<glint::tools::schedule::ScheduleCli>(
        {"schedule",
         "Write the capture schedule of a .jsim or .sim (JSON, text table or DIRSIG "
         "capture_list): poses, sun angles and output files per capture; filter, shard or "
         "--summary it",
         glint::kCommonSeed},
        argc, argv);
}
