// SPDX-License-Identifier: Apache-2.0
// glint-platform2jsim: converts DIRSIG4 inputs (.sim, or .platform/.ppd/.tasks parts) into a
// DIRSIG5 .jsim, checks a simulation and every file it references, and dumps platforms as
// normalized JSON. A thin main over lib/app_platform2jsim; the option wiring is in cli.cpp.
#include "../tool_main.h"
#include "cli.h"

int main(int argc, char** argv) {
    return glint::tools::tool_main<glint::tools::platform2jsim::Platform2JsimCli>(
        {"platform2jsim",
         "Convert DIRSIG4 inputs (.sim, or --platform/--motion/--tasks) into a DIRSIG5 .jsim, "
         "--check a simulation and every file it references, --dump-platform as JSON",
         glint::kCommonBasic},
        argc, argv);
}
