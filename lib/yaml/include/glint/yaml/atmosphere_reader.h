// SPDX-License-Identifier: Apache-2.0
// glint's own atmosphere files: the YAML atmosphere (model none, parametric, tabulated; keys
// in glint/model/atmosphere.h) and the table file of the tabulated model. (The DIRSIG `.atm`
// is glint/dirsig/atm_reader.h; glint/inputs/scene_atmosphere.h tells the two apart.)
//
// Table file format (glint's definition, docs/physics.md ("Atmosphere and sun")):
//
// | item | rule |
// |---|---|
// | row | 5 or 6 numbers (columns below), separated by blanks or commas |
// | wavelength_um | µm, > 0, strictly increasing |
// | sun_T | direct transmittance top of atmosphere → surface, [0, 1] |
// | sensor_T | direct transmittance surface → sensor, [0, 1] |
// | path_radiance | W/(cm² sr µm) at the sensor, ≥ 0 |
// | sky_irradiance | diffuse irradiance on a horizontal surface, W/(cm² µm), ≥ 0 |
// | thermal_sky | optional 6th column: sky emission, W/(cm² sr µm), ≥ 0 |
// | rows | at least 2, all with the same number of columns |
// | comments | `#` to the end of the line; blank lines skipped; CRLF accepted |
#pragma once

#include <filesystem>
#include <string>

#include "glint/core/diagnostics.h"
#include "glint/dirsig/read_options.h"
#include "glint/model/atmosphere.h"

namespace glint::yaml {

/// Parses the `text` of a YAML atmosphere file `path` (named `display_name` in messages,
/// default: the path). Problems go to `diagnostics` with file:line (YAML syntax errors, an
/// unknown or missing `model`, values out of range, an unreadable table as errors; unknown
/// keys as warnings). Table files are resolved against the folder of `path` and read through
/// `options`.
model::Atmosphere parse_yaml_atmosphere(const std::string& text, const std::filesystem::path& path,
                                        const std::string& display_name,
                                        const dirsig::ReadOptions& options,
                                        Diagnostics& diagnostics);

/// Reads a tabulated-atmosphere table file (format above), reporting each bad row with the
/// file and line. `display_name` names the file in messages (default: the path).
model::TabulatedAtmosphere read_atmosphere_table(const std::filesystem::path& path,
                                                 const dirsig::ReadOptions& options,
                                                 Diagnostics& diagnostics,
                                                 const std::string& display_name = {});

}  // namespace glint::yaml
