// SPDX-License-Identifier: Apache-2.0
// The weather history a simulation names: a `.jsim`'s ThermWeather plugin (`filename`,
// relative to the .jsim), else its `.atm`'s `<uniformweather><classicdata><filename>`
// (relative to the .atm). docs/thermal.md ("Weather").
#pragma once

#include "glint/core/diagnostics.h"
#include "glint/core/log.h"
#include "glint/dirsig/read_options.h"
#include "glint/model/atmosphere.h"
#include "glint/model/scene.h"
#include "glint/model/simulation.h"
#include "glint/model/weather.h"

namespace glint::inputs {

/// Reads the weather history `simulation` (and its atmosphere `atmosphere`) names, checked
/// row by row (glint/dirsig/wth_reader.h); empty when none is named. A bad row is an error in
/// `diagnostics`; a ThermWeather plugin without a `filename` input or a missing file is an
/// error when the weather is `needed` (a material uses THERM), else a warning (DIRSIG's
/// simulations name a weather whether or not a material uses it); naming none when it is
/// needed is an error at the simulation file. A ThermWeather plugin
/// beside an `.atm` that names a weather too is a warning at the .atm's (the plugin's is used).
model::Weather read_simulation_weather(const model::Simulation& simulation,
                                       const model::Atmosphere& atmosphere,
                                       const dirsig::ReadOptions& options, bool needed,
                                       Diagnostics& diagnostics, const Log& log = {});

/// Whether a material of `scene` uses THERM (and so needs the weather).
bool needs_weather(const model::Scene& scene) noexcept;

}  // namespace glint::inputs
