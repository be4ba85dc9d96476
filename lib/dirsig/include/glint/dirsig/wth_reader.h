// SPDX-License-Identifier: Apache-2.0
// DIRSIG's `.wth` weather history: a header line (the number of rows and the hours between
// them) and one row per step of 13 numbers — time (h), air temperature (°C), pressure (mbar),
// relative humidity (fraction), dew point (°C), wind speed (m/s), direct and diffuse
// insolation (Langley/h), sky exposure (0 overcast … 1 clear), cloud type, precipitation
// type, precipitation rate (cm/h) and its temperature (°C). DIRSIG's writer runs a negative
// number into the field before it (`0.00-15.00`): a sign after a digit starts a new number.
// docs/formats.md (".wth").
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "glint/core/diagnostics.h"
#include "glint/dirsig/read_options.h"
#include "glint/model/weather.h"

namespace glint::dirsig {

/// Parses the text of a `.wth` named `file` into SI units; every problem goes to
/// `diagnostics` at its file:line (the history is empty when any is an error).
model::Weather parse_wth(std::string_view text, const std::string& file,
                         Diagnostics& diagnostics);

/// Reads and parses the `.wth` at `path` (a missing or unreadable file is an error in
/// `diagnostics`, and the history empty).
model::Weather read_wth(const std::filesystem::path& path, const ReadOptions& options,
                        Diagnostics& diagnostics);

}  // namespace glint::dirsig
