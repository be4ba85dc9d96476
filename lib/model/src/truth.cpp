// SPDX-License-Identifier: Apache-2.0
// The truth collector catalogue (glint/model/truth.h).
#include "glint/model/truth.h"

#include <array>

#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::model {
namespace {

using Q = TruthQuantity;

constexpr std::array<TruthQuantityInfo, 19> kQuantities{{
    {Q::material_index, "materialindex", "Material Index", "index", true},
    {Q::instance_index, "instanceindex", "Instance Index", "index", true},
    {Q::object_index, "objectindex", "Object Index", "index", true},
    {Q::abundance, "abundance", "Abundance", "fraction", false},
    {Q::scene_x, "scenex", "Scene X", "m", true},
    {Q::scene_y, "sceney", "Scene Y", "m", true},
    {Q::scene_z, "scenez", "Scene Z", "m", true},
    {Q::latitude, "latitude", "Latitude", "degrees", true},
    {Q::longitude, "longitude", "Longitude", "degrees", true},
    {Q::altitude, "altitude", "Altitude", "m", true},
    {Q::normal_x, "normalx", "Normal X", "unit", true},
    {Q::normal_y, "normaly", "Normal Y", "unit", true},
    {Q::normal_z, "normalz", "Normal Z", "unit", true},
    {Q::distance, "distance", "Distance", "m", true},
    {Q::shadow, "shadowfraction", "Shadow Fraction", "fraction", true},
    {Q::temperature, "temperature", "Temperature", "K", true},
    {Q::reflectance, "reflectance", "Reflectance", "fraction", true},
    {Q::sample_count, "samplecount", "Sample Count", "paths", false},
    {Q::standard_error, "standarderror", "Standard Error", "", false},
}};

}  // namespace

std::span<const TruthQuantityInfo> truth_quantities() noexcept { return kQuantities; }

const TruthQuantityInfo& truth_quantity_info(TruthQuantity quantity) noexcept {
    return kQuantities[static_cast<std::size_t>(quantity)];
}

std::span<const TruthSet> truth_sets() {
    static const std::vector<TruthSet> sets{
        {"Material", {Q::material_index}},
        {"Abundance", {Q::abundance}},
        {"GeoLocation",
         {Q::scene_x, Q::scene_y, Q::scene_z, Q::latitude, Q::longitude, Q::altitude}},
        {"Intersection",
         {Q::scene_x, Q::scene_y, Q::scene_z, Q::normal_x, Q::normal_y, Q::normal_z, Q::distance}},
        {"Shadow", {Q::shadow}},
        {"Temperature", {Q::temperature}},
        {"Reflectance", {Q::reflectance}},
        {"SampleCount", {Q::sample_count}},
        {"StandardError", {Q::standard_error}},
        {"InstanceId", {Q::instance_index, Q::object_index}},
    };
    return sets;
}

std::optional<std::vector<TruthQuantity>> expand_truth_collector(std::string_view name) {
    const std::string_view trimmed = trim(name);
    for (const TruthSet& set : truth_sets()) {
        if (iequals(set.name, trimmed)) return set.quantities;
    }
    for (const TruthQuantityInfo& info : kQuantities) {
        if (iequals(info.name, trimmed)) return std::vector<TruthQuantity>{info.quantity};
    }
    return std::nullopt;
}

std::string known_truth_collectors() {
    std::string text = "known sets: ";
    bool first = true;
    for (const TruthSet& set : truth_sets()) {
        text += (first ? "" : ", ") + std::string(set.name);
        first = false;
    }
    text += "; individual collectors: ";
    first = true;
    for (const TruthQuantityInfo& info : kQuantities) {
        text += (first ? "" : ", ") + std::string(info.name);
        first = false;
    }
    return text;
}

std::vector<AbundanceTarget> resolve_abundance(const TruthCollector& collector, const Scene& scene,
                                               std::vector<std::string>& warnings) {
    std::vector<AbundanceTarget> targets;
    for (const std::string& item : collector.materials) {
        AbundanceTarget target{false, item, std::vector<std::uint8_t>(scene.materials.size(), 0)};
        bool by_id = false;
        for (std::size_t m = 0; m < scene.materials.size(); ++m) {
            if (scene.materials[m].id == item) {
                target.matches[m] = 1;
                by_id = true;
            }
        }
        bool any = by_id;
        for (std::size_t m = 0; m < scene.materials.size() && !by_id; ++m) {
            if (scene.materials[m].name == item) {
                target.matches[m] = 1;
                any = true;
            }
        }
        if (!any) {
            std::string known;
            for (std::size_t m = 0; m < scene.materials.size(); ++m) {
                if (m == 12) {
                    known += ", ... (" + std::to_string(scene.materials.size()) + " in all)";
                    break;
                }
                known += (m > 0 ? ", " : "") + quote(scene.materials[m].id);
            }
            throw input_error("Abundance material " + quote(item) +
                                  " is not a material id or name of the scene (its ids: " +
                                  (known.empty() ? std::string("none") : known) + ")",
                              collector.where);
        }
        targets.push_back(std::move(target));
    }
    for (const std::string& tag : collector.tags) {
        AbundanceTarget target{true, tag, std::vector<std::uint8_t>(scene.instances.size(), 0)};
        bool any = false;
        for (std::size_t i = 0; i < scene.instances.size(); ++i) {
            for (const std::string& t : scene.instances[i].tags) {
                if (t == tag) {
                    target.matches[i] = 1;
                    any = true;
                }
            }
        }
        if (!any) {
            warnings.push_back("Abundance tag " + quote(tag) +
                               " is carried by no instance of the scene: its band is 0 "
                               "everywhere");
        }
        targets.push_back(std::move(target));
    }
    return targets;
}

bool writes_truth(const TruthCollection& truth) noexcept {
    return truth.enabled && !truth.collectors.empty() && !truth.image_file.basename.empty();
}

}  // namespace glint::model
