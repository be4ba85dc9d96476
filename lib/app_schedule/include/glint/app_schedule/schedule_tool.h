// SPDX-License-Identifier: Apache-2.0
// `glint-schedule`: loads a `.jsim` (or `.sim`), enumerates its capture schedule in time
// order and writes it as the "glint-schedule" JSON (docs/tools/glint-schedule.md has the
// schema), as a text table like DIRSIG's console output, or as DIRSIG's --log_info_filename
// capture_list view; or summarises it (--summary: counts, problems, time span, from the
// analytic counts). Captures are streamed: each is written as it is generated, so schedules
// of 10⁸ captures never sit in memory. Filters (--task, --captures, --focal-plane) and
// shards (--shard K/N, balanced by problem count) select what is written (selection.h).
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "glint/app_schedule/selection.h"
#include "glint/core/context.h"
#include "glint/dirsig/read_options.h"
#include "glint/schedule/schedule.h"

namespace glint::app_schedule {

/// What the output holds.
enum class OutputFormat {
    json,          ///< the "glint-schedule" JSON (default)
    text,          ///< a readable table, one capture per line
    capture_list,  ///< DIRSIG's --log_info_filename JSON (capture_list, run_info)
};

/// Parses "json", "text" or "capture_list"; nullopt otherwise.
std::optional<OutputFormat> parse_output_format(const std::string& text);

/// Options of glint-schedule.
struct Options {
    std::filesystem::path input;  ///< the `.jsim` or `.sim`
    /// Output file; "-" or empty is the `out` stream. Written atomically otherwise.
    std::string output = "-";
    OutputFormat format = OutputFormat::json;
    /// Also write the capture_list view of the selected captures to this file (DIRSIG's
    /// --log_info_filename); empty: none.
    std::string log_info_file;
    /// Print counts, problems and time span instead of the captures (text or json).
    bool summary = false;
    Filters filters;
    /// --output_folder, --output_prefix, --scale_resolution (the seed is taken from the
    /// context, not from here).
    schedule::ScheduleOptions schedule;
    dirsig::ReadOptions read_options;
};

/// Runs glint-schedule writing data to `out` (or the -o file). Diagnostics go to ctx.log
/// ("file:line: element: message"); progress to ctx.progress ("captures"). Returns 0 on
/// success and 1 when the inputs have errors (all of them logged, nothing written). Throws
/// glint::Error: usage for options that do not fit together or an output naming an input,
/// input for a filter naming what the schedule does not have, io when an output cannot be
/// written, cancelled on interrupt (temporary files removed).
int run(const Options& options, Context& ctx, std::ostream& out);

}  // namespace glint::app_schedule
