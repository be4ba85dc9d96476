// SPDX-License-Identifier: Apache-2.0
// Scene data built in code (glint/model/scene.h).
#include "glint/model/scene.h"

namespace glint::model {

Material flat_material(const std::string& id, double reflectance, double temperature_k,
                       std::optional<double> emissivity, SpecularLobe specular) {
    Material m;
    m.id = id;
    m.name = id;
    m.reflectance.wavelengths_um = {0.1, 100.0};
    m.reflectance.values = {reflectance, reflectance};
    const double e = emissivity.value_or(1.0 - reflectance);
    m.emissivity.wavelengths_um = {0.1, 100.0};
    m.emissivity.values = {e, e};
    m.emissivity_is_default = !emissivity.has_value();
    m.temperature_k = temperature_k;
    m.specular = specular;
    return m;
}

}  // namespace glint::model
