// SPDX-License-Identifier: Apache-2.0
// Number formatting shared by messages and file writers.
#pragma once

#include <string>

namespace glint {

/// The shortest text that reads back as exactly `value` ("0.55", "1e-300", "inf").
std::string format_shortest(double value);

}  // namespace glint
