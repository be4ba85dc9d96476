// SPDX-License-Identifier: Apache-2.0
// OpenCV as an oracle for Bayer bilinear demosaicing: `cv2.demosaicing` (python3-opencv) on a
// 16-bit mosaic must agree with glint's bilinear result within 1 DN everywhere but on the
// outermost pixels (OpenCV fills those by copying), for all four phases, odd and even sizes.
// OpenCV names a layout after the second line's second and third pixels, so glint's rggb is
// COLOR_BayerBG2RGB, grbg BayerGB, gbrg BayerGR and bggr BayerRG (cfa.h). Skips when cv2
// cannot be imported.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "glint/demosaic/demosaic.h"
#include "glint/test/oracle.h"
#include "glint/test/temp_dir.h"

namespace glint::demosaic::oracle {
namespace opencv_bayer_test {

using glint::test::CommandResult;
using glint::test::python_command;
using glint::test::python_has;
using glint::test::run_command;
using glint::test::TempDir;

/// Reads a native-order uint16 mosaic (h × w), demosaics it with OpenCV, writes h × w × 3
/// uint16 values (R, G, B).
constexpr const char* kOpenCvDemosaic = R"(
import sys
import numpy as np
import cv2
w, h, code, src, dst = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3], sys.argv[4], sys.argv[5]
mosaic = np.fromfile(src, dtype=np.uint16).reshape(h, w)
rgb = cv2.demosaicing(mosaic, getattr(cv2, "COLOR_" + code + "2RGB"))
assert rgb.dtype == np.uint16 and rgb.shape == (h, w, 3)
np.ascontiguousarray(rgb).tofile(dst)
)";

const char* opencv_code(BayerPhase phase) {
    switch (phase) {
        case BayerPhase::rggb:
            return "BayerBG";
        case BayerPhase::grbg:
            return "BayerGB";
        case BayerPhase::gbrg:
            return "BayerGR";
        case BayerPhase::bggr:
            return "BayerRG";
    }
    return "?";
}

/// Full-range pseudo-random 16-bit values mixed with a smooth slanted ramp, so that both
/// noise and gradients are compared.
Plane test_mosaic(std::size_t w, std::size_t h, unsigned seed) {
    Plane plane{w, h, {}};
    std::uint64_t state = 0x9e3779b97f4a7c15ull * (seed + 1);
    for (std::size_t y = 0; y < h; ++y) {
        for (std::size_t x = 0; x < w; ++x) {
            state = state * 6364136223846793005ull + 1442695040888963407ull;
            const double noise = static_cast<double>((state >> 33) % 65536);
            const double ramp = 300.0 * static_cast<double>(x) + 150.0 * static_cast<double>(y);
            const double v = (x / 8 + y / 8) % 2 == 0 ? noise : std::fmod(ramp, 65535.0);
            plane.values.push_back(std::round(v));
        }
    }
    return plane;
}

std::vector<std::uint16_t> opencv_demosaic(const TempDir& dir, const Plane& mosaic,
                                           BayerPhase phase) {
    std::vector<std::uint16_t> in(mosaic.values.begin(), mosaic.values.end());
    const auto src = dir / "mosaic.u16";
    const auto dst = dir / "rgb.u16";
    std::ofstream(src, std::ios::binary)
        .write(reinterpret_cast<const char*>(in.data()),
               static_cast<std::streamsize>(in.size() * sizeof(std::uint16_t)));
    const CommandResult result =
        run_command(python_command(dir, kOpenCvDemosaic,
                                   {std::to_string(mosaic.width), std::to_string(mosaic.height),
                                    opencv_code(phase), src.string(), dst.string()}));
    EXPECT_EQ(result.exit_status, 0) << result.err;
    std::vector<std::uint16_t> out(mosaic.values.size() * 3);
    std::ifstream(dst, std::ios::binary)
        .read(reinterpret_cast<char*>(out.data()),
              static_cast<std::streamsize>(out.size() * sizeof(std::uint16_t)));
    return out;
}

TEST(OpenCvOracle, BayerBilinearMatchesCvDemosaicingWithinOneDnAwayFromBorders) {
    if (!python_has("cv2, numpy")) {
        GTEST_SKIP() << GLINT_ORACLE_PYTHON
                     << " cannot import cv2 (install python3-opencv for the oracle)";
    }
    TempDir dir;
    for (const auto& [w, h] :
         std::vector<std::pair<std::size_t, std::size_t>>{{64, 48}, {37, 29}}) {
        for (BayerPhase phase :
             {BayerPhase::rggb, BayerPhase::grbg, BayerPhase::gbrg, BayerPhase::bggr}) {
            SCOPED_TRACE(std::string(bayer_phase_name(phase)) + " = " + opencv_code(phase) + ", " +
                         std::to_string(w) + "x" + std::to_string(h));
            const Plane mosaic = test_mosaic(w, h, static_cast<unsigned>(w + h));
            const RgbImage ours = demosaic_bayer_bilinear(mosaic, phase);
            const std::vector<std::uint16_t> theirs = opencv_demosaic(dir, mosaic, phase);
            // Largest difference at each distance from the nearest border (0, 1, >= 2).
            double max_diff[3] = {0, 0, 0};
            std::size_t compared = 0, exact = 0;
            for (std::size_t y = 0; y < h; ++y) {
                for (std::size_t x = 0; x < w; ++x) {
                    const std::size_t d = std::min({x, y, w - 1 - x, h - 1 - y, std::size_t{2}});
                    for (std::size_t c = 0; c < 3; ++c) {
                        const double diff =
                            std::fabs(ours.at(x, y, c) - theirs[(y * w + x) * 3 + c]);
                        max_diff[d] = std::max(max_diff[d], diff);
                        if (d == 2) {
                            ++compared;
                            if (std::round(ours.at(x, y, c)) == theirs[(y * w + x) * 3 + c]) {
                                ++exact;
                            }
                        }
                    }
                }
            }
            std::cout << "[ opencv   ] " << bayer_phase_name(phase) << " (" << opencv_code(phase)
                      << ") " << w << "x" << h << ": max |glint - opencv| " << max_diff[2]
                      << " DN from 2 px in (" << exact << " of " << compared
                      << " values equal after rounding); " << max_diff[1] << " DN 1 px in; "
                      << max_diff[0] << " DN on the border\n";
            EXPECT_LE(max_diff[2], 1.0);
            EXPECT_LE(max_diff[1], 1.0);
        }
    }
}

}  // namespace opencv_bayer_test
}  // namespace glint::demosaic::oracle
