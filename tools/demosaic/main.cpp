// SPDX-License-Identifier: Apache-2.0
// glint-demosaic: a Bayer or TrueSense colour filter array mosaic to R, G, B (ENVI or an
// image). A thin main over lib/app_demosaic; the option wiring is in cli.cpp.
#include "../tool_main.h"
#include "cli.h"

int main(int argc, char** argv) {
    return glint::tools::tool_main<glint::tools::demosaic::DemosaicCli>(
        {"demosaic",
         "Demosaic a Bayer or TrueSense colour filter array image into R, G, B "
         "(ENVI, PNG, TIFF, JPEG, EXR, PPM)",
         glint::kCommonMaxMemory},
        argc, argv);
}
