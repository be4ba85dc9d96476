// SPDX-License-Identifier: Apache-2.0
// The normalized platform JSON (`glint-platform2jsim --dump-platform`): every field of a
// model::Platform with its default resolved (nothing omitted; absent optional values are
// null), lengths in m, times in s, angles in rad, rates in Hz, wavelengths in µm, keys
// suffixed with their unit, enumerations in their XML spelling, plus derived quantities
// (F#, G#, pixel IFOV and field of view, channel integrals). The schema, "glint-platform"
// version 1, is documented in docs/formats.md.
#pragma once

#include <string>

#include "glint/model/platform.h"

namespace glint::app_platform2jsim {

/// The `format` and `version` of the normalized platform JSON.
inline constexpr const char* kPlatformJsonFormat = "glint-platform";
inline constexpr int kPlatformJsonVersion = 1;

/// The normalized JSON of `platform`, `indent` spaces per level (negative: one line), no
/// trailing newline. Instruments are listed flat in list_instruments() order (their index);
/// the attachment tree refers to them by index. Derived values that cannot be computed (no
/// aperture, an invalid bandpass) are null. Never throws for a well-formed model.
std::string platform_to_json(const model::Platform& platform, int indent = 2);

}  // namespace glint::app_platform2jsim
