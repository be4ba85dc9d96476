// SPDX-License-Identifier: Apache-2.0
// The truth collector catalogue (docs/truth.md): set and individual names in any case, the
// sets' band order, unknown names, and Abundance targets resolved against a scene (material
// by id, then by name; tags by instance; an unknown material is an error at the collector).
#include "glint/model/truth.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "glint/core/error.h"

namespace glint::model {
namespace truth_test {

using Q = TruthQuantity;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

TEST(TruthCatalogue, SetAndIndividualNamesInAnyCase) {
    EXPECT_THAT(*expand_truth_collector("Material"), ElementsAre(Q::material_index));
    EXPECT_THAT(*expand_truth_collector("materialindex"), ElementsAre(Q::material_index));
    EXPECT_THAT(*expand_truth_collector(" MATERIALINDEX "), ElementsAre(Q::material_index));
    EXPECT_THAT(
        *expand_truth_collector("geolocation"),
        ElementsAre(Q::scene_x, Q::scene_y, Q::scene_z, Q::latitude, Q::longitude, Q::altitude));
    EXPECT_THAT(*expand_truth_collector("Intersection"),
                ElementsAre(Q::scene_x, Q::scene_y, Q::scene_z, Q::normal_x, Q::normal_y,
                            Q::normal_z, Q::distance));
    EXPECT_THAT(*expand_truth_collector("InstanceId"),
                ElementsAre(Q::instance_index, Q::object_index));
    EXPECT_FALSE(expand_truth_collector("Materials").has_value());
    EXPECT_FALSE(expand_truth_collector("").has_value());
}

TEST(TruthCatalogue, EveryQuantityHasOneEntryNamedUniquely) {
    std::set<std::string> names;
    std::size_t i = 0;
    for (const TruthQuantityInfo& info : truth_quantities()) {
        EXPECT_EQ(static_cast<std::size_t>(info.quantity), i++) << info.name;
        EXPECT_TRUE(names.insert(std::string(info.name)).second) << info.name;
        EXPECT_EQ(&truth_quantity_info(info.quantity), &info);
        // Every individual name is accepted on its own.
        EXPECT_THAT(*expand_truth_collector(info.name), ElementsAre(info.quantity));
    }
    const std::string known = known_truth_collectors();
    for (const TruthSet& set : truth_sets()) EXPECT_THAT(known, HasSubstr(set.name));
    for (const std::string& name : names) EXPECT_THAT(known, HasSubstr(name));
}

Scene two_materials() {
    Scene scene;
    scene.materials = {flat_material("10", 0.2), flat_material("11", 0.5)};
    scene.materials[0].name = "grass";
    scene.materials[1].name = "Grass";
    scene.instances.resize(3);
    scene.instances[1].tags = {"car", "red"};
    scene.instances[2].tags = {"car"};
    return scene;
}

TEST(TruthCatalogue, AbundanceMaterialsById_ThenByName_TagsByInstance) {
    const Scene scene = two_materials();
    TruthCollector collector;
    collector.name = "Abundance";
    collector.materials = {"11", "grass"};
    collector.tags = {"car", "truck"};
    std::vector<std::string> warnings;
    const std::vector<AbundanceTarget> targets = resolve_abundance(collector, scene, warnings);
    ASSERT_EQ(targets.size(), 4u);
    EXPECT_FALSE(targets[0].is_tag);
    EXPECT_THAT(targets[0].matches, ElementsAre(0, 1));  // id 11
    EXPECT_THAT(targets[1].matches, ElementsAre(1, 0));  // name "grass" (case-sensitive)
    EXPECT_TRUE(targets[2].is_tag);
    EXPECT_THAT(targets[2].matches, ElementsAre(0, 1, 1));
    EXPECT_THAT(targets[3].matches, ElementsAre(0, 0, 0));
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_THAT(warnings[0], HasSubstr("Abundance tag \"truck\" is carried by no instance"));
}

TEST(TruthCatalogue, AbundanceUnknownMaterialIsAnErrorAtTheCollectorListingTheIds) {
    const Scene scene = two_materials();
    TruthCollector collector;
    collector.name = "Abundance";
    collector.materials = {"asphalt"};
    collector.where = {"p.platform", 12, "collector"};
    std::vector<std::string> warnings;
    try {
        resolve_abundance(collector, scene, warnings);
        FAIL() << "no error";
    } catch (const Error& error) {
        EXPECT_EQ(error.category(), ErrorCategory::input);
        EXPECT_EQ(error.context().line, 12);
        EXPECT_THAT(error.message(),
                    HasSubstr("Abundance material \"asphalt\" is not a material id or name of "
                              "the scene (its ids: \"10\", \"11\")"));
    }
}

TEST(TruthCatalogue, WritesTruthOnlyWhenEnabledWithCollectorsAndAFile) {
    TruthCollection truth;
    truth.image_file.basename = "t";
    EXPECT_FALSE(writes_truth(truth));  // no collector
    truth.collectors.push_back({"Material", {}, {}, {}});
    EXPECT_TRUE(writes_truth(truth));
    truth.enabled = false;
    EXPECT_FALSE(writes_truth(truth));
    truth.enabled = true;
    truth.image_file.basename.clear();
    EXPECT_FALSE(writes_truth(truth));
}

}  // namespace truth_test
}  // namespace glint::model
