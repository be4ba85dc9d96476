// SPDX-License-Identifier: Apache-2.0
// `glint-envi merge PART_FOLDER... -o OUT`: joins the files sharded glint-render runs wrote
// (each into its own folder: shards by captures, by rows, or both) into the files one run
// would have written (docs/scale.md). Files are matched by their path relative to their
// part folder. A file without `glint part ...` keys (glint/io/envi_part.h) is whole and is
// copied; the parts of one file are joined capture by capture, band of lines by band, after
// checking that they cover every line of every capture of the whole file exactly once and
// agree on everything else their headers say. The result equals the single run's file byte
// for byte, and its header every key but `glint command line` (the merge's). Lidar BIN
// files (never split by glint-render) are copied; other files are named in one warning and
// left. Nothing is written until every file has been checked; each file is then written
// atomically.
#pragma once

#include <filesystem>
#include <vector>

#include "glint/core/context.h"

namespace glint::app_envi {

/// Options of `merge`.
struct MergeOptions {
    std::vector<std::filesystem::path> parts;  ///< the part folders, in the order given
    std::filesystem::path output_folder;       ///< -o: where the whole files go
    /// --expect: a glint-schedule JSON of the whole run (made with the output folder
    /// `output_folder`): every image and truth file it lists must come out, and nothing else.
    std::filesystem::path expect;
};

/// Merges; returns the files written, in path order. Throws glint::Error: usage for bad
/// options (no part, a part that is the output folder), input when the parts do not make
/// whole files (every problem is logged through ctx.log.error first, each naming the file
/// and the parts), io when a file cannot be read or written.
std::vector<std::filesystem::path> merge_parts(const MergeOptions& options, Context& ctx);

}  // namespace glint::app_envi
