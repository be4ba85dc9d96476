// SPDX-License-Identifier: Apache-2.0
// Internal: the checks every demosaicing method makes on its input plane.
#pragma once

#include "glint/demosaic/demosaic.h"

namespace glint::demosaic::internal {

/// Throws glint::Error (input) when the plane's values do not match its size or the plane is
/// smaller than one block of `pattern`.
void check_plane(const Plane& plane, CfaPattern pattern);

}  // namespace glint::demosaic::internal
