// SPDX-License-Identifier: Apache-2.0
// The power-spectral-density tables of correlated jitter: the reader of PSD text files (the
// `psdfile` of `<rotationdeviates>` axes and of platform jitter) whose rows are checked by
// model::check_psd_row, the rules inline tables (FlexMotion `<psd>` entries) follow too. The
// synthesis lives in glint/motion/jitter.h.
//
// File format (glint's definition, docs/motion.md ("Jitter")):
//
// | item | rule |
// |---|---|
// | row | `frequency psd [phase]`: 2 or 3 numbers, separated by blanks or one comma |
// | frequency | Hz, ≥ 0, strictly increasing from row to row |
// | psd | one-sided, ≥ 0, unit²/Hz (m²/Hz for location axes, rad²/Hz for rotation axes) |
// | phase | rad, any finite value; either every row has one or none has |
// | comments | `#` to the end of the line; blank lines skipped; CRLF and a BOM accepted |
// | rows | at least 2 |
#pragma once

#include <filesystem>
#include <string>

#include "glint/core/diagnostics.h"
#include "glint/dirsig/read_options.h"
#include "glint/model/jitter.h"

namespace glint::dirsig {

/// Reads a PSD text file. Reports every bad row to `diagnostics` as an error with the file
/// and line (non-numeric or non-finite values, a wrong number of values, rows with and
/// without a phase mixed, a negative frequency or PSD, a frequency not greater than the
/// previous one) and carries on; also fewer than 2 rows, and a file that cannot be read.
/// Diagnostics and the table's `where` name the file as `display_name` (default: the path);
/// `where.line` is the line of the first row.
model::PsdTable read_psd_file(const std::filesystem::path& file, const ReadOptions& options,
                              Diagnostics& diagnostics, const std::string& display_name = {});

}  // namespace glint::dirsig
