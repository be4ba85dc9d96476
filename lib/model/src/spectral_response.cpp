// SPDX-License-Identifier: Apache-2.0
// Member functions of the spectral-response model: looking up a colour-filter-array
// pattern's channel for a filter.
#include "glint/model/spectral_response.h"

namespace glint::model {

std::optional<std::string> ChannelPattern::channel_for(const std::string& filter) const {
    for (const auto& [filter_name, channel_name] : mappings) {
        if (filter_name == filter) return channel_name;
    }
    return std::nullopt;
}

}  // namespace glint::model
