// SPDX-License-Identifier: Apache-2.0
// Depth of field (<focusdistance> with <aperturediameter>): the sample rays of one pixel of a
// camera 1000 m above flat ground, its element shrunk to a point so that only the lens
// spreads them, land on the ground inside the circle of confusion — projected back into the
// image, a uniform disc of diameter D·f_L·|d − f|/(d·(f − f_L)) pixels (the thin-lens formula;
// glint's D·f_L·|d − f|/(d·f) is within 0.02 % of it here) — and on one point when the ground
// is at the focus distance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include "glint/core/rng.h"
#include "glint/motion/euler.h"
#include "glint/motion/rigid.h"
#include "glint/sensor/camera.h"
#include "glint/sensor/pixel_ray_source.h"
#include "glint/test/platforms.h"

namespace glint::sensor {
namespace thin_lens_test {

constexpr double kHeight_m = 1000.0;
constexpr double kFocal_m = 0.1;
constexpr double kPitch_m = 10e-6;
constexpr double kAperture_m = 0.2;

struct Spread {
    double max_radius_px = 0.0;
    double mean_square_radius_px2 = 0.0;
};

/// Where pixel (12, 7)'s sample rays meet the ground, projected back through the lens centre
/// into the image: their largest and mean-square distance from their centroid.
Spread ground_spread(double focus_m) {
    model::DetectorArray a;
    a.x_count = 24;
    a.y_count = 16;
    a.x_spacing_m = a.y_spacing_m = kPitch_m;
    a.x_size_m = a.y_size_m = 1e-12;  // a point element: only the lens spreads the rays
    model::InstrumentProperties p;
    p.focal_length_m = kFocal_m;
    p.aperture_diameter_m = kAperture_m;
    p.focus_distance_m = focus_m;
    const CameraModel camera(p, a, 24, 16);
    const motion::PoseService poses(test::one_mount_platform(),
                                    std::make_unique<test::HoverTrajectory>(kHeight_m), {}, {});
    const PixelRaySource source(camera, poses, 0, {0.0, 0.0, 0.0});
    const motion::Rigid pose = poses.instrument_to_scene(0, 0.0);
    const motion::Rigid to_instrument = motion::inverse(pose);
    constexpr int kSamples = 20000;
    std::vector<std::array<double, 2>> at;
    for (int n = 0; n < kSamples; ++n) {
        RandomStream rng(5, {0, 0, 0, 7 * 24 + 12, static_cast<std::uint64_t>(n)});
        const auto ray = source.generate(7 * 24 + 12, static_cast<std::uint64_t>(n), rng);
        const double s = -ray.origin_m.z / ray.direction.z;
        const Vec3 hit = ray.origin_m + ray.direction * s;
        at.push_back(camera.project(motion::apply_point(to_instrument, hit)).value());
    }
    double cx = 0, cy = 0;
    for (const auto& q : at) cx += q[0], cy += q[1];
    cx /= kSamples;
    cy /= kSamples;
    Spread spread;
    for (const auto& q : at) {
        const double r2 = (q[0] - cx) * (q[0] - cx) + (q[1] - cy) * (q[1] - cy);
        spread.max_radius_px = std::max(spread.max_radius_px, std::sqrt(r2));
        spread.mean_square_radius_px2 += r2 / kSamples;
    }
    EXPECT_NEAR(cx, 12.5, 0.02);  // px: the blur is centred on the pixel
    EXPECT_NEAR(cy, 7.5, 0.02);
    return spread;
}

TEST(ThinLens, GroundAtTheFocusDistanceIsSharp) {
    EXPECT_LT(ground_spread(kHeight_m).max_radius_px, 1e-6);  // px: round-off only
}

TEST(ThinLens, OutOfFocusGroundBlursToTheCircleOfConfusion) {
    for (const double focus_m : {250.0, 500.0, 2000.0, 8000.0}) {
        const double d = kHeight_m;
        const double coc_px =
            kAperture_m * kFocal_m * std::abs(d - focus_m) / (d * (focus_m - kFocal_m)) / kPitch_m;
        const Spread spread = ground_spread(focus_m);
        // A uniform disc: the largest radius is its radius (20 000 draws come within 0.1 %),
        // the mean square radius half its square. 5 %: the bound.
        EXPECT_NEAR(2 * spread.max_radius_px, coc_px, 0.05 * coc_px) << focus_m;
        EXPECT_NEAR(spread.mean_square_radius_px2, coc_px * coc_px / 8, 0.05 * coc_px * coc_px / 8)
            << focus_m;
    }
}

}  // namespace thin_lens_test
}  // namespace glint::sensor
