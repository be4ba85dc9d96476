// SPDX-License-Identifier: Apache-2.0
// Truth collection (docs/truth.md), continued from truth_test.cpp: the sample count is what the
// convergence settings give, the standard error the spread of the samples (∝ 1/√N), split
// channels sum their states; the first-hit bands agree with the materials hit; and collecting
// truth changes neither the radiance nor, with the thread count, the truth's bytes. The scene
// and camera are truth_fixture.h's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "truth_fixture.h"

namespace glint::render {
namespace truth_convergence_test {

using namespace test_truth;

// --- Sample count and standard error ---------------------------------------------------------

/// An edge scene: ground of `dark` reflectance, a 1 mm bright slab (0.9) for y ≥ 0.1 m, the
/// centre line of row 3; `truth` collected (`channels` as write_simulation's).
void write_edge(const fs::path& dir, double dark, const std::string& truth,
                const std::string& channels = {}) {
    write_simulation(dir,
                     "materials:\n"
                     "  - {id: dark, reflectance: {wavelengths: [0.3, 1.0], values: [" +
                         std::to_string(dark) + ", " + std::to_string(dark) +
                         "]}}\n"
                         "  - {id: bright, reflectance: {wavelengths: [0.3, 1.0], values: "
                         "[0.9, 0.9]}}\n"
                         "objects:\n"
                         "  - {name: ground, primitive: ground_plane, material: dark}\n"
                         "  - {name: slab, primitive: box, material: bright, lower: [-1000, "
                         "0.1, 0], upper: [1000, 1000, 0.001]}\n",
                     truth, channels);
}

TEST(Truth, SampleCountIsWhatTheConvergenceSettingsGive) {
    test::TempDir dir;
    write_edge(dir.path(), 0.05, truth_collection("T", "t", collector("SampleCount")));
    // min = max = N: every pixel N.
    const Rendered fixed = render_into(dir.path(), {8, 8, 0.0});
    for (std::size_t p = 0; p < kSide * kSide; ++p) {
        EXPECT_EQ(fixed.truth.values[p], 8.0) << p;
    }
    // With a threshold of 1e-4 W/(cm² sr µm): a uniform pixel's samples differ only by the
    // sun's disc draw (1e-3 relative of ≤ 0.046 W/(cm² sr µm)), so its mean moves by far less
    // than 1e-4 per sample and it stops at the minimum; an edge pixel's samples are 0.0026
    // or 0.046 (p = 0.5), its mean moves by ~0.022/N per sample, which stays above 1e-4 up
    // to N ≈ 220 (about 200 measured). It stops at the minimum only if all 16 first samples
    // fall on one side (probability 2^-15).
    const Rendered adaptive = render_into(dir.path(), {16, 512, 1e-4});
    for (std::size_t row = 0; row < kSide; ++row) {
        for (std::size_t column = 0; column < kSide; ++column) {
            const double n = adaptive.truth.at("Sample Count", column, row);
            if (row == 3) {
                EXPECT_GT(n, 16.0) << column;
                EXPECT_LE(n, 512.0) << column;
            } else {
                EXPECT_EQ(n, 16.0) << column << ", " << row;
            }
        }
    }
    // The render's own statistics agree.
    ASSERT_EQ(adaptive.report.captures.size(), 1u);
    const CaptureReport& stats = adaptive.report.captures[0];
    EXPECT_EQ(stats.min_samples, 16u);
    double total = 0.0;
    double most = 0.0;
    for (const double n : adaptive.truth.values) {
        total += n;
        most = std::max(most, n);
    }
    EXPECT_EQ(static_cast<double>(stats.max_samples), most);
    EXPECT_DOUBLE_EQ(stats.mean_samples, total / (kSide * kSide));
}

TEST(Truth, StandardErrorIsTheSpreadOfTheSamplesAndShrinksAsOneOverRootN) {
    // A black ground (its radiance is its own emission, the same for every sample) and the
    // bright slab over half of row 3.
    test::TempDir dir;
    write_edge(
        dir.path(), 0.0,
        truth_collection("T", "t", collector("StandardError") + collector("Abundance", "bright")));
    const Rendered coarse = render_into(dir.path(), {64, 64, 0.0});
    fs::remove_all(dir / "out");
    const Rendered fine = render_into(dir.path(), {1024, 1024, 0.0});
    const std::string band = "Standard Error 'Green'";
    EXPECT_EQ(fine.truth.header.find_extra("glint band units"), "{Watts/(cm2 sr um), fraction}");
    double ratio_sum = 0.0;
    for (std::size_t column = 0; column < kSide; ++column) {
        for (const std::size_t row : {4u, 5u, 6u, 7u}) {
            // Every sample the same value: exactly no spread.
            EXPECT_EQ(coarse.truth.at(band, column, row), 0.0) << column << ", " << row;
            EXPECT_EQ(fine.truth.at(band, column, row), 0.0) << column << ", " << row;
        }
        // The edge pixels' samples take two values, L_dark (row 7's) and L_bright (row 0's,
        // up to the sun disc's ~1e-3 relative draw): with a the bright fraction of the
        // samples (the Abundance band), their variance is a(1 − a)(ΔL)² and the standard
        // error of the mean √(a(1 − a)/(N − 1)) ΔL (N effective samples, weights 1). The
        // bright samples spread by 1.1e-3 relative (the sun disc's draw), so row 0's mean and
        // that of the edge pixel's bright samples differ by ~1.1e-3 √(1/64 + 1/32) = 2.4e-4
        // relative at N = 64 (less at 1024): 1e-3 is 4 of those.
        for (const Rendered* r : {&coarse, &fine}) {
            const double n = r == &coarse ? 64.0 : 1024.0;
            const double a = r->truth.at("Material Abundance 'bright'", column, 3);
            const double delta = r->radiance(column, 0) - r->radiance(column, 7);
            const double expected = std::sqrt(a * (1.0 - a) / (n - 1.0)) * delta;
            EXPECT_NEAR(r->truth.at(band, column, 3) / expected, 1.0, 1e-3)
                << column << ", N = " << n;
        }
        ratio_sum += coarse.truth.at(band, column, 3) / fine.truth.at(band, column, 3);
    }
    // 1/√N: from N = 64 to 1024 the standard error shrinks 4×. With p = 0.5 the estimated
    // variance is 0.25 ΔL² (1 − χ²₁/N) (a's binomial spread), so each pixel's ratio is
    // 4 √((1 − χ²/64)/(1 − χ²/1024)) · √(1023/63)/4: the mean over the 8 edge pixels is
    // 4.00 with a spread of ~0.016; 0.1 is 6 of those.
    const double ratio = ratio_sum / kSide;
    EXPECT_NEAR(ratio, 4.0, 0.1);
}

TEST(Truth, WithSplitChannelsSampleCountSumsTheStatesAndEachChannelHasItsOwnError) {
    // Three tophat channels on the 0.50–0.60 µm grid (as split_channels_test's), each its own
    // spectral state with its own samples: the sample count is the paths of all states (3N),
    // each channel's standard error comes from its own state's samples.
    test::TempDir dir;
    write_edge(dir.path(), 0.0,
               truth_collection("T", "t",
                                collector("SampleCount") + collector("StandardError") +
                                    collector("Abundance", "bright")),
               R"(<channellist>
              <channel name="Blue" shape="tophat"><center>0.52</center><width>0.05</width></channel>
              <channel name="Mid" shape="tophat"><center>0.55</center><width>0.03</width></channel>
              <channel name="Red" shape="tophat"><center>0.58</center><width>0.05</width></channel>
            </channellist>)");
    constexpr std::uint64_t kSamples = 256;
    RenderOptions options = options_into(dir / "out");
    options.convergence = radiometry::Convergence{kSamples, kSamples, 0.0};
    options.only_captures = {0};
    options.split_channels = true;
    render(load(dir / "one.jsim"), options, Context{});
    io::EnviHeader image_header;
    const std::vector<double> image = io::read_envi_bip(dir / "out" / "frame.img", &image_header);
    TruthImage truth;
    truth.values = io::read_envi_bip(dir / "out" / "t.img", &truth.header);
    ASSERT_EQ(image_header.find_extra("glint split channels"), "true");
    ASSERT_EQ(truth.header.bands, 5u);
    const char* names[] = {"Blue", "Mid", "Red"};
    std::size_t differing = 0;
    for (std::size_t c = 0; c < 3; ++c) {
        const std::string band = std::string("Standard Error '") + names[c] + "'";
        for (std::size_t column = 0; column < kSide; ++column) {
            for (std::size_t row = 0; row < kSide; ++row) {
                EXPECT_EQ(truth.at("Sample Count", column, row), 3.0 * kSamples);
                if (row > 3) {
                    EXPECT_EQ(truth.at(band, column, row), 0.0) << band;
                }
            }
            // Each state's samples in the edge pixel are L_dark or L_bright of its channel
            // (rows 7 and 0): its bright share a_c is (L − L_dark)/ΔL of the pixel's value in
            // the image, its standard error √(a_c(1 − a_c)/(N − 1)) ΔL as in the joint case,
            // to the sun disc's 1.1e-3 √(1/256 + 1/128) = 1.2e-4 relative: 1e-3 is 8 of those.
            const auto value = [&](std::size_t row) {
                return image[(row * kSide + column) * 3 + c];
            };
            const double delta = value(0) - value(7);
            const double a = (value(3) - value(7)) / delta;
            const double expected = std::sqrt(a * (1.0 - a) / (kSamples - 1.0)) * delta;
            EXPECT_NEAR(truth.at(band, column, 3) / expected, 1.0, 1e-3) << band << " " << column;
            // The first-hit truth is the first state's: its share is the Blue channel's; the
            // other states draw their own samples.
            const double first = truth.at("Material Abundance 'bright'", column, 3);
            if (c == 0) {
                EXPECT_NEAR(a, first, 1e-3) << column;
            } else if (std::fabs(a - first) > 1e-3) {
                ++differing;
            }
        }
    }
    EXPECT_GT(differing, 8u) << "the Mid and Red states drew the Blue state's samples";
}

// --- Truth changes nothing -------------------------------------------------------------------

/// scene.yaml's grey plate and white box (edges, shadows, bounces between them) plus a black
/// block, tagged "dark", at 320 K (its first hits get a shadow ray for truth alone). The
/// materials and the instances are in the same order: grey/ground, white/box, black/block.
constexpr const char* kMixedScene = R"(materials:
  - {id: grey, reflectance: {wavelengths: [0.3, 1.0], values: [0.2, 0.2]}}
  - {id: white, reflectance: {wavelengths: [0.3, 1.0], values: [0.9, 0.9]}}
  - {id: black, reflectance: {wavelengths: [0.3, 1.0], values: [0, 0]}, temperature: 320}
objects:
  - {name: ground, primitive: ground_plane, material: grey}
  - {name: box, primitive: box, material: white, lower: [-0.3, -0.3, 0], upper: [0.3, 0.3, 0.5]}
  - name: block
    primitive: box
    material: black
    lower: [0.35, -0.7, 0]
    upper: [0.75, -0.35, 0.2]
    instances: [{name: block, tags: [dark]}]
)";

TEST(Truth, TemperatureReflectanceAndIndicesAreThoseOfTheMaterialsHit) {
    // Every sample hits one of the three materials, so per pixel, with a_m the abundances,
    // temperature = 300 K + 20 K a_black and reflectance = 0.2 a_grey + 0.9 a_white (the
    // reflectances are flat, so the reference wavelength does not matter): identities up to
    // rounding (1e-12). The block is the only black and the only "dark" instance, and the
    // instances follow the materials' order, so the tag's abundance is black's and the
    // instance and object indices are the material index.
    test::TempDir dir;
    write_simulation(dir.path(), kMixedScene,
                     truth_collection("T", "t",
                                      collector("Material") + collector("InstanceId") +
                                          collector("Abundance", "grey,white,black") +
                                          "<collector><name>Abundance</name><tags>dark</tags>"
                                          "</collector>" +
                                          collector("Temperature") + collector("Reflectance")));
    const Rendered r = render_into(dir.path(), {64, 64, 0.0});
    std::size_t mixed = 0;
    for (std::size_t row = 0; row < kSide; ++row) {
        for (std::size_t column = 0; column < kSide; ++column) {
            const auto at = [&](const std::string& band) { return r.truth.at(band, column, row); };
            const double grey = at("Material Abundance 'grey'");
            const double white = at("Material Abundance 'white'");
            const double black = at("Material Abundance 'black'");
            EXPECT_NEAR(grey + white + black, 1.0, 1e-12);
            EXPECT_EQ(at("Tag Abundance 'dark'"), black);
            EXPECT_NEAR(at("Temperature"), 300.0 + 20.0 * black, 1e-12);
            EXPECT_NEAR(at("Reflectance"), 0.2 * grey + 0.9 * white, 1e-12);
            EXPECT_EQ(at("Instance Index"), at("Material Index"));
            EXPECT_EQ(at("Object Index"), at("Material Index"));
            if (grey < 1.0 && white < 1.0 && black < 1.0) ++mixed;
        }
    }
    EXPECT_GT(mixed, 4u) << "too few mixed pixels to test";
    EXPECT_EQ(r.truth.header.find_extra("glint instance names"), "{ground, box, block}");
}

TEST(Truth, CollectingTruthChangesNoRadianceAndIsTheSameForAnyThreadCount) {
    // Adaptive convergence over kMixedScene.
    const std::string truth =
        truth_collection("T", "t",
                         collector("Material") + collector("Abundance", "white,black") +
                             collector("GeoLocation") + collector("Intersection") +
                             collector("Shadow") + collector("Temperature") +
                             collector("Reflectance") + collector("InstanceId")) +
        truth_collection("U", "u", collector("SampleCount") + collector("StandardError"));
    test::TempDir dir;
    write_simulation(dir / "plain", kMixedScene, "");
    write_simulation(dir / "truth", kMixedScene, truth);
    const radiometry::Convergence convergence{4, 64, 1e-5};
    const Rendered plain = render_into(dir / "plain", convergence, 2);
    const Rendered one = render_into(dir / "truth", convergence, 1);
    const std::vector<char> one_t = read_bytes(one.folder / "t.img");
    const std::vector<char> one_u = read_bytes(one.folder / "u.img");
    fs::remove_all(dir / "truth" / "out");
    const Rendered two = render_into(dir / "truth", convergence, 2);

    EXPECT_FALSE(fs::exists(plain.folder / "t.img"));
    const std::vector<char> image = read_bytes(plain.folder / "frame.img");
    ASSERT_EQ(image.size(), kSide * kSide * sizeof(double));
    EXPECT_EQ(read_bytes(one.folder / "frame.img"), image) << "truth changed the radiance";
    EXPECT_EQ(read_bytes(two.folder / "frame.img"), image);
    ASSERT_EQ(one_t.size(), kSide * kSide * one.truth.header.bands * sizeof(double));
    EXPECT_EQ(read_bytes(two.folder / "t.img"), one_t) << "1 vs 2 threads";
    EXPECT_EQ(read_bytes(two.folder / "u.img"), one_u) << "1 vs 2 threads";

    // Not vacuous: the scene's three materials are all seen, samples vary by pixel, and the
    // box shadows some of the plate.
    std::array<int, 3> materials{};
    double shadowed = 0.0;
    for (std::size_t p = 0; p < kSide * kSide; ++p) {
        const double m = one.truth.at("Material Index", p % kSide, p / kSide);
        ASSERT_TRUE(m == 0.0 || m == 1.0 || m == 2.0) << m;
        ++materials[static_cast<std::size_t>(m)];
        shadowed += one.truth.at("Shadow Fraction", p % kSide, p / kSide);
    }
    EXPECT_GT(materials[0], 0);
    EXPECT_GT(materials[1], 0);
    EXPECT_GT(materials[2], 0);
    EXPECT_GT(shadowed, 0.0);
    EXPECT_LT(one.report.captures[0].min_samples, one.report.captures[0].max_samples);
}

}  // namespace truth_convergence_test
}  // namespace glint::render
