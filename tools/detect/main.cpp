// SPDX-License-Identifier: Apache-2.0
// glint-detect: applies a focal plane's detector model (QE, shot/dark/read noise, ADC), TDI
// accumulation and CFA mosaic to a radiometric ENVI product. A thin main over
// lib/app_detect; the options are in cli.cpp.
#include "../tool_main.h"
#include "cli.h"

int main(int argc, char** argv) {
    return glint::tools::tool_main<glint::tools::detect::DetectCli>(
        {"detect",
         "Turn a radiometric product (Photons/cm2) into digital counts: QE, shot, dark and read "
         "noise, ADC, TDI accumulation and CFA mosaic of a focal plane",
         glint::kCommonSeed | glint::kCommonThreads | glint::kCommonMaxMemory},
        argc, argv);
}
