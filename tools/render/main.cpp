// SPDX-License-Identifier: Apache-2.0
// glint-render: renders the captures of a .jsim or DIRSIG4 .sim into ENVI images in the units
// the DIRSIG5 BasicPlatform manual promises. A thin main over lib/app_render; the options are
// in cli.cpp.
#include "../tool_main.h"
#include "cli.h"

int main(int argc, char** argv) {
    return glint::tools::tool_main<glint::tools::render::RenderCli>(
        {"render",
         "Render the captures of a .jsim or .sim with the spectral path tracer into ENVI "
         "images (radiance in the units of each focal plane's <imagefile>)",
         glint::kCommonSeed | glint::kCommonThreads},
        argc, argv);
}
