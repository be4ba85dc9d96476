// SPDX-License-Identifier: Apache-2.0
// OpenCV as an oracle for the camera's lens distortion (docs/validation.md): the
// five-parameter model of the DIRSIG5 BasicPlatform manual (docs/references.md) is OpenCV's
// (distCoeffs = k1, k2, p1, p2, k3 on coordinates normalised by the focal length). For a
// grid of pixel positions across arrays with barrel, pincushion and tangential distortion
// (and an array offset), glint's direction() (the iterative inverse) must give the
// normalised undistorted point cv2.undistortPointsIter finds (iterated to 1e-15), and
// project() (the forward model) must give the distorted point cv2.projectPoints computes
// from that direction. Both within 1e-12 in normalised units (1e-13 m on the focal plane
// for f = 0.1 m): both sides iterate to about 1e-15, so what is left is double round-off
// (about 1e-15 measured), while the distortion moves the points by 4e-5 to 1.5e-4.
// Skips when cv2 cannot be imported.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "glint/sensor/camera.h"
#include "glint/test/oracle.h"
#include "glint/test/temp_dir.h"

namespace glint::sensor::oracle {
namespace opencv_distortion_test {

using glint::test::CommandResult;
using glint::test::python_command;
using glint::test::python_has;
using glint::test::run_command;
using glint::test::TempDir;

constexpr double kFocal_m = 0.1;
constexpr double kPitch_m = 10e-6;
constexpr std::size_t kColumns = 640;
constexpr std::size_t kRows = 480;

/// argv: k1 k2 k3 p1 p2 input output. Input lines "x_d y_d X Y" (distorted normalised
/// coordinates, and an undistorted direction's X/Z, Y/Z); output lines "x_u y_u x_p y_p":
/// undistortPointsIter of (x_d, y_d) and projectPoints of (X, Y, 1), identity camera matrix.
constexpr const char* kOpenCv = R"(
import sys
import numpy as np
import cv2
k1, k2, k3, p1, p2 = (float(v) for v in sys.argv[1:6])
rows = np.loadtxt(sys.argv[6], ndmin=2)
dist = np.array([k1, k2, p1, p2, k3])
K = np.eye(3)
criteria = (cv2.TERM_CRITERIA_COUNT | cv2.TERM_CRITERIA_EPS, 1000, 1e-15)
und = cv2.undistortPointsIter(rows[:, 0:2].reshape(-1, 1, 2), K, dist, None, None, criteria)
obj = np.column_stack([rows[:, 2], rows[:, 3], np.ones(len(rows))]).reshape(-1, 1, 3)
proj, _ = cv2.projectPoints(obj, np.zeros(3), np.zeros(3), K, dist)
np.savetxt(sys.argv[7], np.column_stack([und.reshape(-1, 2), proj.reshape(-1, 2)]), fmt="%.17g")
)";

struct Case {
    const char* name;
    model::Distortion k;
    double x_offset_m;
    double y_offset_m;
};

TEST(OpenCvOracle, DistortionMatchesProjectPointsAndUndistortPoints) {
    if (!python_has("cv2, numpy")) {
        GTEST_SKIP() << GLINT_ORACLE_PYTHON
                     << " cannot import cv2 (install python3-opencv for the oracle)";
    }
    // The array's corner is at r ≈ 0.04 (normalised); the coefficients bend it by up to 1 %.
    const std::vector<Case> cases{
        {"barrel", {-2.5, 3.0, -8.0, 0, 0}, 0, 0},
        {"pincushion", {3.0, -2.0, 5.0, 0, 0}, 0, 0},
        {"tangential", {0.5, 0, 0, 0.004, -0.003}, 0, 0},
        {"all, offset array", {-1.5, 4.0, 2.0, -0.002, 0.003}, 3e-4, -2e-4},
    };
    TempDir dir;
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        model::InstrumentProperties properties;
        properties.focal_length_m = kFocal_m;
        properties.distortion = c.k;
        model::DetectorArray array;
        array.x_count = kColumns;
        array.y_count = kRows;
        array.x_spacing_m = array.y_spacing_m = array.x_size_m = array.y_size_m = kPitch_m;
        array.x_offset_m = c.x_offset_m;
        array.y_offset_m = c.y_offset_m;
        const CameraModel camera(properties, array, kColumns, kRows);

        // A 9 × 7 grid of pixel centres from corner to corner.
        std::vector<std::array<double, 2>> distorted;  // focal-plane point / f
        std::vector<Vec3> directions;                  // glint's undistorted directions
        for (std::size_t j = 0; j < 7; ++j) {
            for (std::size_t i = 0; i < 9; ++i) {
                const std::size_t column = i * (kColumns - 1) / 8;
                const std::size_t row = j * (kRows - 1) / 6;
                const std::array<double, 2> fp = camera.focal_plane_point(column, row, 0.5, 0.5);
                distorted.push_back({fp[0] / kFocal_m, fp[1] / kFocal_m});
                directions.push_back(camera.direction(fp));
            }
        }
        const auto input = dir / "points.txt";
        const auto output = dir / "opencv.txt";
        {
            std::ofstream out(input);
            out.precision(17);
            for (std::size_t n = 0; n < distorted.size(); ++n) {
                const Vec3& d = directions[n];
                out << distorted[n][0] << ' ' << distorted[n][1] << ' ' << d.x / -d.z << ' '
                    << d.y / -d.z << '\n';
            }
        }
        auto number = [](double v) {
            std::ostringstream s;
            s.precision(17);
            s << v;
            return s.str();
        };
        const CommandResult result = run_command(
            python_command(dir, kOpenCv,
                           {number(c.k.k1), number(c.k.k2), number(c.k.k3), number(c.k.p1),
                            number(c.k.p2), input.string(), output.string()}));
        ASSERT_EQ(result.exit_status, 0) << result.err;

        std::ifstream in(output);
        double worst_inverse = 0, worst_forward = 0, worst_bend = 0;
        for (std::size_t n = 0; n < distorted.size(); ++n) {
            double x_u = 0, y_u = 0, x_p = 0, y_p = 0;
            ASSERT_TRUE(in >> x_u >> y_u >> x_p >> y_p) << n;
            const Vec3& d = directions[n];
            // Inverse: glint's direction() against cv2.undistortPointsIter.
            worst_inverse =
                std::max({worst_inverse, std::fabs(d.x / -d.z - x_u), std::fabs(d.y / -d.z - y_u)});
            // Forward: cv2.projectPoints of glint's direction lands where glint's pixel is,
            // and glint's project() of it too.
            worst_forward = std::max({worst_forward, std::fabs(x_p - distorted[n][0]),
                                      std::fabs(y_p - distorted[n][1])});
            const auto pixel = camera.project(d);
            ASSERT_TRUE(pixel.has_value());
            const double x_glint =
                (((*pixel)[0] - kColumns / 2.0) * kPitch_m + c.x_offset_m) / kFocal_m;
            const double y_glint =
                (-((*pixel)[1] - kRows / 2.0) * kPitch_m + c.y_offset_m) / kFocal_m;
            worst_forward =
                std::max({worst_forward, std::fabs(x_glint - x_p), std::fabs(y_glint - y_p)});
            worst_bend = std::max({worst_bend, std::fabs(d.x / -d.z - distorted[n][0]),
                                   std::fabs(d.y / -d.z - distorted[n][1])});
        }
        std::cout << "[ opencv   ] " << c.name << ": max |glint - opencv| " << worst_inverse
                  << " (undistort), " << worst_forward << " (project), normalised; the "
                  << "distortion moves points by up to " << worst_bend << '\n';
        EXPECT_LT(worst_inverse, 1e-12);
        EXPECT_LT(worst_forward, 1e-12);
        EXPECT_GT(worst_bend, 1e-5);  // the distortion is not negligible: the test can fail
    }
}

}  // namespace opencv_distortion_test
}  // namespace glint::sensor::oracle
