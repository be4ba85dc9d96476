// SPDX-License-Identifier: Apache-2.0
// Truth collection (docs/truth.md) against analytic answers: abundance is the covered area
// fraction and the material index its majority, a pixel that sees nothing has no first-hit
// truth, the geolocation is the camera model's projection of the pixel centre, the distance
// the geometric range, the shadow fraction the share of the pixel the sun does not light.
// The scenes and camera are truth_fixture.h's; sample counts, standard errors and determinism
// are in truth_convergence_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "truth_fixture.h"

namespace glint::render {
namespace truth_test {

using namespace test_truth;

// --- Abundance and material index ---------------------------------------------------------

TEST(Truth, AbundanceIsTheCoveredAreaFractionAndTheMaterialIndexItsMajority) {
    // Material a everywhere but on two 1 mm slabs of b: "east" (x ≥ 0, y ≤ 0.26 m) starts on
    // the boundary between columns 3 and 4 and ends 0.3 of the way up row 2; "west" (x ≤
    // −0.45 m) covers column 0 and 0.75 of column 1. The slab tops are 1 mm up: their edges
    // move by 1e-6 of their distance from nadir (< 1 µm), nothing against a 0.2 m pixel.
    test::TempDir dir;
    write_simulation(
        dir.path(), R"(materials:
  - {id: a, reflectance: {wavelengths: [0.3, 1.0], values: [0.2, 0.2]}}
  - {id: b, reflectance: {wavelengths: [0.3, 1.0], values: [0.6, 0.6]}}
objects:
  - {name: ground, primitive: ground_plane, material: a}
  - {name: east, primitive: box, material: b, lower: [0, -1000, 0], upper: [1000, 0.26, 0.001]}
  - {name: west, primitive: box, material: b, lower: [-1000, -1000, 0], upper: [-0.45, 1000, 0.001]}
)",
        truth_collection("T", "t", collector("Material") + collector("Abundance", "a,b")));
    constexpr std::uint64_t kSamples = 4096;
    const Rendered r = render_into(dir.path(), {kSamples, kSamples, 0.0});
    ASSERT_EQ(r.truth.header.bands, 3u);
    std::size_t partial = 0;
    for (std::size_t row = 0; row < kSide; ++row) {
        for (std::size_t column = 0; column < kSide; ++column) {
            const double f = covered(column, row, 0.0, 1000.0, -1000.0, 0.26) +
                             covered(column, row, -1000.0, -0.45, -1000.0, 1000.0);
            const double a = r.truth.at("Material Abundance 'a'", column, row);
            const double b = r.truth.at("Material Abundance 'b'", column, row);
            // Every sample hits a or b: the two fractions are k/N and (N − k)/N.
            EXPECT_NEAR(a + b, 1.0, 1e-12) << column << ", " << row;
            if (f == 0.0 || f == 1.0) {
                // Wholly on one side (the x = 0 edge is a pixel boundary): no sample strays.
                EXPECT_EQ(b, f) << column << ", " << row;
            } else {
                // Binomial: standard error √(f(1 − f)/N) (0.0072 for f = 0.3, 0.0068 for 0.75
                // at N = 4096); 4 standard errors fail with probability 6e-5 (fixed seed).
                ++partial;
                EXPECT_NEAR(b, f, 4.0 * std::sqrt(f * (1.0 - f) / kSamples))
                    << column << ", " << row << " covered " << f;
            }
            // The majority material (scene order: a = 0, b = 1); f is 0.3 or 0.75, at least
            // 28 standard errors from 0.5.
            EXPECT_EQ(r.truth.at("Material Index", column, row), f > 0.5 ? 1.0 : 0.0)
                << column << ", " << row;
        }
    }
    EXPECT_EQ(partial, 4u + 8u) << "row 2 of columns 4–7 and column 1";
    EXPECT_EQ(r.truth.header.find_extra("glint material ids"), "{a, b}");
}

TEST(Truth, APixelThatSeesNothingHasNoAbundanceAndNaNFirstHitQuantities) {
    // A 0.8 m ground square under the middle 4 × 4 pixels (its edges on pixel boundaries),
    // nothing elsewhere: the outer pixels' samples all leave the scene downwards (radiance 0).
    test::TempDir dir;
    write_simulation(dir.path(), R"(materials:
  - {id: a, reflectance: {wavelengths: [0.3, 1.0], values: [0.2, 0.2]}}
objects:
  - {name: ground, primitive: ground_plane, material: a, size: 0.8}
)",
                     truth_collection("T", "t",
                                      collector("Material") + collector("Abundance", "a") +
                                          collector("Intersection") + collector("Shadow") +
                                          collector("SampleCount") + collector("StandardError")));
    const Rendered r = render_into(dir.path(), {16, 16, 0.0});
    for (std::size_t row = 0; row < kSide; ++row) {
        for (std::size_t column = 0; column < kSide; ++column) {
            const bool inside = column >= 2 && column <= 5 && row >= 2 && row <= 5;
            EXPECT_EQ(r.truth.at("Material Abundance 'a'", column, row), inside ? 1.0 : 0.0);
            EXPECT_EQ(r.truth.at("Sample Count", column, row), 16.0);
            for (const char* band :
                 {"Material Index", "Scene X", "Normal Z", "Distance", "Shadow Fraction"}) {
                EXPECT_EQ(std::isnan(r.truth.at(band, column, row)), !inside)
                    << band << " at " << column << ", " << row;
            }
            if (!inside) {
                EXPECT_EQ(r.radiance(column, row), 0.0);
                EXPECT_EQ(r.truth.at("Standard Error 'Green'", column, row), 0.0);
            }
        }
    }
    EXPECT_EQ(r.truth.header.find_extra("data ignore value"), "NaN");
}

// --- Geolocation and distance --------------------------------------------------------------

constexpr double kPlate_m = 20.0;  // height of the plate that fills the view

/// Samples per pixel of the plate renders.
constexpr std::uint64_t kPlateSamples = 1024;

/// A plate render and where each pixel's centre lands on the plate (pixel after pixel).
struct PlateRender {
    Rendered rendered;
    std::vector<motion::Vec3> centres;
};

/// Renders a 100 m plate of material b, kPlate_m high, on a ground plane of a, collecting
/// `collectors` (kPlateSamples per pixel); the centres come from the camera model and the
/// pose that the render uses (plan_render()).
PlateRender render_plate(const fs::path& dir, const std::string& collectors) {
    write_simulation(dir,
                     R"(materials:
  - {id: a, reflectance: {wavelengths: [0.3, 1.0], values: [0.2, 0.2]}}
  - {id: b, reflectance: {wavelengths: [0.3, 1.0], values: [0.5, 0.5]}}
objects:
  - {name: ground, primitive: ground_plane, material: a}
  - {name: plate, primitive: box, material: b, lower: [-50, -50, 0], upper: [50, 50, )" +
                         format_shortest(kPlate_m) + "]}\n",
                     truth_collection("T", "t", collectors));
    PlateRender plate;
    const auto prepared =
        detail::plan_render(load(dir / "one.jsim"), options_into(dir / "prep"), Context{});
    const sensor::CameraModel& camera = prepared.plan->states.at(0).camera;
    const schedule::PluginSchedule& plugin = prepared.plan->inputs.schedule->plugins().at(0);
    const std::size_t instrument = prepared.plan->inputs.schedule->sources().at(0).instrument_index;
    const motion::Rigid pose = plugin.poses->instrument_to_scene(instrument, 0.0);
    const motion::Vec3 origin = motion::apply_point(pose, {});
    for (std::size_t row = 0; row < kSide; ++row) {
        for (std::size_t column = 0; column < kSide; ++column) {
            const motion::Vec3 d = motion::apply_direction(
                pose, camera.direction(camera.focal_plane_point(column, row, 0.5, 0.5)));
            const double t = (kPlate_m - origin.z) / d.z;
            plate.centres.push_back({origin.x + t * d.x, origin.y + t * d.y, origin.z + t * d.z});
        }
    }
    plate.rendered = render_into(dir, {kPlateSamples, kPlateSamples, 0.0});
    return plate;
}

TEST(Truth, GeoLocationIsTheCameraModelsProjectionOfThePixelCentre) {
    // On a plane parallel to the focal plane a nadir pinhole maps the element linearly, so
    // the mean of uniformly drawn element points is the projection of the element centre.
    test::TempDir dir;
    const PlateRender plate = render_plate(dir.path(), collector("GeoLocation"));
    const Rendered& r = plate.rendered;
    ASSERT_EQ(r.truth.header.bands, 6u);

    // WGS84, for the independent conversion below.
    constexpr double kA = 6378137.0;
    constexpr double kF = 1.0 / 298.257223563;
    constexpr double kE2 = kF * (2.0 - kF);
    constexpr double kDeg = 3.14159265358979323846 / 180.0;
    const double lat0 = 43.0 * kDeg;
    const double w = std::sqrt(1.0 - kE2 * std::sin(lat0) * std::sin(lat0));
    const double meridian = kA * (1.0 - kE2) / (w * w * w);  // M
    const double normal = kA / w;                            // N
    constexpr double kH0 = 150.0;

    // The footprint of a pixel on the plate is 0.2 × 0.98 = 0.196 m square: one sample's
    // point spreads 0.196/√12 = 57 mm per axis about the centre, the mean of 1024 by 1.8 mm;
    // 1 cm is 5.6 of those (probability 3e-8 per value, 128 values, fixed seed).
    constexpr double kPosition_m = 0.01;
    for (std::size_t row = 0; row < kSide; ++row) {
        for (std::size_t column = 0; column < kSide; ++column) {
            const motion::Vec3& c = plate.centres[row * kSide + column];
            // The camera model is the closed form of camera.h for this camera.
            const double scale = (kCamera_m - kPlate_m) / kCamera_m * kPixel_m;
            ASSERT_NEAR(c.x, (static_cast<double>(column) - 3.5) * scale, 1e-9);
            ASSERT_NEAR(c.y, (3.5 - static_cast<double>(row)) * scale, 1e-9);
            const double x = r.truth.at("Scene X", column, row);
            const double y = r.truth.at("Scene Y", column, row);
            const double z = r.truth.at("Scene Z", column, row);
            EXPECT_NEAR(x, c.x, kPosition_m) << column << ", " << row;
            EXPECT_NEAR(y, c.y, kPosition_m) << column << ", " << row;
            // Every hit is on the plate's top: z is exact but for Embree's float32 hit
            // distance (ulp(980 m) = 61 µm).
            EXPECT_NEAR(z, kPlate_m, 1e-3) << column << ", " << row;

            // Latitude, longitude and altitude of the truth's own scene point, from the ENU
            // frame's definition (up = the ellipsoid normal at the origin): to first order
            // a step north y turns the normal by y / (M + h), a step east x by x / ((N + h)
            // cos φ0), and the tangent plane rises above the ellipsoid by x²/2N + y²/2M. The
            // second-order terms neglected are ~(1 m / 6.4e6 m)² rad; the tolerances (1e-8°
            // ≈ 1 mm, 1 mm) are the frame conversions' accuracy (1 mm round trip, 1 µm
            // against GeographicLib's LocalCartesian: docs/validation.md, "Geometry").
            const double h = kH0 + z;
            EXPECT_NEAR(r.truth.at("Latitude", column, row), 43.0 + y / (meridian + h) / kDeg,
                        1e-8);
            EXPECT_NEAR(r.truth.at("Longitude", column, row),
                        -77.6 + x / ((normal + h) * std::cos(lat0)) / kDeg, 1e-8);
            EXPECT_NEAR(r.truth.at("Altitude", column, row),
                        h + 0.5 * (x * x / normal + y * y / meridian), 1e-3);
        }
    }
}

TEST(Truth, DistanceIsTheGeometricRangeToTheMeanHitPoint) {
    test::TempDir dir;
    const PlateRender plate = render_plate(dir.path(), collector("Intersection"));
    const Rendered& r = plate.rendered;
    ASSERT_EQ(r.truth.header.bands, 7u);
    constexpr double kDepth_m = kCamera_m - kPlate_m;
    constexpr double kSide_m = kPixel_m * kDepth_m / kCamera_m;  // the footprint on the plate
    for (std::size_t row = 0; row < kSide; ++row) {
        for (std::size_t column = 0; column < kSide; ++column) {
            const double x = r.truth.at("Scene X", column, row);
            const double y = r.truth.at("Scene Y", column, row);
            const double z = r.truth.at("Scene Z", column, row);
            const double distance = r.truth.at("Distance", column, row);
            // (a) The range of the mean hit point from the camera (0, 0, 1000). The mean of
            // the ranges exceeds it by Var(point)/2R = 2 × (0.057 m)²/(2 × 980 m) = 3e-6 m
            // (3e-9 relative, Jensen); Embree's float32 hit distance is good to ~1e-7
            // relative: 1e-6 relative bounds both with margin.
            const double range = std::sqrt(x * x + y * y + (kCamera_m - z) * (kCamera_m - z));
            EXPECT_NEAR(distance / range, 1.0, 1e-6) << column << ", " << row;
            // (b) The analytic mean of the range over the element's footprint (the mean of
            // √(D² + x² + y²) over the 0.196 m square about the projected centre; midpoint
            // rule, 64 × 64). The range varies across a pixel by at most (1.1 m / 980 m) ×
            // 0.196 m = 0.2 mm, so the Monte-Carlo mean of 1024 samples is within ~2e-6 m
            // (2e-9 relative) of it; 1e-6 relative again leaves room for float32.
            const motion::Vec3& c = plate.centres[row * kSide + column];
            double sum = 0.0;
            constexpr int kSteps = 64;
            for (int a = 0; a < kSteps; ++a) {
                for (int b = 0; b < kSteps; ++b) {
                    const double px = c.x + ((a + 0.5) / kSteps - 0.5) * kSide_m;
                    const double py = c.y + ((b + 0.5) / kSteps - 0.5) * kSide_m;
                    sum += std::sqrt(kDepth_m * kDepth_m + px * px + py * py);
                }
            }
            const double mean = sum / (kSteps * kSteps);
            EXPECT_NEAR(distance / mean, 1.0, 1e-6) << column << ", " << row;
            // A flat plate facing the camera: the normal is +Z.
            EXPECT_NEAR(r.truth.at("Normal X", column, row), 0.0, 1e-12);
            EXPECT_NEAR(r.truth.at("Normal Y", column, row), 0.0, 1e-12);
            EXPECT_NEAR(r.truth.at("Normal Z", column, row), 1.0, 1e-12);
        }
    }
}

// --- Shadow ----------------------------------------------------------------------------------

TEST(Truth, ShadowFractionIsTheShareOfThePixelTheSunDoesNotLight) {
    // A wall along x (y ∈ [−1.1, −1.0] m, south of the view) of the height that puts the
    // edge of its shadow on the ground at y = 0.1 m, the centre line of row 3: rows 4–7 lie
    // in its shadow, rows 0–2 in the sun, row 3 half and half. The ground is black for x < 0
    // (the first hit's shadow ray is traced for truth alone) and grey for x ≥ 0 (the
    // radiance's own shadow ray), two boxes whose tops are at z = 0.
    const motion::SunPosition sun = motion::sun_position(
        parse_iso8601("2020-06-21T12:00:00.0000-04:00"), motion::SceneFrame(43.0, -77.6, 150.0));
    const motion::Vec3 s = sun.direction_enu;
    ASSERT_LT(s.y, -0.1) << "the sun must be to the south";
    ASSERT_GT(s.z, 0.1);
    // A ground point at y sees the wall's north face (y = −1) at height (y + 1) s_z / −s_y.
    constexpr double kEdge_m = 0.1;
    const double wall_m = (kEdge_m + 1.0) * s.z / -s.y;
    test::TempDir dir;
    write_simulation(dir.path(),
                     R"(materials:
  - {id: black, reflectance: {wavelengths: [0.3, 1.0], values: [0, 0]}}
  - {id: grey, reflectance: {wavelengths: [0.3, 1.0], values: [0.3, 0.3]}}
objects:
  - {name: west, primitive: box, material: black, lower: [-1000, -1000, -1], upper: [0, 1000, 0]}
  - {name: east, primitive: box, material: grey, lower: [0, -1000, -1], upper: [1000, 1000, 0]}
  - {name: wall, primitive: box, material: grey, lower: [-1000, -1.1, 0], upper: [1000, -1.0, )" +
                         format_shortest(wall_m) + "]}\n",
                     truth_collection("T", "t", collector("Shadow")));
    // Row 3's shadow fraction is binomial with p = 0.5: standard error 0.5/√N = 0.005 for
    // N = 10000, so 0.02 is 4 standard errors. The sun's disc (0.27° radius) blurs the edge
    // symmetrically about it (the share of the disc behind the wall's top edge), over
    // ±(h / sin²α) × 0.0049 rad ≈ ±18 mm for the sun's elevation seen along x, α ≈ 72°, and a
    // wall h ≈ 3.3 m high: no bias at row 3, and rows 2 and 4 (whose nearest points are
    // 0.1 m from the edge) are wholly lit or shadowed.
    constexpr std::uint64_t kSamples = 10000;
    const Rendered r = render_into(dir.path(), {kSamples, kSamples, 0.0});
    double row_sum = 0.0;
    for (std::size_t row = 0; row < kSide; ++row) {
        for (std::size_t column = 0; column < kSide; ++column) {
            const double shadow = r.truth.at("Shadow Fraction", column, row);
            if (row < 3) {
                EXPECT_EQ(shadow, 0.0) << column << ", " << row;
            } else if (row > 3) {
                EXPECT_EQ(shadow, 1.0) << column << ", " << row;
            } else {
                EXPECT_NEAR(shadow, 0.5, 0.02) << column << ", " << row;
                row_sum += shadow;
            }
        }
    }
    // The mean of row 3's 8 pixels has a standard error of 0.5/√80000 = 0.0018: a bias of
    // the edge (a shifted or lopsided penumbra) larger than 4 of those would show here.
    EXPECT_NEAR(row_sum / kSide, 0.5, 4.0 * 0.5 / std::sqrt(kSide * kSamples));
}
}  // namespace truth_test
}  // namespace glint::render
