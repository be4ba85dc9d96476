// SPDX-License-Identifier: Apache-2.0
// glint-bench: measures the Embree scene and the path tracer on a procedural scene of about
// a million triangles against bare Embree, and writes the figures as JSON (stdout or -o).
// A thin main over measurements.h; docs/performance.md explains the report.
#include <unistd.h>

#include <iostream>
#include <optional>
#include <string>

#include "glint/core/atomic_file.h"
#include "glint/core/runner.h"
#include "measurements.h"

int main(int argc, char** argv) {
    using glint::bench::BenchOptions;
    std::string command_line = "glint-bench";
    for (int i = 1; i < argc; ++i) command_line += std::string(" ") + argv[i];
    BenchOptions options;
    const BenchOptions quick = glint::bench::quick_options();
    bool quick_run = false;
    std::string output = "-";
    CLI::App* app_ptr = nullptr;

    const glint::ToolSpec spec{
        "bench",
        "Benchmark the Embree scene and the path tracer against bare Embree on a procedural "
        "scene of ~1 M triangles; writes JSON",
        glint::kCommonThreads | glint::kCommonSeed};
    const glint::ToolStreams streams{std::cout, std::cerr, ::isatty(STDERR_FILENO) != 0};
    const auto configure = [&](CLI::App& app) {
        app_ptr = &app;
        app.add_option("--image-size", options.image_size, "Side of the camera image, pixels")
            ->check(CLI::Range(1u, 16384u))
            ->capture_default_str();
        app.add_option("--samples", options.samples, "Samples per pixel")
            ->check(CLI::Range(1u, 1u << 20))
            ->capture_default_str();
        app.add_option("--tile", options.tile, "Pixels per solve() call")
            ->check(CLI::Range(1u, 1u << 28))
            ->capture_default_str();
        app.add_option("--bands", options.bands, "Bands of the ratio and scaling runs")
            ->check(CLI::Range(1u, 4096u))
            ->capture_default_str();
        app.add_option("--spectral-samples", options.spectral_samples,
                       "Wavelengths per path of the spectrally sampled band-cost runs")
            ->check(CLI::Range(2u, 4096u))
            ->capture_default_str();
        app.add_option("--repeats", options.repeats,
                       "Run every measurement N times; keep the fastest")
            ->check(CLI::Range(1u, 100u))
            ->capture_default_str();
        app.add_option("--min-bare-seconds", options.min_bare_seconds,
                       "Bare Embree: trace the rays again until this many seconds have passed")
            ->check(CLI::Range(0.0, 3600.0))
            ->capture_default_str();
        app.add_option("--terrain-quads", options.scene.terrain_quads,
                       "Terrain grid cells per side (2 triangles each)")
            ->check(CLI::Range(1u, 8192u))
            ->capture_default_str();
        app.add_option("--buildings", options.scene.buildings, "Instanced buildings")
            ->check(CLI::Range(0u, 1u << 22))
            ->capture_default_str();
        app.add_flag("--quick", quick_run,
                     "Tiny sizes for a smoke run (explicit size options still apply)");
        app.add_option("-o,--output", output, "JSON report file ('-': stdout)")
            ->capture_default_str();
    };
    const auto execute = [&](glint::Context& ctx) {
        if (quick_run) {
            const auto unset = [&](const char* name) { return app_ptr->count(name) == 0; };
            if (unset("--image-size")) options.image_size = quick.image_size;
            if (unset("--min-bare-seconds")) options.min_bare_seconds = quick.min_bare_seconds;
            if (unset("--terrain-quads")) options.scene.terrain_quads = quick.scene.terrain_quads;
            if (unset("--buildings")) options.scene.buildings = quick.scene.buildings;
        }
        options.command_line = command_line;
        // Opened first, so that an unwritable output fails before a minute of measuring.
        std::optional<glint::AtomicFile> file;
        if (output != "-") file.emplace(output);
        const std::string text = glint::bench::run_benchmark(options, ctx).dump(2) + "\n";
        if (file) {
            file->write(text);
            file->commit();
        } else {
            std::cout << text << std::flush;
            if (!std::cout) throw glint::io_error("cannot write the report to stdout");
        }
        return glint::kExitSuccess;
    };
    return glint::run_tool(spec, argc, argv, streams, configure, execute);
}
