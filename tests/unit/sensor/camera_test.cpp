// SPDX-License-Identifier: Apache-2.0
// Tests of CameraModel: the focal-plane layout (centres, element area, offsets, flips,
// scale_resolution) against the formulas of glint/sensor/camera.h, the pinhole angles against
// atan(half-width / f), the Brown distortion round trip (project ∘ direction) and against an
// independent evaluation of the forward model, and the input errors.
#include "glint/sensor/camera.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/error.h"

namespace glint::sensor {
namespace camera_test {

/// An instrument with focal length `f_m` and optional distortion, located in a fake file.
model::InstrumentProperties properties(double f_m,
                                       std::optional<model::Distortion> distortion = {}) {
    model::InstrumentProperties p;
    p.focal_length_m = f_m;
    p.distortion = distortion;
    p.where = {"cam.platform", 12, "platform/attachment/instrument[Cam]/properties"};
    return p;
}

/// A detector array of `columns` × `rows` elements, square pitch and element sizes in µm.
model::DetectorArray array(std::size_t columns, std::size_t rows, double pitch_um, double size_um) {
    model::DetectorArray a;
    a.x_count = columns;
    a.y_count = rows;
    a.x_spacing_m = a.y_spacing_m = pitch_um * 1e-6;
    a.x_size_m = a.y_size_m = size_um * 1e-6;
    a.where = {"cam.platform", 40, "platform/attachment/instrument[Cam]/focalplane/detectorarray"};
    return a;
}

CameraModel camera(const model::InstrumentProperties& p, const model::DetectorArray& a) {
    return CameraModel(p, a, a.x_count, a.y_count);
}

/// Angles of a direction from the boresight, seen in the XZ and YZ planes (rad).
double angle_x(const Vec3& d) { return std::atan2(d.x, -d.z); }
double angle_y(const Vec3& d) { return std::atan2(d.y, -d.z); }

/// The Brown forward model written out again, independently of camera.cpp.
std::array<double, 2> brown(const model::Distortion& k, double x, double y) {
    const double r2 = x * x + y * y;
    const double r4 = r2 * r2;
    const double r6 = r4 * r2;
    const double radial = 1 + k.k1 * r2 + k.k2 * r4 + k.k3 * r6;
    return {x * radial + 2 * k.p1 * x * y + k.p2 * (r2 + 2 * x * x),
            y * radial + k.p1 * (r2 + 2 * y * y) + 2 * k.p2 * x * y};
}

template <typename F>
Error error_of(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e;
    }
    ADD_FAILURE() << "no glint::Error thrown";
    return internal_error("none");
}

// Pixel centres are placed symmetrically about the array centre, for even and odd counts:
// (i + ½ − N/2) and (N − 1 − i + ½ − N/2) are exact negatives in binary floating point.
TEST(CameraModel, PixelCentresAreSymmetricAboutTheAxis) {
    for (const std::size_t n : {4u, 5u, 1u, 640u, 641u}) {
        const CameraModel cam = camera(properties(0.05), array(n, n + 1, 10, 10));
        for (std::size_t i = 0; i < cam.columns(); ++i) {
            for (std::size_t j = 0; j < cam.rows(); ++j) {
                const auto a = cam.focal_plane_point(i, j, 0.5, 0.5);
                const auto b = cam.focal_plane_point(n - 1 - i, n - j, 0.5, 0.5);
                ASSERT_EQ(a[0], -b[0]) << n << " " << i << " " << j;
                ASSERT_EQ(a[1], -b[1]) << n << " " << i << " " << j;
            }
        }
    }
    // Centres one pitch apart; columns towards +X, rows towards −Y (top line forward).
    const CameraModel cam = camera(properties(0.05), array(4, 3, 10, 10));
    EXPECT_NEAR(cam.focal_plane_point(0, 0, 0.5, 0.5)[0], -15e-6, 1e-18);  // m, round-off
    EXPECT_NEAR(cam.focal_plane_point(3, 0, 0.5, 0.5)[0], 15e-6, 1e-18);
    EXPECT_NEAR(cam.focal_plane_point(0, 0, 0.5, 0.5)[1], 10e-6, 1e-18);
    EXPECT_NEAR(cam.focal_plane_point(0, 2, 0.5, 0.5)[1], -10e-6, 1e-18);
}

// The centre pixel of an odd array sits exactly on the optical axis: x = y = 0 exactly, so
// the direction is exactly −Z, with or without distortion (distort(0) = 0).
TEST(CameraModel, CentrePixelOfAnOddArrayLooksExactlyAlongMinusZ) {
    const model::Distortion k{0.3, -0.1, 0.02, 0.01, -0.02};
    for (const auto& p : {properties(0.035), properties(0.035, k)}) {
        const CameraModel cam = camera(p, array(5, 7, 12, 8));
        const auto fp = cam.focal_plane_point(2, 3, 0.5, 0.5);
        EXPECT_EQ(fp[0], 0.0);
        EXPECT_EQ(fp[1], 0.0);
        EXPECT_EQ(cam.direction(fp), (Vec3{0, 0, -1}));
    }
}

// Without distortion the pinhole angles are atan(focal-plane coordinate / f): the array's
// corner at atan(half-width / f), the corner pixel's centre at atan((half-width − ½ pitch)/f).
TEST(CameraModel, CornerDirectionsAreAtanOfHalfWidthOverFocalLength) {
    const double f = 0.1;
    const CameraModel cam = camera(properties(f), array(640, 480, 15, 15));
    const double half_w = 320 * 15e-6;
    const double half_h = 240 * 15e-6;
    const Vec3 corner = cam.direction(cam.focal_plane_point(0, 0, 0.0, 0.0));
    EXPECT_NEAR(angle_x(corner), -std::atan(half_w / f), 1e-15);  // rad, round-off
    EXPECT_NEAR(angle_y(corner), std::atan(half_h / f), 1e-15);
    const Vec3 far_corner = cam.direction(cam.focal_plane_point(639, 479, 1.0, 1.0));
    EXPECT_NEAR(angle_x(far_corner), std::atan(half_w / f), 1e-15);
    EXPECT_NEAR(angle_y(far_corner), -std::atan(half_h / f), 1e-15);
    const Vec3 centre = cam.direction(cam.focal_plane_point(639, 0, 0.5, 0.5));
    EXPECT_NEAR(angle_x(centre), std::atan((half_w - 7.5e-6) / f), 1e-15);
    EXPECT_NEAR(angle_y(centre), std::atan((half_h - 7.5e-6) / f), 1e-15);
    EXPECT_NEAR(norm(centre), 1.0, 1e-15);
}

// An element smaller than its pitch: samples stay within the active area (s/2 about the
// centre), not the pitch cell, and the extremes reach its edges.
TEST(CameraModel, SamplesStayWithinTheActiveArea) {
    const CameraModel cam = camera(properties(0.05), array(6, 4, 10, 6));
    EXPECT_DOUBLE_EQ(cam.pitch_m()[0], 10e-6);
    EXPECT_DOUBLE_EQ(cam.element_size_m()[1], 6e-6);
    const double tol = 1e-18;  // m, round-off on 1e-5 m coordinates
    for (std::size_t i = 0; i < 6; ++i) {
        for (std::size_t j = 0; j < 4; ++j) {
            const auto c = cam.focal_plane_point(i, j, 0.5, 0.5);
            for (const double u : {0.0, 0.1, 0.5, 0.9, 0.9999999}) {
                for (const double v : {0.0, 0.3, 0.9999999}) {
                    const auto p = cam.focal_plane_point(i, j, u, v);
                    EXPECT_LE(std::abs(p[0] - c[0]), 3e-6 + tol);
                    EXPECT_LE(std::abs(p[1] - c[1]), 3e-6 + tol);
                }
            }
            EXPECT_NEAR(cam.focal_plane_point(i, j, 0.0, 0.0)[0], c[0] - 3e-6, tol);
            EXPECT_NEAR(cam.focal_plane_point(i, j, 0.0, 0.0)[1], c[1] + 3e-6, tol);
        }
    }
}

// The array offset moves every focal-plane point by the offset, so an odd array's centre pixel
// looks atan(offset / f) off the boresight.
TEST(CameraModel, OffsetsShiftTheField) {
    model::DetectorArray plain = array(5, 3, 10, 8);
    model::DetectorArray shifted = plain;
    shifted.x_offset_m = 1e-3;
    shifted.y_offset_m = -2e-3;
    const CameraModel a = camera(properties(0.05), plain);
    const CameraModel b = camera(properties(0.05), shifted);
    for (std::size_t i = 0; i < 5; ++i) {
        for (std::size_t j = 0; j < 3; ++j) {
            const auto pa = a.focal_plane_point(i, j, 0.2, 0.7);
            const auto pb = b.focal_plane_point(i, j, 0.2, 0.7);
            EXPECT_NEAR(pb[0] - pa[0], 1e-3, 1e-18);  // m, round-off
            EXPECT_NEAR(pb[1] - pa[1], -2e-3, 1e-18);
        }
    }
    const Vec3 d = b.direction(b.focal_plane_point(2, 1, 0.5, 0.5));
    EXPECT_NEAR(angle_x(d), std::atan(1e-3 / 0.05), 1e-15);  // rad, round-off
    EXPECT_NEAR(angle_y(d), std::atan(-2e-3 / 0.05), 1e-15);
}

// xflip mirrors the focal plane about x = x_offset (column i's centre goes to column
// N − 1 − i's, u mirrored inside the element); yflip does the same for the rows.
TEST(CameraModel, FlipsMirrorTheArrayAboutItsCentre) {
    model::DetectorArray plain = array(6, 5, 10, 7);
    plain.x_offset_m = 3e-4;
    plain.y_offset_m = -1e-4;
    model::DetectorArray x_flipped = plain;
    x_flipped.x_flip = true;
    model::DetectorArray y_flipped = plain;
    y_flipped.y_flip = true;
    const CameraModel a = camera(properties(0.05), plain);
    const CameraModel bx = camera(properties(0.05), x_flipped);
    const CameraModel by = camera(properties(0.05), y_flipped);
    const double tol = 1e-18;  // m, round-off
    for (std::size_t i = 0; i < 6; ++i) {
        for (std::size_t j = 0; j < 5; ++j) {
            const auto p = a.focal_plane_point(i, j, 0.25, 0.8);
            const auto px = bx.focal_plane_point(i, j, 0.25, 0.8);
            const auto py = by.focal_plane_point(i, j, 0.25, 0.8);
            EXPECT_NEAR(px[0] - 3e-4, -(p[0] - 3e-4), tol);
            EXPECT_NEAR(px[1], p[1], tol);
            EXPECT_NEAR(py[0], p[0], tol);
            EXPECT_NEAR(py[1] + 1e-4, -(p[1] + 1e-4), tol);
            // Centres: i → N − 1 − i, j → M − 1 − j.
            const auto cx = bx.focal_plane_point(i, j, 0.5, 0.5);
            const auto cy = by.focal_plane_point(i, j, 0.5, 0.5);
            EXPECT_NEAR(cx[0], a.focal_plane_point(5 - i, j, 0.5, 0.5)[0], tol);
            EXPECT_NEAR(cy[1], a.focal_plane_point(i, 4 - j, 0.5, 0.5)[1], tol);
        }
    }
}

// project() inverts direction() ∘ focal_plane_point for every distortion kind, with flips and
// offsets: the fractional pixel position comes back as i + ½ + (u − ½) s/p to 1e-9 px.
TEST(CameraModel, ProjectInvertsDirection) {
    struct Case {
        const char* name;
        std::optional<model::Distortion> k;
    };
    const std::vector<Case> cases = {
        {"none", std::nullopt},
        {"barrel", model::Distortion{-0.25, 0.05, 0, 0, 0}},
        {"pincushion", model::Distortion{0.3, 0.1, -0.05, 0, 0}},
        {"tangential", model::Distortion{0, 0, 0, 0.02, -0.015}},
        {"all", model::Distortion{-0.15, 0.04, 0.01, -0.01, 0.02}},
        // The LensDistortion example of the DIRSIG5 BasicPlatform manual (f = 35 mm), over a
        // ±0.1 field.
        {"manual", model::Distortion{5, 2.5, -100, 0.1, 0.05}},
    };
    double worst_px = 0;
    double worst_brown = 0;
    for (const Case& c : cases) {
        for (const int flips : {0, 1, 2, 3}) {
            model::DetectorArray a = array(700, 500, 10, 8);
            a.x_offset_m = 2e-4;
            a.y_offset_m = -3e-4;
            a.x_flip = (flips & 1) != 0;
            a.y_flip = (flips & 2) != 0;
            const double f = 0.035;
            const CameraModel cam = camera(properties(f, c.k), a);
            for (std::size_t i = 0; i < 700; i += 37) {
                for (std::size_t j = 0; j < 500; j += 29) {
                    for (const auto& [u, v] :
                         {std::array<double, 2>{0.5, 0.5}, {0.0, 0.9}, {0.97, 0.13}}) {
                        const auto fp = cam.focal_plane_point(i, j, u, v);
                        const Vec3 d = cam.direction(fp);
                        ASSERT_NEAR(norm(d), 1.0, 1e-15);
                        const auto px = cam.project(d);
                        ASSERT_TRUE(px.has_value());
                        const double ec = (*px)[0] - (i + 0.5 + (u - 0.5) * 0.8);
                        const double er = (*px)[1] - (j + 0.5 + (v - 0.5) * 0.8);
                        worst_px = std::max({worst_px, std::abs(ec), std::abs(er)});
                        ASSERT_LE(std::abs(ec), 1e-9) << c.name << " flips " << flips;
                        ASSERT_LE(std::abs(er), 1e-9) << c.name << " flips " << flips;
                        // Independent check: the forward Brown model of the direction's
                        // normalised coordinates gives back the focal-plane point / f.
                        if (c.k) {
                            const auto b = brown(*c.k, d.x / -d.z, d.y / -d.z);
                            worst_brown = std::max({worst_brown, std::abs(b[0] - fp[0] / f),
                                                    std::abs(b[1] - fp[1] / f)});
                            ASSERT_LE(std::abs(b[0] - fp[0] / f), 1e-12) << c.name;
                            ASSERT_LE(std::abs(b[1] - fp[1] / f), 1e-12) << c.name;
                        }
                    }
                }
            }
        }
    }
    std::printf("[ measured ] worst round trip %.3g px, worst Brown residual %.3g\n", worst_px,
                worst_brown);
    // Nothing projects from the hemisphere behind the camera.
    const CameraModel cam = camera(properties(0.035), array(10, 10, 10, 10));
    EXPECT_FALSE(cam.project({0, 0, 0}).has_value());
    EXPECT_FALSE(cam.project({0.3, 0.1, 0}).has_value());
    EXPECT_FALSE(cam.project({0, 0, 1}).has_value());
    EXPECT_FALSE(cam.project({0, 0, std::nan("")}).has_value());
    // Length does not matter.
    const auto a = cam.project({1e-4, 0, -1});
    const auto b = cam.project({3e-4, 0, -3});
    ASSERT_TRUE(a && b);
    EXPECT_NEAR((*a)[0], (*b)[0], 1e-12);
}

// Barrel distortion (k1 < 0) pushes the scene direction of an edge pixel outwards (a wider
// field), pincushion (k1 > 0) pulls it inwards: r_u = r_d / (1 + k1 r_u²) to first order.
TEST(CameraModel, BarrelWidensAndPincushionNarrowsTheField) {
    const double f = 0.02;
    const model::DetectorArray a = array(1001, 1, 10, 10);  // half-width 5.005 mm, r_d ≈ 0.25
    const double r_d = 500.5 * 10e-6 / f;
    const auto edge_angle = [&](std::optional<model::Distortion> k) {
        const CameraModel cam = camera(properties(f, k), a);
        return angle_x(cam.direction(cam.focal_plane_point(1000, 0, 1.0, 0.5)));
    };
    const double ideal = std::atan(r_d);
    const double barrel = edge_angle(model::Distortion{-0.2, 0, 0, 0, 0});
    const double pincushion = edge_angle(model::Distortion{0.2, 0, 0, 0, 0});
    // k1 r³ ≈ 0.003 rad of shift at r ≈ 0.25.
    EXPECT_GT(barrel, ideal + 0.002);
    EXPECT_LT(pincushion, ideal - 0.002);
    // Radial only on the x axis: r_u solves r_u (1 + k1 r_u²) = r_d exactly (cubic, by
    // bisection here).
    for (const double k1 : {-0.2, 0.2}) {
        double lo = 0, hi = 1;
        for (int n = 0; n < 200; ++n) {
            const double mid = 0.5 * (lo + hi);
            (mid * (1 + k1 * mid * mid) < r_d ? lo : hi) = mid;
        }
        EXPECT_NEAR(std::tan(edge_angle(model::Distortion{k1, 0, 0, 0, 0})), lo, 1e-13);
    }
}

// Where the fixed-point iteration is too slow (strong barrel near the fold of the radial map,
// contraction ≈ 0.9) or diverges (strong pincushion far off axis, contraction ≈ −1.2), the
// Newton steps still find the undistorted point: checked with the independent forward model.
TEST(CameraModel, UndistortionConvergesWhereTheFixedPointDoesNot) {
    const double f = 0.01;
    struct Case {
        model::Distortion k;
        double x_u;  // undistorted normalised coordinate on the x axis
    };
    for (const Case& c : {Case{{-0.4, 0, 0, 0, 0}, 0.88}, Case{{1.0, 0, 0, 0, 0}, 1.2},
                          Case{{1.0, 0, 0, 0.05, -0.03}, 1.1}}) {
        const auto xd = brown(c.k, c.x_u, 0.1);
        model::DetectorArray a = array(1, 1, 10, 10);
        a.x_offset_m = xd[0] * f;  // the single pixel's centre sits on the distorted point
        a.y_offset_m = xd[1] * f;
        const CameraModel cam = camera(properties(f, c.k), a);
        const Vec3 d = cam.direction(cam.focal_plane_point(0, 0, 0.5, 0.5));
        EXPECT_NEAR(d.x / -d.z, c.x_u, 1e-12);  // normalised, convergence tolerance
        EXPECT_NEAR(d.y / -d.z, 0.1, 1e-12);
        const auto back = brown(c.k, d.x / -d.z, d.y / -d.z);
        EXPECT_NEAR(back[0], xd[0], 1e-14);  // normalised, round-off
        EXPECT_NEAR(back[1], xd[1], 1e-14);
    }
}

// scale_resolution: twice the columns and half the rows cover the same field; the pitch and
// element size scale by N/N'.
TEST(CameraModel, ScaleResolutionKeepsTheFieldOfView) {
    model::DetectorArray a = array(100, 80, 10, 8);
    a.x_offset_m = 1e-4;
    const CameraModel base(properties(0.05), a, 100, 80);
    const CameraModel scaled(properties(0.05), a, 200, 40);
    EXPECT_EQ(scaled.columns(), 200u);
    EXPECT_EQ(scaled.rows(), 40u);
    EXPECT_DOUBLE_EQ(scaled.pitch_m()[0], 5e-6);
    EXPECT_DOUBLE_EQ(scaled.pitch_m()[1], 20e-6);
    EXPECT_DOUBLE_EQ(scaled.element_size_m()[0], 4e-6);
    EXPECT_DOUBLE_EQ(scaled.element_size_m()[1], 16e-6);
    // Edges of the field: the outer edges of the first and last pitch cells.
    const auto edge = [](const CameraModel& cam, std::size_t i, std::size_t j, double u, double v) {
        // u, v of the pitch cell (not the element): shift by the element/pitch ratio.
        const double su = 0.5 + (u - 0.5) * cam.pitch_m()[0] / cam.element_size_m()[0];
        const double sv = 0.5 + (v - 0.5) * cam.pitch_m()[1] / cam.element_size_m()[1];
        return cam.direction(cam.focal_plane_point(i, j, su, sv));
    };
    const double tol = 1e-15;  // rad, round-off
    const Vec3 b0 = edge(base, 0, 0, 0, 0), s0 = edge(scaled, 0, 0, 0, 0);
    const Vec3 b1 = edge(base, 99, 79, 1, 1), s1 = edge(scaled, 199, 39, 1, 1);
    EXPECT_NEAR(angle_x(b0), angle_x(s0), tol);
    EXPECT_NEAR(angle_y(b0), angle_y(s0), tol);
    EXPECT_NEAR(angle_x(b1), angle_x(s1), tol);
    EXPECT_NEAR(angle_y(b1), angle_y(s1), tol);
    EXPECT_NEAR(angle_x(b0), std::atan((1e-4 - 500e-6) / 0.05), tol);
    // Centre of the scaled array: between columns 99 and 100, on the offset.
    const auto mid = scaled.project(base.direction(base.focal_plane_point(49, 39, 1.0, 1.0)));
    ASSERT_TRUE(mid);
    // x = (49 + ½ − 50) · 10 µm + ½ · 8 µm = −1 µm from the array centre: 100 − 1/5 px.
    EXPECT_NEAR((*mid)[0], 99.8, 1e-9);  // px, round-off
}

TEST(CameraModel, InputErrorsNameTheElement) {
    const model::DetectorArray good = array(10, 10, 10, 10);
    // No focal length: at <properties>.
    {
        model::InstrumentProperties p = properties(0.05);
        p.focal_length_m.reset();
        const Error e = error_of([&] { camera(p, good); });
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_EQ(e.context().line, 12);
        EXPECT_EQ(e.context().element, "platform/attachment/instrument[Cam]/properties");
        EXPECT_NE(e.message().find("no focal length"), std::string::npos) << e.what();
    }
    {
        const Error e = error_of([&] { camera(properties(0.0), good); });
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_NE(e.message().find("focal length 0 m is not positive"), std::string::npos)
            << e.what();
    }
    {
        const Error e = error_of([&] {
            camera(properties(0.05, model::Distortion{std::nan(""), 0, 0, 0, 0}), good);
        });
        EXPECT_EQ(e.context().line, 12);
    }
    // Array errors: at <detectorarray>.
    const auto expect_array_error = [](const Error& e, const std::string& text) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_EQ(e.context().file, "cam.platform");
        EXPECT_EQ(e.context().line, 40);
        EXPECT_NE(e.message().find(text), std::string::npos) << e.what();
        EXPECT_EQ(e.message().back() == '.', false);
    };
    {
        model::DetectorArray a = good;
        a.x_count = 0;
        expect_array_error(error_of([&] { CameraModel(properties(0.05), a, 10, 10); }),
                           "xelementcount is 0");
    }
    expect_array_error(error_of([&] { CameraModel(properties(0.05), good, 10, 0); }),
                       "scaled y pixel count is 0");
    {
        model::DetectorArray a = good;
        a.y_size_m = 12e-6;
        expect_array_error(error_of([&] { camera(properties(0.05), a); }),
                           "yelementsize 12 um is larger than yelementspacing 10 um");
    }
    {
        model::DetectorArray a = good;
        a.x_spacing_m = 0;
        expect_array_error(error_of([&] { camera(properties(0.05), a); }),
                           "xelementspacing 0 um is not positive");
        a.x_spacing_m = -1e-5;
        expect_array_error(error_of([&] { camera(properties(0.05), a); }),
                           "xelementspacing -10 um is not positive");
    }
    {
        model::DetectorArray a = good;
        a.x_size_m = 0;
        expect_array_error(error_of([&] { camera(properties(0.05), a); }),
                           "xelementsize 0 um is not positive");
    }
    {
        model::DetectorArray a = good;
        a.y_offset_m = std::numeric_limits<double>::infinity();
        expect_array_error(error_of([&] { camera(properties(0.05), a); }),
                           "yarrayoffset is not a finite number");
    }
    // The full text names the file, line and element.
    model::DetectorArray a = good;
    a.x_size_m = 2e-5;
    EXPECT_EQ(std::string(error_of([&] { camera(properties(0.05), a); }).what()),
              "cam.platform:40: platform/attachment/instrument[Cam]/focalplane/detectorarray: "
              "xelementsize 20 um is larger than xelementspacing 10 um, expected an element "
              "no larger than its pitch");
}

}  // namespace camera_test
}  // namespace glint::sensor
