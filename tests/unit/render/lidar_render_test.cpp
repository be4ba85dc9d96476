// SPDX-License-Identifier: Apache-2.0
// Lidar receivers through glint-render's capture loop (tests/data/lidar): a 16 × 16 receiver
// 1000 m above a Lambertian plate collects, summed over its pixels and time bins, the photons
// of the lidar equation E ρ A / (π R²) · QE · λ/(h c), peaking in the bin of 2R/c; its passive
// term equals a simple capture's photon rate in the same band through the same optics; the
// detector model's QE scales both; its pixels are in DIRSIG's order (x slowest); the BIN
// file's headers say what was simulated.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <numeric>
#include <string>
#include <vector>

#include "glint/core/error.h"
#include "glint/io/envi.h"
#include "glint/io/lidar_bin.h"
#include "glint/render/render.h"
#include "glint/test/temp_dir.h"
#include "render_fixture.h"

namespace glint::render {
namespace lidar_render_test {

namespace fs = std::filesystem;
using test_render::load;
using test_render::options_into;
using test_render::read_text;

const fs::path kLidarData = fs::path(GLINT_TEST_DATA_DIR) / "lidar";
const fs::path kRenderData = fs::path(GLINT_TEST_DATA_DIR) / "render";

/// The fixture's simulation in `dir` with its platform edited by `edit` (and another scene
/// when `scene` is given).
fs::path write_simulation(const fs::path& dir, const std::function<std::string(std::string)>& edit,
                          const fs::path& scene = kLidarData / "plate.yaml") {
    std::ofstream(dir / "lidar.platform") << edit(read_text(kLidarData / "lidar.platform"));
    std::ofstream(dir / "lidar.jsim")
        << "[{\"scene_list\": [{\"inputs\": \"" << scene.string() << "\"}], \"plugin_list\": [\n"
        << " {\"name\": \"BasicAtmosphere\", \"inputs\": {\"atmosphere_filename\": \""
        << (kRenderData / "none.atm.yaml").string() << "\"}},\n"
        << " {\"name\": \"BasicPlatform\", \"inputs\": {\"platform_filename\": \"lidar.platform\", "
        << "\"motion_filename\": \"" << (kRenderData / "static.ppd").string()
        << "\", \"tasks_filename\": \"" << (kRenderData / "snapshot.tasks").string() << "\"}}]}]\n";
    return dir / "lidar.jsim";
}

std::string replace(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

/// Each pixel's active values summed over its time samples, and the histogram summed over
/// pixels.
struct Sums {
    double total = 0.0;
    std::vector<double> histogram;
    std::vector<double> passive;
};

Sums sums_of(const io::BinFile& file) {
    const io::BinPulse& p = file.tasks.at(0).pulses.at(0);
    const std::size_t values = p.values_per_pixel();
    Sums s;
    s.histogram.assign(values - 1, 0.0);
    for (std::size_t i = 0; i < p.data.size() / values; ++i) {
        s.passive.push_back(p.data[i * values]);
        for (std::size_t j = 1; j < values; ++j) s.histogram[j - 1] += p.data[i * values + j];
    }
    s.total = std::accumulate(s.histogram.begin(), s.histogram.end(), 0.0);
    return s;
}

/// A simple-capture camera with the lidar's optics, band and 16-column array (`rows` rows),
/// its image in photons/s per cm² at the focal plane (basename cam), for the platform's
/// attachment.
std::string camera_beside_the_lidar(int rows) {
    return "    <instrument name=\"Cam\" type=\"generic\">\n"
           "      <properties><focallength>500</focallength>"
           "<aperturediameter>0.05</aperturediameter></properties>\n"
           "      <focalplane name=\"Frame\"><capturemethod type=\"simple\">\n"
           "        <imagefile fluxunits=\"photonspersecond\"><basename>cam</basename>"
           "</imagefile>\n"
           "        <spectralresponse><bandpass spectralunits=\"microns\"><minimum>1.060"
           "</minimum><maximum>1.068</maximum><delta>0.002</delta></bandpass>\n"
           "          <channellist><channel name=\"band\" shape=\"tophat\"><center>1.064</center>"
           "<width>0.02</width></channel></channellist></spectralresponse>\n"
           "      </capturemethod>\n"
           "      <detectorarray spatialunits=\"microns\">\n"
           "        <clock type=\"independent\" temporalunits=\"hertz\"><rate>10</rate>"
           "<offset>0</offset></clock>\n"
           "        <xelementcount>16</xelementcount><yelementcount>" +
           std::to_string(rows) +
           "</yelementcount>\n"
           "        <xelementsize>20</xelementsize><yelementsize>20</yelementsize>\n"
           "        <xelementspacing>20</xelementspacing><yelementspacing>20</yelementspacing>\n"
           "      </detectorarray></focalplane>\n"
           "    </instrument>\n";
}

TEST(LidarRender, ReturnedPhotonsFollowTheLidarEquationAndPeakAt2ROverC) {
    test::TempDir dir;
    RenderOptions options = options_into(dir / "out");
    options.convergence = radiometry::Convergence{1000, 1000, 0.0};
    const RenderReport report = render(load(kLidarData / "lidar.jsim"), options, Context{});
    ASSERT_EQ(report.files, std::vector<fs::path>{dir / "out" / "lidar.bin"});
    const io::BinFile file = io::read_bin(dir / "out" / "lidar.bin");
    const Sums s = sums_of(file);
    // E ρ A / (π R²) photons at λ/(h c) per joule: the whole beam (w = 50 µrad) falls inside
    // the 640 µrad field of view.
    constexpr double kEnergy = 1e-3, kRho = 0.3, kDiameter = 0.05, kRange = 1000.0;
    const double area = std::numbers::pi * kDiameter * kDiameter / 4.0;
    const double photons_per_joule = 1.064e-6 / (6.62607015e-34 * 299792458.0);
    const double expected =
        kEnergy * kRho * area / (std::numbers::pi * kRange * kRange) * photons_per_joule;
    // 2 %: 1000 samples per pixel leave about 0.7 % of Monte-Carlo error on the sum (the beam
    // covers a few pixels), and glint's G# = (1 + 4F²)/π is 0.25 % below the paraxial 4F²/π
    // of the lidar equation at F = 10.
    EXPECT_NEAR(s.total, expected, 0.02 * expected);
    const std::size_t peak = static_cast<std::size_t>(
        std::max_element(s.histogram.begin(), s.histogram.end()) - s.histogram.begin());
    EXPECT_EQ(peak,
              static_cast<std::size_t>(std::floor((2.0 * kRange / 299792458.0 - 6e-6) / 1e-9)));
    EXPECT_EQ(peak, 671u);

    // The headers say what was simulated.
    EXPECT_EQ(file.header.x_count, 16u);
    EXPECT_EQ(file.header.y_count, 16u);
    EXPECT_NEAR(file.header.x_pitch_m, 20e-6, 1e-15);
    EXPECT_NEAR(file.header.origin_latitude_deg, 43.0, 1e-12);
    EXPECT_EQ(file.header.created, "20200621T160000");
    const io::BinTaskHeader& task = file.tasks.at(0).header;
    EXPECT_DOUBLE_EQ(task.focal_length_mm, 500.0);
    EXPECT_DOUBLE_EQ(task.pulse_rate_hz, 10.0);
    EXPECT_DOUBLE_EQ(task.pulse_energy_j, 1e-3);
    EXPECT_DOUBLE_EQ(task.pulse_duration_s, 5e-9);
    EXPECT_DOUBLE_EQ(task.laser_center_um, 1.064);
    EXPECT_DOUBLE_EQ(task.laser_width_um, 1e-4);
    const io::BinPulse& pulse = file.tasks.at(0).pulses.at(0);
    EXPECT_EQ(pulse.bin_count, 1500u);
    EXPECT_EQ(pulse.samples_per_bin, 1u);
    EXPECT_DOUBLE_EQ(pulse.gate_start_s, 6e-6);
    EXPECT_DOUBLE_EQ(pulse.gate_stop_s, 7.5e-6);
    EXPECT_NEAR(pulse.platform_location[2], 1000.0, 1e-9);
    EXPECT_EQ(pulse.data.size(), 16u * 16u * 1501u);
}

TEST(LidarRender, PassiveTermEqualsASimpleCapturesPhotonRateInTheSameBand) {
    // One platform, the lidar and a camera with the same optics, array and band, its image in
    // photons/s per cm² at the focal plane: passive = camera × element area (cm²).
    test::TempDir dir;
    const fs::path jsim = write_simulation(dir.path(), [](std::string text) {
        return replace(text, "  </attachment>", camera_beside_the_lidar(16) + "  </attachment>");
    });
    RenderOptions options = options_into(dir / "out");
    options.convergence = radiometry::Convergence{64, 64, 0.0};
    const RenderReport report = render(load(jsim), options, Context{});
    ASSERT_EQ(report.files.size(), 2u);
    const Sums s = sums_of(io::read_bin(dir / "out" / "lidar.bin"));
    const std::vector<double> camera = io::read_envi_bip(dir / "out" / "cam.img", nullptr);
    ASSERT_EQ(camera.size(), s.passive.size());
    const double element_cm2 = 20e-4 * 20e-4;
    for (std::size_t y = 0; y < 16; ++y) {
        for (std::size_t x = 0; x < 16; ++x) {
            // 0.5 %: a sunlit Lambertian plate is nearly uniform over a pixel, so the two
            // captures' independent samples differ by far less (the sun disc's sampling).
            const double expected = camera[y * 16 + x] * element_cm2;
            EXPECT_NEAR(s.passive[io::bin_pixel_index(x, y, 16)], expected, 0.005 * expected)
                << "pixel (" << x << ", " << y << ")";
        }
    }
    EXPECT_GT(s.passive[0], 1e6);  // photons/s: the sun at noon on a ρ = 0.3 plate
}

TEST(LidarRender, PixelsAreInDirsigsOrderXSlowest) {
    // A 16 × 8 array (x and y orders differ) over the grey plate with a white box covering one
    // corner of the view: the BIN file's pixel (x, y), read at bin_pixel_index(x, y, 8), is
    // the camera's pixel (x, y) of the same optics, so the box appears in the same corner.
    test::TempDir dir;
    std::ofstream(dir / "corner.yaml")
        << "origin: {latitude: 43.0, longitude: -77.6, altitude: 150}\n"
           "materials:\n"
           "  - {id: grey, reflectance: {wavelengths: [0.3, 2.0], values: [0.3, 0.3]}}\n"
           "  - {id: white, reflectance: {wavelengths: [0.3, 2.0], values: [0.9, 0.9]}}\n"
           "objects:\n"
           "  - {name: ground, primitive: ground_plane, material: grey}\n"
           "  - {name: panel, primitive: box, material: white, lower: [0.05, 0.03, 0],\n"
           "     upper: [2, 2, 0.001]}\n";
    const fs::path jsim = write_simulation(
        dir.path(),
        [](std::string text) {
            text = replace(text, "<yelementcount>16</yelementcount>",
                           "<yelementcount>8</yelementcount>");
            return replace(text, "  </attachment>", camera_beside_the_lidar(8) + "  </attachment>");
        },
        dir / "corner.yaml");
    RenderOptions options = options_into(dir / "out");
    options.convergence = radiometry::Convergence{256, 256, 0.0};
    render(load(jsim), options, Context{});
    const io::BinFile file = io::read_bin(dir / "out" / "lidar.bin");
    ASSERT_EQ(file.header.x_count, 16u);
    ASSERT_EQ(file.header.y_count, 8u);
    const io::BinPulse& pulse = file.tasks.at(0).pulses.at(0);
    const std::vector<double> camera = io::read_envi_bip(dir / "out" / "cam.img", nullptr);
    ASSERT_EQ(camera.size(), 16u * 8u);
    const double element_cm2 = 20e-4 * 20e-4;
    const auto [darkest, brightest] = std::minmax_element(camera.begin(), camera.end());
    ASSERT_GT(*brightest, 2.5 * *darkest) << "test design: the box must be in view, not all of it";
    const double reference = *brightest * element_cm2;
    for (std::size_t y = 0; y < 8; ++y) {
        for (std::size_t x = 0; x < 16; ++x) {
            const double passive =
                pulse.data[io::bin_pixel_index(x, y, 8) * pulse.values_per_pixel()];
            // 20 % of the brightest: 256 samples leave a partly covered edge pixel about 3 %
            // of it apart between the two captures (white 0.9 against grey 0.3); a pixel from
            // the wrong place is up to 67 % apart.
            EXPECT_NEAR(passive, camera[y * 16 + x] * element_cm2, 0.2 * reference)
                << "pixel (" << x << ", " << y << ")";
        }
    }
}

TEST(LidarRender, TheDetectorModelsQuantumEfficiencyScalesPassiveAndActiveAlike) {
    test::TempDir dir;
    RenderOptions options = options_into(dir / "one");
    options.convergence = radiometry::Convergence{20, 20, 0.0};
    render(load(kLidarData / "lidar.jsim"), options, Context{});
    const fs::path jsim = write_simulation(dir.path(), [](std::string text) {
        return replace(text, "<signalgate>",
                       "<detectormodel><quantumefficiency>0.4</quantumefficiency>"
                       "</detectormodel>\n          <signalgate>");
    });
    options = options_into(dir / "qe");
    options.convergence = radiometry::Convergence{20, 20, 0.0};
    render(load(jsim), options, Context{});
    const Sums one = sums_of(io::read_bin(dir / "one" / "lidar.bin"));
    const Sums qe = sums_of(io::read_bin(dir / "qe" / "lidar.bin"));
    // Same seeds, same samples: exactly 0.4 × (to rounding).
    EXPECT_NEAR(qe.total, 0.4 * one.total, 1e-12 * one.total);
    for (std::size_t i = 0; i < one.passive.size(); ++i) {
        EXPECT_NEAR(qe.passive[i], 0.4 * one.passive[i], 1e-12 * one.passive[i]);
    }
}

TEST(LidarRender, AReceiverWithoutAnApertureIsAnInputErrorAtItsProperties) {
    test::TempDir dir;
    const fs::path jsim = write_simulation(dir.path(), [](std::string text) {
        return replace(text, "<aperturediameter>0.05</aperturediameter>", "");
    });
    try {
        render(load(jsim), options_into(dir / "out"), Context{});
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_NE(e.message().find("needs a collecting aperture"), std::string::npos)
            << e.message();
        EXPECT_NE(e.context().file.find("lidar.platform"), std::string::npos);
    }
    EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(LidarRender, ATabulatedPulseShapeIsUsedAsWritten) {
    // A flat 4 ns pulse starting at the firing time: the ground's return (671.28 ns into the
    // gate) spreads over [671.28, 675.28) ns, so bins 671–675 hold it in the ratio
    // 0.72 : 1 : 1 : 1 : 0.28 — the shape read from the file, not a Gaussian.
    test::TempDir dir;
    std::ofstream(dir / "flat.txt") << "# time (s) power\n0 1\n4e-9 1\n";
    const fs::path jsim = write_simulation(dir.path(), [](std::string text) {
        return replace(text, "<pulseshape type=\"gaussian\"/>",
                       "<pulseshape type=\"tabulated\"><filename>flat.txt</filename>"
                       "</pulseshape>");
    });
    RenderOptions options = options_into(dir / "out");
    options.convergence = radiometry::Convergence{20, 20, 0.0};
    render(load(jsim), options, Context{});
    const Sums s = sums_of(io::read_bin(dir / "out" / "lidar.bin"));
    const double full = s.histogram[672];
    ASSERT_GT(full, 0.0);
    // Pixels see the ground at slightly different ranges (≤ 0.3 µrad off-axis): 1e-3 of a bin.
    EXPECT_NEAR(s.histogram[671] / full, 0.72, 0.01);
    EXPECT_NEAR(s.histogram[673] / full, 1.0, 1e-3);
    EXPECT_NEAR(s.histogram[674] / full, 1.0, 1e-3);
    EXPECT_NEAR(s.histogram[675] / full, 0.28, 0.01);
    EXPECT_EQ(s.histogram[670], 0.0);
    EXPECT_EQ(s.histogram[676], 0.0);
}

}  // namespace lidar_render_test
}  // namespace glint::render
