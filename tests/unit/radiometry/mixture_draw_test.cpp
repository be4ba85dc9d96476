// SPDX-License-Identifier: Apache-2.0
// Tests of a mixture texel's material draw (glint/radiometry/mixture_draw.h): each material is
// drawn over a share of [0, 1) equal to its weight, zero weights are never drawn, and rounding
// past the sum lands on the last material with a weight.
#include "glint/radiometry/mixture_draw.h"

#include <gtest/gtest.h>

#include <array>
#include <vector>

namespace glint::radiometry {
namespace mixture_draw_test {

TEST(MixtureDraw, EachMaterialOverItsWeight) {
    const std::array<std::uint32_t, 4> materials{7, 8, 9, 10};
    const std::array<float, 4> weights{0.25f, 0.0f, 0.75f, 0.0f};
    const scene::MaterialMix mix{materials, weights};
    EXPECT_EQ(draw_from_mix(mix, 0.0), 7u);
    EXPECT_EQ(draw_from_mix(mix, 0.2499), 7u);
    EXPECT_EQ(draw_from_mix(mix, 0.25), 9u);  // the zero weight between is skipped
    EXPECT_EQ(draw_from_mix(mix, 0.9999), 9u);
    EXPECT_EQ(draw_from_mix(mix, 1.0), 9u);  // past the sum: the last with a weight
    // Over a stratified [0, 1): the shares are the weights.
    std::array<int, 11> counts{};
    constexpr int kDraws = 10'000;
    for (int i = 0; i < kDraws; ++i) ++counts[draw_from_mix(mix, (i + 0.5) / kDraws)];
    EXPECT_EQ(counts[7], 2'500);
    EXPECT_EQ(counts[9], 7'500);
    EXPECT_EQ(counts[8] + counts[10], 0);
}

TEST(MixtureDraw, OnlyAMixtureHitDrawsANumber) {
    RandomStream a(1, {2});
    RandomStream b(1, {2});
    scene::RayHit hit;
    hit.material = 3;
    // No mixture: nothing drawn, the material kept; a's next number is b's first.
    model::Scene model_scene;
    const scene::GeometryScene empty = scene::GeometryScene::build(model_scene, {}, {});
    draw_mixture_material(empty, hit, a);
    EXPECT_EQ(hit.material, 3u);
    EXPECT_EQ(a.uniform(), b.uniform());
}

}  // namespace mixture_draw_test
}  // namespace glint::radiometry
