// SPDX-License-Identifier: Apache-2.0
// Helpers of the capture method (glint/model/capture.h).
#include "glint/model/capture.h"

#include <cmath>

namespace glint::model {

std::uint64_t SignalGate::bin_count() const {
    if (!(bin_width_s > 0.0) || !(stop_s > start_s)) return 0;
    return static_cast<std::uint64_t>(std::llround((stop_s - start_s) / bin_width_s));
}

}  // namespace glint::model
