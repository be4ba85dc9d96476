// SPDX-License-Identifier: Apache-2.0
// Simulation helpers: finding the BasicPlatform and BasicAtmosphere entries among the plugins.
#include "glint/model/simulation.h"

namespace glint::model {

std::vector<std::size_t> Simulation::basic_platform_indices() const {
    std::vector<std::size_t> indices;
    for (std::size_t i = 0; i < plugins.size(); ++i) {
        if (plugins[i].basic_platform) indices.push_back(i);
    }
    return indices;
}

const BasicAtmosphereInputs* Simulation::atmosphere() const {
    for (const Plugin& plugin : plugins) {
        if (plugin.basic_atmosphere) return &*plugin.basic_atmosphere;
    }
    return nullptr;
}

}  // namespace glint::model
