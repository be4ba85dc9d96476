// SPDX-License-Identifier: Apache-2.0
// glint-schedule's options: the simulation, -o, --format, --summary, the filters and
// shard, DIRSIG's run options (--output_folder, --output_prefix, --scale_resolution,
// --log_info_filename; dashed spellings accepted too).
#include "cli.h"

#include "../read_options_cli.h"
#include "glint/core/error.h"
#include "glint/core/runner.h"

namespace glint::tools::schedule {

void ScheduleCli::configure(CLI::App& app) {
    m_app = &app;
    app.add_option("input", m_options.input, "The simulation: a .jsim or a DIRSIG4 .sim")
        ->type_name("SIM");
    app.add_option("-o,--output", m_options.output, "Output file (- for stdout, the default)")
        ->type_name("FILE");
    app.add_option("--format", m_format,
                   "json (the glint-schedule JSON; the default), text (a table like DIRSIG's "
                   "console; the default with --summary) or capture_list (DIRSIG's "
                   "--log_info_filename JSON)")
        ->type_name("FORMAT");
    app.add_flag("--summary", m_options.summary,
                 "Print counts, problems (pixels) and time span of the selection instead of "
                 "the captures (text or json)");
    app.add_option("--task", m_task, "Only captures of task N (0-based, within each plugin)")
        ->check(whole_number())
        ->type_name("N");
    app.add_option("--captures", m_captures,
                   "Only global capture indices A to B-1 (A:B, A:, :B or N)")
        ->type_name("A:B");
    app.add_option("--focal-plane,--focal_plane", m_focal_plane,
                   "Only captures of the focal plane NAME (or INSTRUMENT/NAME)")
        ->type_name("NAME");
    app.add_option("--shard", m_shard,
                   "Only shard K of N (1 <= K <= N): contiguous runs balanced by problem count")
        ->type_name("K/N");
    app.add_option("--by", m_by,
                   "What --shard splits: captures (whole captures, the default) or rows (a band "
                   "of lines of every capture)")
        ->type_name("captures|rows");
    app.add_option("--output-folder,--output_folder", m_output_folder,
                   "Output folder of every BasicPlatform without its own in the .jsim")
        ->type_name("DIR");
    app.add_option("--output-prefix,--output_prefix", m_output_prefix,
                   "Output prefix of every BasicPlatform without its own in the .jsim")
        ->type_name("PREFIX");
    app.add_option("--scale-resolution,--scale_resolution", m_options.schedule.scale_resolution,
                   "Scale every focal plane's pixel counts by this factor (> 0)")
        ->type_name("FACTOR")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    add_read_options(app, m_options.read_options);
    app.add_option("--log-info-filename,--log_info_filename", m_options.log_info_file,
                   "Also write DIRSIG's capture_list JSON of the selected captures to FILE")
        ->type_name("FILE");
}

int ScheduleCli::execute(Context& ctx, std::ostream& out) {
    const CLI::App& app = *m_app;
    if (app.count("--format") == 0 && m_options.summary) m_format = "text";
    const auto format = app_schedule::parse_output_format(m_format);
    if (!format) {
        throw usage_error("--format: expected json, text or capture_list, got \"" + m_format +
                          "\"");
    }
    m_options.format = *format;
    if (app.count("--task") > 0) m_options.filters.task = m_task;
    if (app.count("--captures") > 0) {
        m_options.filters.captures = app_schedule::parse_capture_range(m_captures);
    }
    if (app.count("--focal-plane") > 0) m_options.filters.focal_plane = m_focal_plane;
    if (app.count("--shard") > 0) m_options.filters.shard = app_schedule::parse_shard(m_shard);
    if (app.count("--by") > 0) {
        if (m_by != "captures" && m_by != "rows") {
            throw usage_error("--by: expected captures or rows, got \"" + m_by + "\"");
        }
        if (!m_options.filters.shard) throw usage_error("--by " + m_by + " needs --shard K/N");
        m_options.filters.shard->by_rows = m_by == "rows";
    }
    if (app.count("--output-folder") > 0) m_options.schedule.output_folder = m_output_folder;
    if (app.count("--output-prefix") > 0) m_options.schedule.output_prefix = m_output_prefix;
    return app_schedule::run(m_options, ctx, out);
}

}  // namespace glint::tools::schedule
