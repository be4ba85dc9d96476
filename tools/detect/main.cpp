// SPDX-License-Identifier: Apache-2.0
// glint-detect: applies a focal plane's detector model (QE, shot/dark/read noise, ADC), TDI
// accumulation and CFA mosaic to a radiometric ENVI product. A thin main over
// lib/app_detect; the options are in cli.cpp.
#include <unistd.h>

#include <iostream>

#include "cli.h"
#include "glint/core/runner.h"

int main(int argc, char** argv) {
    glint::tools::detect::DetectCli cli(argc, argv);
    const glint::ToolSpec spec{
        "detect",
        "Turn a radiometric product (Photons/cm2) into digital counts: QE, shot, dark and read "
        "noise, ADC, TDI accumulation and CFA mosaic of a focal plane",
        glint::kCommonSeed | glint::kCommonThreads};
    const glint::ToolStreams streams{std::cout, std::cerr, ::isatty(STDERR_FILENO) != 0};
    return glint::run_tool(
        spec, argc, argv, streams, [&](CLI::App& app) { cli.configure(app); },
        [&](glint::Context& ctx) { return cli.execute(ctx); });
}
