// SPDX-License-Identifier: Apache-2.0
// glint-envi's subcommands and options (CLI11), including the spellings of DIRSIG's
// `image_tool convert` (--output_filename=, --format=png, --gamma=, --band=, --bands=,
// --percent=, --per_band), and the dispatch to lib/app_envi.
#include "cli.h"

#include <iostream>

#include "glint/core/error.h"
#include "glint/core/runner.h"

namespace glint::tools::envi {
namespace {

std::vector<std::size_t> parse_band_list(const std::string& text) {
    std::vector<std::size_t> bands;
    std::size_t begin = 0;
    while (begin <= text.size()) {
        std::size_t end = text.find(',', begin);
        if (end == std::string::npos) end = text.size();
        const std::string item = text.substr(begin, end - begin);
        if (item.empty() || item.size() > 9 ||
            item.find_first_not_of("0123456789") != std::string::npos) {
            throw usage_error(
                "--bands takes band numbers separated by commas, e.g. 2,1,0 "
                "(got '" +
                text + "')");
        }
        bands.push_back(static_cast<std::size_t>(std::stoul(item)));
        begin = end + 1;
    }
    return bands;
}

}  // namespace

void EnviCli::configure(CLI::App& app) {
    app.require_subcommand(1);

    m_info = app.add_subcommand("info", "Describe ENVI files (sizes, type, bands, provenance)");
    m_info->add_option("--format", m_info_format, "Report format: text or json")
        ->check(CLI::IsMember({"text", "json"}))
        ->capture_default_str();
    m_info->add_option("files", m_options.info.files, "ENVI data files or headers")
        ->required()
        ->type_name("FILE");

    m_stats = app.add_subcommand("stats", "Per-band count, min, max, mean and std of a file");
    m_stats->add_option("--format", m_stats_format, "Report format: text or json")
        ->check(CLI::IsMember({"text", "json"}))
        ->capture_default_str();
    m_stats->add_option("file", m_options.stats.file, "ENVI file (or any image)")
        ->required()
        ->type_name("FILE");

    m_convert = app.add_subcommand("convert",
                                   "Convert ENVI to PNG/TIFF/JPEG/EXR/PPM, or any image to ENVI");
    CLI::App& c = *m_convert;
    c.add_option("files", m_convert_files, "IN OUT, or IN alone with --output")
        ->required()
        ->expected(1, 2)
        ->type_name("FILE");
    c.add_option("-o,--output,--output_filename", m_output, "Output file (image_tool spelling)")
        ->type_name("FILE");
    c.add_option("-f,--format", m_options.convert.format,
                 "Output format: png, tiff, jpeg, exr, ppm or envi (default: from OUT's "
                 "extension)");
    c.add_option("--band", m_band, "Write this one band (numbered from 0)")
        ->check(whole_number())
        ->type_name("N");
    c.add_option("--pulse", m_pulse,
                 "A DIRSIG lidar BIN input: write only this pulse (numbered from 0 over the "
                 "file) to OUT; without it every pulse goes to OUT-pNNNN")
        ->check(whole_number())
        ->type_name("N");
    c.add_flag("--range", m_options.convert.range,
               "A DIRSIG lidar BIN input: write each pulse's range image instead of its cube "
               "(band 0 the range of each pixel's strongest return in m, band 1 its photons)");
    c.add_option("--bands", m_bands, "Write these bands as the output channels, e.g. 2,1,0")
        ->type_name("R,G,B");
    c.add_option("--gamma", m_gamma, "Display gamma: stretched values s become s^(1/G)")
        ->type_name("G");
    c.add_option("--percent", m_percent,
                 "Percentile stretch: clip P% of the values at each end (0 <= P < 50)")
        ->type_name("P");
    c.add_flag("--per-band,--per_band", m_options.convert.per_band,
               "Stretch each band on its own limits (default: one stretch for all bands)");
    c.add_option("--min", m_min, "Fixed stretch: this value maps to 0 (with --max)")
        ->type_name("A");
    c.add_option("--max", m_max, "Fixed stretch: this value maps to full scale (with --min)")
        ->type_name("B");
    c.add_flag("--raw", m_options.convert.raw, "No stretch: write values unchanged");
    c.add_option("--bit-depth,--bit_depth", m_bit_depth,
                 "Output bits per value: 8, 16 (half for EXR), 32 (float); ENVI also 64")
        ->check(CLI::IsMember({8, 16, 32, 64}))
        ->type_name("BITS");
    c.add_option("--data-type,--data_type", m_data_type,
                 "ENVI output type: uint8, int16, uint16, int32, uint32, int64, uint64, "
                 "float32, float64 (or the ENVI code)")
        ->type_name("TYPE");
    c.add_option("--colormap", m_colormap,
                 "One band of labels: index (a colour per value), none (a grey stretch) or "
                 "auto (index for an index band in an 8/16-bit image)")
        ->check(CLI::IsMember({"auto", "index", "none"}))
        ->capture_default_str();

    m_encode = app.add_subcommand("encode", "Encode image frames into a video with ffmpeg");
    CLI::App& e = *m_encode;
    e.add_option("-r,--framerate", m_options.encode.framerate, "Frames per second")
        ->capture_default_str()
        ->type_name("F");
    e.add_option("-o,--output", m_options.encode.output, "Output video (e.g. video.mp4)")
        ->required()
        ->type_name("FILE");
    e.add_option("--codec", m_options.encode.codec,
                 "ffmpeg video codec (default: libx264 for mp4/m4v/mov/mkv)");
    e.add_option("--pix-fmt", m_options.encode.pixel_format,
                 "ffmpeg pixel format (default: yuv420p with libx264)");
    e.add_option("--crf", m_crf, "libx264 constant rate factor, 0-51 (ffmpeg's default: 23)");
    e.add_option("--timeout", m_timeout_s, "Stop ffmpeg after this many seconds")->type_name("S");
    e.add_option("frames", m_options.encode.frames,
                 "Frames in display order, or one pattern such as frames/f%04d.png")
        ->required()
        ->type_name("FRAME");

    m_merge = app.add_subcommand(
        "merge", "Join the parts sharded glint-render runs wrote into the files of one run");
    CLI::App& m = *m_merge;
    m.add_option("parts", m_options.merge.parts, "The part folders (each shard's --output-folder)")
        ->required()
        ->type_name("PART_FOLDER");
    m.add_option("-o,--output-folder,--output_folder", m_options.merge.output_folder,
                 "Folder for the whole files (the single run's --output-folder)")
        ->required()
        ->type_name("DIR");
    m.add_option("--expect", m_options.merge.expect,
                 "A glint-schedule JSON of the whole run (made with -o's folder as its "
                 "--output-folder): every image and truth file it lists must come out")
        ->type_name("SCHEDULE");

    for (CLI::App* sub : {m_info, m_stats, m_convert, m_encode, m_merge}) sub->fallthrough();
}

void EnviCli::finish_convert() {
    app_envi::ConvertOptions& o = m_options.convert;
    CLI::App& c = *m_convert;
    if (!m_output.empty()) {
        if (m_convert_files.size() != 1) {
            throw usage_error("convert takes one input when --output is given (got " +
                              std::to_string(m_convert_files.size()) + " files)");
        }
        o.input = m_convert_files.front();
        o.output = m_output;
    } else {
        if (m_convert_files.size() != 2) {
            throw usage_error("convert needs an input and an output (or --output FILE)");
        }
        o.input = m_convert_files[0];
        o.output = m_convert_files[1];
    }
    if (c.count("--band") > 0) o.band = m_band;
    if (c.count("--pulse") > 0) o.pulse = m_pulse;
    if (c.count("--bands") > 0) o.bands = parse_band_list(m_bands);
    if (c.count("--gamma") > 0) o.gamma = m_gamma;
    if (c.count("--percent") > 0) o.percent = m_percent;
    if (c.count("--min") > 0) o.min = m_min;
    if (c.count("--max") > 0) o.max = m_max;
    if (c.count("--bit-depth") > 0) o.bit_depth = m_bit_depth;
    o.colormap = *app_envi::colormap_from_name(m_colormap);
    if (c.count("--data-type") > 0) {
        o.data_type = io::envi_type_from_string(m_data_type);
        if (!o.data_type) throw usage_error("unknown ENVI data type '" + m_data_type + "'");
    }
}

int EnviCli::execute(Context& ctx, std::ostream& out) {
    using app_envi::Subcommand;
    if (m_info->parsed()) {
        m_options.subcommand = Subcommand::info;
        m_options.info.format = *app_envi::report_format_from_name(m_info_format);
    } else if (m_stats->parsed()) {
        m_options.subcommand = Subcommand::stats;
        m_options.stats.format = *app_envi::report_format_from_name(m_stats_format);
    } else if (m_convert->parsed()) {
        m_options.subcommand = Subcommand::convert;
        finish_convert();
    } else if (m_encode->parsed()) {
        m_options.subcommand = Subcommand::encode;
        if (m_encode->count("--crf") > 0) m_options.encode.crf = m_crf;
        if (m_encode->count("--timeout") > 0) m_options.encode.timeout_s = m_timeout_s;
    } else if (m_merge->parsed()) {
        m_options.subcommand = Subcommand::merge;
    } else {
        throw usage_error("no subcommand given");
    }
    return app_envi::run(m_options, ctx, out);
}

}  // namespace glint::tools::envi
