// SPDX-License-Identifier: Apache-2.0
// Internal interface of the `.mat` reader's curve files: the text of a file a `.mat`
// `REFLECTANCE_PROP`/`EMISSIVITY_PROP` names, read as a two-column curve (wavelength µm,
// value) or as a classic DIRSIG `.ems` (curve count, angular table, curves in µm after
// `CURVE_BEGIN` or in descending cm⁻¹). docs/formats.md ("Material curve files") gives the
// layouts. Also the reflectance limit a `.mat` material with both curves gets.
#pragma once

#include <string>
#include <vector>

#include "glint/core/diagnostics.h"
#include "glint/model/scene.h"

namespace glint::dirsig::detail {

/// Where a curve file's text came from, for its messages.
struct CurveSource {
    std::string file;      ///< display name of the curve file
    std::string element;   ///< the `.mat` key path naming it
    std::string quantity;  ///< "reflectance", "emissivity" or "intensity"
    /// The largest value accepted: 1 for reflectance and emissivity, infinity for a source's
    /// intensity (W/(sr µm)). Values below 0 are always refused.
    double max_value = 1.0;
};

/// Parses `text` into `table`'s wavelengths and values (increasing µm, values in
/// [0, source.max_value]).
/// Each problem goes to `diagnostics` at the curve file's line; a text in neither layout is
/// one error. An empty table on return means nothing usable was read (always reported).
/// A classic .ems with several curves (texture classes) also gives every curve, the first
/// included, in file order, to `classes` when it is given.
void parse_curve_text(const std::string& text, const CurveSource& source,
                      model::SpectralTable& table, Diagnostics& diagnostics,
                      std::vector<model::SpectralTable>* classes = nullptr);

/// Where `material`'s emissivity + reflectance exceed 1 by more than
/// model::kEmissivityReflectanceSlack inside both curves' range, lowers the reflectance to
/// 1 − emissivity (on the union of both curves' wavelengths there) with one warning at the
/// material; a smaller excess (rounding) is left alone silently.
void limit_reflectance(model::Material& material, Diagnostics& diagnostics);

}  // namespace glint::dirsig::detail
