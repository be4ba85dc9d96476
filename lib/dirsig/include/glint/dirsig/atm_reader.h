// SPDX-License-Identifier: Apache-2.0
// The DIRSIG `.atm` atmosphere: the simpleradiativetransfer subset (apparent sky
// temperature); other radiative-transfer blocks are errors, weather blocks warnings.
#pragma once

#include <string>
#include <string_view>

#include "glint/core/diagnostics.h"
#include "glint/model/atmosphere.h"

namespace glint::dirsig {

/// Parses the text of a `.atm` file named `file` in diagnostics. Throws glint::Error (input)
/// when the text is not XML with an `<atmosphericconditions>` root; every other problem goes
/// to `diagnostics`.
model::Atmosphere parse_atm(std::string_view text, const std::string& file,
                            Diagnostics& diagnostics);

}  // namespace glint::dirsig
