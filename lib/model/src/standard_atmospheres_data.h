// SPDX-License-Identifier: Apache-2.0
// The tables of the standard atmospheres (standard_atmospheres_data.cpp), private to
// lib/model.
#pragma once

#include <span>

#include "glint/model/standard_atmospheres.h"

namespace glint::model::detail {

/// The levels of `which`, 0-100 km ascending (empty for isothermal).
std::span<const AtmosphereLevel> standard_atmosphere_levels(StandardAtmosphere which) noexcept;

}  // namespace glint::model::detail
