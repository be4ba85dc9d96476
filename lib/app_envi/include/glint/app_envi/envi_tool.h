// SPDX-License-Identifier: Apache-2.0
// glint-envi's entry point: one of its subcommands (info, stats, convert, encode, merge) with
// its options, run as the other tools are run. docs/tools/glint-envi.md documents them.
#pragma once

#include <ostream>

#include "glint/app_envi/convert.h"
#include "glint/app_envi/encode.h"
#include "glint/app_envi/info.h"
#include "glint/app_envi/merge.h"
#include "glint/app_envi/stats.h"
#include "glint/core/context.h"

namespace glint::app_envi {

/// The subcommand of a glint-envi run.
enum class Subcommand { info, stats, convert, encode, merge };

/// Options of glint-envi: the subcommand, and the options of each (only the chosen one's are
/// used).
struct Options {
    Subcommand subcommand = Subcommand::info;
    InfoOptions info;
    StatsOptions stats;
    ConvertOptions convert;
    EncodeOptions encode;
    MergeOptions merge;
};

/// Runs the subcommand: report_info or report_stats write their report to `out`;
/// convert_file and encode_frames write files (nothing to `out`); merge_parts writes files
/// and lists them on `out`. Returns the exit status
/// (report_info's 1 when a file could not be reported, else 0); other failures are thrown.
int run(const Options& options, Context& ctx, std::ostream& out);

}  // namespace glint::app_envi
