// SPDX-License-Identifier: Apache-2.0
// glint-envi's entry point: one of its four subcommands (info, stats, convert, encode) with
// its options, run as the other tools are run. docs/tools/glint-envi.md documents them.
#pragma once

#include <ostream>

#include "glint/app_envi/convert.h"
#include "glint/app_envi/encode.h"
#include "glint/app_envi/info.h"
#include "glint/app_envi/stats.h"
#include "glint/core/context.h"

namespace glint::app_envi {

/// The subcommand of a glint-envi run.
enum class Subcommand { info, stats, convert, encode };

/// Options of glint-envi: the subcommand, and the options of each (only the chosen one's are
/// used).
struct Options {
    Subcommand subcommand = Subcommand::info;
    InfoOptions info;
    StatsOptions stats;
    ConvertOptions convert;
    EncodeOptions encode;
};

/// Runs the subcommand: report_info or report_stats write their report to `out`;
/// convert_file and encode_frames write files (nothing to `out`). Returns the exit status
/// (report_info's 1 when a file could not be reported, else 0); other failures are thrown.
int run(const Options& options, Context& ctx, std::ostream& out);

}  // namespace glint::app_envi
