// SPDX-License-Identifier: Apache-2.0
// A lidar transmitter's tabulated temporal pulse shape (`<pulseshape type="tabulated">`'s
// `<filename>`, docs/lidar.md), read by the input loader. glint's definition of the file:
//
// clang-format off
// | content | rule |
// |---|---|
// | row | `time power`: 2 numbers separated by blanks or one comma |
// | time | s after the pulse's reference (firing) time, finite, strictly increasing |
// | power | relative (any scale; normalised to unit energy), finite, ≥ 0, some > 0 |
// | comments | `#` to the end of the line; blank lines skipped; CRLF accepted |
// | rows | at least 2 |
// clang-format on
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "glint/core/diagnostics.h"
#include "glint/dirsig/read_options.h"
#include "glint/model/instrument.h"

namespace glint::dirsig {

/// Parses the text of a pulse-shape file; every bad row goes to `diagnostics` as an error at
/// `file_name:line`. The rows that were valid are returned.
model::PulseShapeTable parse_pulse_shape(std::string_view text, const std::string& file_name,
                                         Diagnostics& diagnostics);

/// Reads `file` (errors as parse_pulse_shape, and one when it cannot be read), naming it
/// `display_name` (default: the path).
model::PulseShapeTable read_pulse_shape_file(const std::filesystem::path& file,
                                             const ReadOptions& options, Diagnostics& diagnostics,
                                             const std::string& display_name = {});

}  // namespace glint::dirsig
