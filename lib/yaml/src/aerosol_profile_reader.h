// SPDX-License-Identifier: Apache-2.0
// The YAML atmosphere's `aerosol_profile` (glint/model/atmosphere.h, AerosolProfile): a user's
// layers of OPAC components, read for the atmosphere reader (atmosphere_reader.cpp). The keys
// and their rules: docs/scene.md ("Atmosphere", "A user's aerosol profile").
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

#include "glint/core/diagnostics.h"
#include "glint/model/atmosphere.h"

namespace glint::yaml::detail {

/// Reads `root`'s aerosol_profile into `p` when there is one, with the keys that go with it:
/// aerosol_optical_depth_550 scales it, relative_humidity_percent replaces its layers' own
/// humidities; aerosol_model, visibility_km and the exponential aerosol's keys are errors
/// beside it, the layered aerosol's other keys warnings. Problems are diagnostics at their
/// file:line; after an error `p.aerosol_profile` stays unset.
void read_aerosol_profile(const YAML::Node& root, const std::string& file,
                          model::ParametricAtmosphere& p, Diagnostics& diagnostics);

}  // namespace glint::yaml::detail
