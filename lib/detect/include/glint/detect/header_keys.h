// SPDX-License-Identifier: Apache-2.0
// What a detected product's ENVI header says about its detection, shared by glint-detect and
// in-render detection so that both write the same keys: the data units, the band names of a
// mosaic, and one `glint ...` key per parameter applied.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "glint/detect/detector.h"

namespace glint::detect {

/// `data units` of the output: "DN", "Electrons" (--electrons), or `input_units` when there
/// is no detector model (mosaic or TDI pass-through).
std::string output_data_units(const DetectionSettings& settings, const std::string& input_units);

/// `band names` of a mosaic output ({"bayer mosaic"} or {"truesense mosaic"}); empty without
/// a CFA (the channel names are kept).
std::vector<std::string> output_band_names(const DetectionSettings& settings);

/// The header keys of the settings, in this order: `glint seed`, `glint detector ...`
/// (quantum efficiency, read noise e, dark current density a per m2, integration time s,
/// pixel area m2, dark electrons, min electrons, max electrons, bit depth, gain dn per e,
/// noise, output; only with a detector model), `glint tdi stages`, `glint tdi mode` (TDI
/// only), `glint cfa pattern`, `glint cfa phase` (Bayer), `glint cfa filters` (CFA only).
std::vector<std::pair<std::string, std::string>> detection_header_keys(
    const DetectionSettings& settings);

}  // namespace glint::detect
