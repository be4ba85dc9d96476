// SPDX-License-Identifier: Apache-2.0
// The truth collectors glint writes (docs/truth.md): each individual collector is one
// quantity, one band (or one band per abundance target or per output channel); a collector
// name in a `<collector>` is either an individual name or the name of a set of them (the
// DIRSIG4-era sets: Material, GeoLocation, Intersection, ...). Names are case-insensitive.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "glint/model/instrument.h"
#include "glint/model/scene.h"

namespace glint::model {

/// One individual truth quantity.
enum class TruthQuantity {
    material_index,  ///< most common first-hit material (index into the scene's materials)
    instance_index,  ///< most common first-hit instance (index into the scene's instances)
    object_index,    ///< most common first-hit geometry object
    abundance,       ///< fraction of the pixel covered by a target: one band per target
    scene_x,         ///< mean first-hit point, scene ENU, m
    scene_y,
    scene_z,
    latitude,   ///< of the mean first-hit point, WGS84, degrees
    longitude,  ///< degrees east
    altitude,   ///< m above the WGS84 ellipsoid
    normal_x,   ///< mean first-hit surface normal (facing the sensor), scene ENU, unit
    normal_y,
    normal_z,
    distance,        ///< mean range from the sample ray's origin to the first hit, m
    shadow,          ///< fraction of first hits that do not see the sun
    temperature,     ///< mean first-hit surface temperature, K
    reflectance,     ///< mean first-hit reflectance at the focal plane's reference wavelength
    sample_count,    ///< paths traced for the pixel
    standard_error,  ///< Monte-Carlo standard error of each output channel: one band each
};

/// What a quantity is called and measured in.
struct TruthQuantityInfo {
    TruthQuantity quantity;
    std::string_view name;   ///< individual collector name (lower case)
    std::string_view label;  ///< band name (abundance and standard error add the target)
    std::string_view units;  ///< empty: the output channel's units (standard error)
    /// Whether the value is undefined for a pixel no sample of which hits a surface (it is
    /// then NaN, the truth images' no-data value).
    bool needs_hit;
};

/// Every individual quantity, in band order.
std::span<const TruthQuantityInfo> truth_quantities() noexcept;
/// The entry of `quantity`.
const TruthQuantityInfo& truth_quantity_info(TruthQuantity quantity) noexcept;

/// A named set of quantities (the DIRSIG4-era collector names).
struct TruthSet {
    std::string_view name;
    std::vector<TruthQuantity> quantities;
};
/// Every set.
std::span<const TruthSet> truth_sets();

/// The quantities collector `name` asks for (a set or an individual name, any case); none
/// when the name is unknown.
std::optional<std::vector<TruthQuantity>> expand_truth_collector(std::string_view name);
/// "known sets: Material, ...; individual collectors: materialindex, ..." for messages.
std::string known_truth_collectors();

/// One target of an Abundance collector, resolved against a scene.
struct AbundanceTarget {
    bool is_tag = false;
    std::string key;  ///< the material id or name, or the tag, as written
    /// Per material (a material target) or per instance (a tag target): 1 when a hit on it
    /// counts for the target.
    std::vector<std::uint8_t> matches;
};

/// The targets of an Abundance collector: each `<materials>` item matches the material with
/// that id, else those with that name (exact text); each `<tags>` item the instances that
/// carry the tag. Throws glint::Error (input, at the collector) for a material item no
/// material matches, listing the scene's ids. A tag no instance carries is kept (its band
/// is 0 everywhere) and a warning saying so is added to `warnings`.
std::vector<AbundanceTarget> resolve_abundance(const TruthCollector& collector, const Scene& scene,
                                               std::vector<std::string>& warnings);

/// Whether a truth collection writes a file: enabled, with collectors and an image file.
bool writes_truth(const TruthCollection& truth) noexcept;

}  // namespace glint::model
