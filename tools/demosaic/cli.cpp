// SPDX-License-Identifier: Apache-2.0
// glint-demosaic's options (CLI11) and their conversion into app_demosaic's options: input
// and output as positionals or as -i/--input/--input_filename and -o/--output/
// --output_filename, the pattern, phase and method by name, the output format and the
// image stretch of glint-envi convert.
#include "cli.h"

#include "glint/core/error.h"

namespace glint::tools::demosaic {

void DemosaicCli::configure(CLI::App& app) {
    m_app = &app;
    app.add_option("files", m_files, "IN OUT (or give them as --input_filename/--output_filename)")
        ->expected(0, 2)
        ->type_name("FILE");
    app.add_option("-i,--input,--input_filename", m_input,
                   "One-band mosaic: ENVI, or an image (.png, .tif, ...)")
        ->type_name("FILE");
    app.add_option("-o,--output,--output_filename", m_output,
                   "Output: ENVI (.img, .dat, ...) or an image (.png, .jpg, .tif, .exr, .ppm)")
        ->type_name("FILE");
    app.add_option("--pattern", m_pattern,
                   "Colour filter array: bayer or truesense (default: the input header's "
                   "'glint cfa pattern', else bayer)")
        ->type_name("NAME");
    app.add_option("--phase,--bayer-phase", m_phase,
                   "Bayer phase, the 2x2 block from pixel (0,0): rggb, grbg, gbrg, bggr "
                   "(default: the input header's 'glint cfa phase', else rggb)")
        ->type_name("NAME");
    app.add_option("--method", m_method,
                   "bilinear (Bayer default), mhc (Malvar-He-Cutler, Bayer), pan-guided "
                   "(TrueSense, its only method)")
        ->type_name("NAME");
    app.add_option("-f,--format", m_options.format,
                   "Output format: png, tiff, jpeg, exr, ppm or envi (default: from the "
                   "output's extension)");
    app.add_option("--percent", m_percent,
                   "Images: percentile stretch, clip P% of the values at each end (0 <= P < 50)")
        ->type_name("P");
    app.add_option("--min", m_min, "Images: fixed stretch, this value maps to 0 (with --max)")
        ->type_name("A");
    app.add_option("--max", m_max, "Images: fixed stretch, this value maps to full scale")
        ->type_name("B");
    app.add_option("--gamma", m_gamma, "Images: stretched values s become s^(1/G)")->type_name("G");
    app.add_flag("--raw", m_options.raw, "Images: no stretch, values rounded and clamped");
    app.add_option("--bit-depth,--bit_depth", m_bit_depth,
                   "Images: bits per value, 8, 16 (half for EXR) or 32 (float)")
        ->check(CLI::IsMember({8, 16, 32}))
        ->type_name("BITS");
    app.add_option("--data-type,--data_type", m_data_type,
                   "ENVI output type: uint8, int16, uint16, int32, uint32, int64, uint64, "
                   "float32, float64 (default: the input's)")
        ->type_name("TYPE");
}

void DemosaicCli::finish() {
    app_demosaic::Options& o = m_options;
    std::size_t next = 0;
    if (!m_input.empty()) {
        o.input = m_input;
    } else if (next < m_files.size()) {
        o.input = m_files[next++];
    } else {
        throw usage_error("no input file named (give IN OUT or --input_filename=FILE)");
    }
    if (!m_output.empty()) {
        o.output = m_output;
    } else if (next < m_files.size()) {
        o.output = m_files[next++];
    } else {
        throw usage_error("no output file named (give IN OUT or --output_filename=FILE)");
    }
    if (next < m_files.size()) {
        throw usage_error("unexpected argument '" + m_files[next] +
                          "' (the input and output are already named)");
    }
    if (m_app->count("--pattern") > 0) o.pattern = app_demosaic::parse_pattern(m_pattern);
    if (m_app->count("--phase") > 0) o.phase = app_demosaic::parse_phase(m_phase);
    if (m_app->count("--method") > 0) o.method = app_demosaic::parse_method(m_method);
    if (m_app->count("--percent") > 0) o.percent = m_percent;
    if (m_app->count("--min") > 0) o.min = m_min;
    if (m_app->count("--max") > 0) o.max = m_max;
    if (m_app->count("--gamma") > 0) o.gamma = m_gamma;
    if (m_app->count("--bit-depth") > 0) o.bit_depth = m_bit_depth;
    if (m_app->count("--data-type") > 0) {
        o.data_type = io::envi_type_from_string(m_data_type);
        if (!o.data_type) throw usage_error("unknown ENVI data type '" + m_data_type + "'");
    }
}

int DemosaicCli::execute(Context& ctx, std::ostream& out) {
    finish();
    return app_demosaic::run(m_options, ctx, out);
}

}  // namespace glint::tools::demosaic
