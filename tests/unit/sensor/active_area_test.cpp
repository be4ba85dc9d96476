// SPDX-License-Identifier: Apache-2.0
// The active-area mask (ActiveArea) and its use in PixelRaySource: a mask with the left half
// black moves every sample into the right half (a thin line's centroid moves by a quarter
// element) and halves the response; a circular mask's response to an edge swept across the
// pixel follows the disc's area on the bright side; bad masks are refused.
#include "glint/sensor/active_area.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <vector>

#include "glint/core/error.h"
#include "glint/core/rng.h"
#include "glint/io/image.h"
#include "glint/motion/euler.h"
#include "glint/motion/rigid.h"
#include "glint/sensor/camera.h"
#include "glint/sensor/pixel_ray_source.h"
#include "glint/test/platforms.h"
#include "glint/test/temp_dir.h"

namespace glint::sensor {
namespace active_area_test {

RandomStream stream(std::uint64_t problem, std::uint64_t sample) {
    return RandomStream(23, {0, 0, 0, problem, sample});
}

GreyImage left_half_black() {
    GreyImage mask{8, 8, std::vector<double>(64, 1.0)};
    for (std::size_t y = 0; y < 8; ++y) {
        for (std::size_t x = 0; x < 4; ++x) mask.values[y * 8 + x] = 0.0;
    }
    return mask;
}

TEST(ActiveArea, LeftHalfBlackMovesTheCentroidAQuarterElementAndHalvesTheResponse) {
    const ActiveArea mask(left_half_black(), "half.png");
    EXPECT_DOUBLE_EQ(mask.mean_sensitivity(), 0.5);  // a uniform field's signal halves
    EXPECT_EQ(mask.description(), "half.png 8 x 8, mean sensitivity 0.5");

    // Through the ray source: pixel (5, 3) of a 10 × 6 nadir camera, element = pitch.
    model::DetectorArray a;
    a.x_count = 10;
    a.y_count = 6;
    a.x_spacing_m = a.y_spacing_m = a.x_size_m = a.y_size_m = 10e-6;
    model::InstrumentProperties p;
    p.focal_length_m = 0.1;
    const CameraModel camera(p, a, 10, 6);
    const motion::PoseService poses(test::one_mount_platform(),
                                    std::make_unique<test::HoverTrajectory>(1000.0), {}, {});
    const motion::Rigid to_instrument = motion::inverse(poses.instrument_to_scene(0, 0.0));
    for (const bool masked : {false, true}) {
        const PixelRaySource source(camera, poses, 0, {0.0, 0.0, 0.0}, nullptr,
                                    masked ? &mask : nullptr);
        double sum_column = 0.0, sum_row = 0.0;
        constexpr int kSamples = 20000;
        for (int n = 0; n < kSamples; ++n) {
            RandomStream rng = stream(3 * 10 + 5, static_cast<std::uint64_t>(n));
            const auto ray = source.generate(3 * 10 + 5, static_cast<std::uint64_t>(n), rng);
            const auto at = camera.project(motion::apply_direction(to_instrument, ray.direction));
            ASSERT_TRUE(at.has_value());
            if (masked) {
                ASSERT_GE((*at)[0], 5.5 - 1e-9);  // px: never on the black half
            }
            sum_column += (*at)[0];
            sum_row += (*at)[1];
        }
        // The centroid a thin line target would see: the pixel centre, moved a quarter
        // element right by the mask. 20 000 uniform draws: standard error 0.002 px.
        EXPECT_NEAR(sum_column / kSamples, masked ? 5.75 : 5.5, 0.01) << masked;
        EXPECT_NEAR(sum_row / kSamples, 3.5, 0.01) << masked;
    }
}

TEST(ActiveArea, CircularMaskFollowsTheDiscAreaUnderASweptEdge) {
    // A disc of radius 0.4 element on 200 × 200 mask pixels (binary).
    constexpr std::size_t kSide = 200;
    constexpr double kRadius = 0.4;
    GreyImage disc{kSide, kSide, std::vector<double>(kSide * kSide, 0.0)};
    for (std::size_t y = 0; y < kSide; ++y) {
        for (std::size_t x = 0; x < kSide; ++x) {
            const double u = (x + 0.5) / kSide - 0.5, v = (y + 0.5) / kSide - 0.5;
            if (u * u + v * v <= kRadius * kRadius) disc.values[y * kSide + x] = 1.0;
        }
    }
    const ActiveArea mask(disc);
    // The mean is the disc's area, π r², up to the pixelation of its rim.
    EXPECT_NEAR(mask.mean_sensitivity(), std::numbers::pi * kRadius * kRadius, 0.003);
    constexpr int kSamples = 40000;
    for (const double edge : {-0.45, -0.3, -0.1, 0.0, 0.2, 0.35, 0.45}) {
        // Response to a bright half-plane u - ½ > edge: mean sensitivity × the share of the
        // samples beyond the edge; analytically the disc's area beyond it.
        int beyond = 0;
        for (int n = 0; n < kSamples; ++n) {
            RandomStream rng = stream(7, static_cast<std::uint64_t>(n));
            const double r1 = rng.uniform();
            if (mask.point(r1, rng.uniform())[0] - 0.5 > edge) ++beyond;
        }
        const double response = mask.mean_sensitivity() * beyond / kSamples;
        const double d = std::clamp(edge / kRadius, -1.0, 1.0);
        const double segment =
            kRadius * kRadius * (std::acos(d) - d * std::sqrt(1.0 - d * d));  // area beyond
        // 40 000 draws: the share's standard error is at most 0.0025 (×0.5 mean); the rim's
        // pixelation adds about 0.002.
        EXPECT_NEAR(response, segment, 0.006) << "edge " << edge;
    }
}

TEST(ActiveArea, RefusesBadMasks) {
    try {
        ActiveArea(GreyImage{2, 2, {0, 0, 0, 0}});
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "the image is all zero");
    }
    try {
        ActiveArea(GreyImage{2, 1, {0.5, 1.5}});
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "a value is above 1 (1.5)");
    }
    model::FileRef ref{"mask.png", "/nowhere/mask.png", ErrorContext{"cam.platform", 9, {}}};
    try {
        ActiveArea::from_model(ref, model::WeightImage{2, 1, {0.0, 0.0}});
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_NE(std::string(e.what()).find(
                      "cam.platform:9: <activearea><image> \"mask.png\": the image is all zero"),
                  std::string::npos)
            << e.what();
    }
    try {
        ActiveArea::from_model(ref, model::WeightImage{});
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::internal) << "the readers read every mask";
    }
    const ActiveArea half = ActiveArea::from_model(ref, model::WeightImage{2, 1, {1.0, 0.0}});
    EXPECT_DOUBLE_EQ(half.mean_sensitivity(), 0.5);
    EXPECT_EQ(half.description(), "mask.png 2 x 1, mean sensitivity 0.5");
}

}  // namespace active_area_test
}  // namespace glint::sensor
