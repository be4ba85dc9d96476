// SPDX-License-Identifier: Apache-2.0
// glint-envi: inspect and convert ENVI files (info, stats, convert, encode). A thin main over
// lib/app_envi; the option wiring is in cli.cpp.
#include "../tool_main.h"
#include "cli.h"

int main(int argc, char** argv) {
    return glint::tools::tool_main<glint::tools::envi::EnviCli>(
        {"envi",
         "Inspect and convert ENVI files: info, stats, convert (to and from images), "
         "encode (frames to video)",
         glint::kCommonMaxMemory},
        argc, argv);
}
