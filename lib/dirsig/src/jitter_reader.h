// SPDX-License-Identifier: Apache-2.0
// The one reader of a jitter axis (jitter_reader.cpp), shared by the motion files' platform
// jitter (`locationjitter`, `orientationjitter`: `xaxis`, `yaxis`, `zaxis`) and the
// `.platform`'s mount jitter (`<rotationdeviates>`: `xrotation`, `yrotation`, `zrotation`).
#pragma once

#include <filesystem>

#include "glint/core/diagnostics.h"
#include "glint/dirsig/read_options.h"
#include "glint/io/xml.h"
#include "glint/model/jitter.h"

namespace glint::dirsig::detail {

/// What a jitter axis moves: a location (values in m, a PSD in m²/Hz) or an angle (rad, rad²/Hz).
enum class JitterQuantity { length, angle };

/// Reads one jitter axis: its `type` (correlated or psd; uncorrelated, normal or gaussian;
/// none; absent: told by its children), an uncorrelated axis' `<mean>` and `<stddev>` (or
/// `<sigma>`), a correlated axis' inline `<psd>` entry table (frequencyunits, magnitudeunits,
/// phaseunits) or its `<psdfile>` (or `<filename>`) resolved against `base_dir`. Values are
/// in the axis' own `spatialunits`/`angularunits`, else `parent_factor` (SI per unit of the
/// parent element). Every problem goes to `diagnostics` at its element.
model::JitterSpec read_jitter_axis(const io::XmlNode& axis, JitterQuantity quantity,
                                   double parent_factor, const ReadOptions& options,
                                   const std::filesystem::path& base_dir, Diagnostics& diagnostics);

}  // namespace glint::dirsig::detail
