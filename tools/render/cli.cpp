// SPDX-License-Identifier: Apache-2.0
// glint-render's options (docs/tools/glint-settings.md).
#include "cli.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "../read_options_cli.h"
#include "glint/core/runner.h"
#include "glint/core/text.h"
#include "glint/schedule/row_band.h"

namespace glint::tools::render {

void RenderCli::configure(CLI::App& app) {
    m_app = &app;
    app.add_option("input", m_options.input, "The simulation: a .jsim or a DIRSIG4 .sim")
        ->type_name("SIM")
        ->required();
    app.add_option("--output-folder,--output_folder", m_output_folder,
                   "Output folder of every BasicPlatform without its own in the .jsim")
        ->type_name("DIR");
    app.add_option("--output-prefix,--output_prefix", m_output_prefix,
                   "Output prefix of every BasicPlatform without its own in the .jsim")
        ->type_name("PREFIX");
    app.add_option("--convergence", m_convergence,
                   "Default MIN,MAX,THRESHOLD samples per pixel and threshold (W/(cm2 sr um) at "
                   "the reference wavelength); a focal plane's <convergence> wins "
                   "(default 10,100,1e-6)")
        ->type_name("MIN,MAX,T");
    app.add_option("--scale-resolution,--scale_resolution",
                   m_options.render.schedule.scale_resolution,
                   "Scale every focal plane's pixel counts by this factor, same field of view")
        ->type_name("FACTOR")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    app.add_flag("--split-channels,--split_channels", m_options.render.split_channels,
                 "Render each channel as its own spectral state (own bands, random streams "
                 "and convergence; same expectation: no dispersion is modelled)");
    app.add_option("--atmosphere", m_options.atmosphere,
                   "Use this atmosphere in place of the simulation's: none, parametric (the "
                   "default parametric model) or a glint YAML atmosphere or DIRSIG .atm file")
        ->type_name("none|parametric|FILE");
    app.add_option("--schedule", m_options.schedule_file,
                   "Render only the captures of this glint-schedule JSON (a subset or shard)")
        ->type_name("FILE");
    app.add_option("--rows", m_rows,
                   "Render only lines A to B-1 of every capture (a row shard; glint-envi merge "
                   "joins the parts): A:B, A:, :B or N")
        ->type_name("A:B");
    app.add_flag("--radiance-only", m_options.radiance_only,
                 "Stop at radiance: write the radiometric product even where a detector model, "
                 "TDI or a colour filter array is configured");
    app.add_flag("--dry-run", m_options.dry_run,
                 "Print the plan (captures, pixels, outputs, memory estimate) and trace nothing");
    app.add_option("--max-memory", m_max_memory,
                   "Cap the memory of the ray-tracing scene (bytes, or with K, M, G, T)")
        ->check(byte_size())
        ->type_name("SIZE");
    add_read_options(app, m_options.read);
    app.add_option("--max-bounces", m_options.render.tracer.max_bounces,
                   "Surface scatterings after the first hit (Russian roulette ends most paths "
                   "earlier)")
        ->type_name("N")
        ->capture_default_str();
    app.add_option("--spectral-samples", m_options.render.tracer.spectral_samples,
                   "Wavelengths each path follows: 0 follows every band; K >= 2 follows the "
                   "reference band and K-1 others drawn per path, weighted to stay unbiased "
                   "(faster per path on many bands, noisier per band)")
        ->type_name("K")
        ->check(CLI::Validator(
            [](const std::string& text) -> std::string {
                return text == "1" ? "1 wavelength per path cannot be drawn: use 0 (every "
                                     "band) or at least 2 (the reference band and one more)"
                                   : "";
            },
            ""))
        ->capture_default_str();
    app.add_option("--isa", m_isa, "Embree ISA: sse2, sse4.2, avx, avx2 or avx512 (default: best)")
        ->type_name("ISA");
    app.add_option("--log-info-filename,--log_info_filename", m_options.render.log_info_file,
                   "Write DIRSIG's capture list (captures, time windows, files) to FILE")
        ->type_name("FILE");
    app.add_flag("--no-processing", m_options.no_processing,
                 "Do not run the focal planes' <processing> tasks (a warning counts them)");
    app.add_flag("--keep-going", m_options.processing.keep_going,
                 "A processing task that fails (or whose program is missing) is a warning, not "
                 "an error: the render goes on");
    app.add_flag("--allow-processing", m_options.processing.allow_all,
                 "Run every program the focal planes' <processing> tasks name, with any "
                 "arguments (by default only image_tool, demosaic, ffmpeg and glint's tools, with "
                 "arguments inside the output folder, and what the allow-list file allows)");
    app.add_option("--processing-timeout", m_processing_timeout_s,
                   "Seconds one processing task may run before it is killed (0: no limit)")
        ->type_name("SECONDS")
        ->check(CLI::Validator(
            [](const std::string& text) -> std::string {
                const std::optional<double> seconds = parse_double(text);
                return seconds && *seconds >= 0.0
                           ? ""
                           : quote(text) + " is not a number of seconds >= 0 (0: no limit)";
            },
            ""))
        ->capture_default_str();
    app.add_option("--data-dir", m_options.render.data_dir,
                   "glint's data folder (solar spectrum); default $GLINT_DATA_DIR, else "
                   "<exe dir>/../share/glint when installed, else the source tree's data/")
        ->type_name("DIR");
}

int RenderCli::execute(Context& ctx, std::ostream& out) {
    const CLI::App& app = *m_app;
    glint::render::RenderOptions& settings = m_options.render;
    if (app.count("--output-folder") > 0) settings.schedule.output_folder = m_output_folder;
    if (app.count("--output-prefix") > 0) settings.schedule.output_prefix = m_output_prefix;
    if (app.count("--convergence") > 0) {
        settings.convergence = app_render::parse_convergence(m_convergence);
    }
    if (app.count("--max-memory") > 0) {
        settings.device.max_memory_bytes =
            *parse_byte_size(m_max_memory);  // checked by byte_size()
    }
    if (m_processing_timeout_s > 0.0) {
        m_options.processing.timeout = std::chrono::milliseconds(
            static_cast<std::int64_t>(std::ceil(std::min(m_processing_timeout_s, 1e9) * 1000.0)));
    } else {
        m_options.processing.timeout.reset();
    }
    if (app.count("--rows") > 0) settings.rows = schedule::parse_row_band(m_rows);
    settings.device.isa = m_isa;
    settings.device.threads = ctx.threads;
    return app_render::run(m_options, ctx, out);
}

}  // namespace glint::tools::render
