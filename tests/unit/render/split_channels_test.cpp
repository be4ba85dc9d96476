// SPDX-License-Identifier: Apache-2.0
// Split channels ("Split Channels into States" in the DIRSIG5 BasicPlatform manual): with
// split_channels each channel of a focal plane is its own spectral state — the bands its
// response covers, its own random streams, its own convergence — instead of one state for the
// focal plane. The states are built from the channels' supports; the option and the .jsim
// entry decide (the entry first); and, as glint models no dispersion, a split render is
// statistically equal to the joint one: the same expectation, different (independent) draws.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../../../lib/render/src/render_parts.h"
#include "glint/inputs/load.h"
#include "glint/io/envi.h"
#include "glint/render/render.h"
#include "glint/test/temp_dir.h"
#include "render_fixture.h"

namespace glint::render {
namespace split_channels_test {

namespace fs = std::filesystem;
using test_render::kRenderData;
using test_render::load;
using test_render::options_into;
using test_render::read_text;

/// cam.platform's one channel replaced by three tophats on its 0.50–0.60 µm grid at 0.02 µm
/// (bands 0.50, 0.52, …, 0.60), their edges between grid points: Blue covers bands 0–2, Mid
/// 2–3 and Red 3–5.
constexpr const char* kThreeChannels = R"(<channellist>
              <channel name="Blue" shape="tophat"><center>0.52</center><width>0.05</width></channel>
              <channel name="Mid" shape="tophat"><center>0.55</center><width>0.03</width></channel>
              <channel name="Red" shape="tophat"><center>0.58</center><width>0.05</width></channel>
            </channellist>)";

/// one.jsim's files in `dir`, the camera with three channels; `entry` is added to the
/// BasicPlatform entry's inputs (e.g. `"split_channels": true`) when not empty.
void write_simulation(const fs::path& dir, const std::string& entry = {}) {
    for (const char* name : {"scene.yaml", "none.atm.yaml", "static.ppd", "three.tasks"}) {
        fs::copy_file(kRenderData / name, dir / name);
    }
    std::string platform = read_text(kRenderData / "cam.platform");
    const std::size_t begin = platform.find("<channellist>");
    const std::size_t end = platform.find("</channellist>") + std::string("</channellist>").size();
    ASSERT_NE(begin, std::string::npos);
    platform.replace(begin, end - begin, kThreeChannels);
    std::ofstream(dir / "cam.platform") << platform;
    std::string jsim = read_text(kRenderData / "one.jsim");
    if (!entry.empty()) {
        const std::string tasks = "\"tasks_filename\": \"three.tasks\"";
        jsim.replace(jsim.find(tasks), tasks.size(), tasks + ", " + entry);
    }
    std::ofstream(dir / "one.jsim") << jsim;
}

std::vector<detail::SpectralState> states_of(const fs::path& jsim, bool option) {
    RenderOptions options = options_into(jsim.parent_path() / "out");
    options.split_channels = option;
    const auto prepared = detail::plan_render(load(jsim), options, Context{});
    return prepared.plan->states.at(0).spectral_states;
}

TEST(SplitChannels, OneStatePerChannelOverTheBandsItsResponseCovers) {
    test::TempDir dir;
    write_simulation(dir.path());
    const std::vector<detail::SpectralState> joint = states_of(dir / "one.jsim", false);
    ASSERT_EQ(joint.size(), 1u);
    EXPECT_EQ(joint[0].bands.first, 0u);
    EXPECT_EQ(joint[0].bands.count, 6u);
    EXPECT_FALSE(joint[0].channel.has_value());

    const std::vector<detail::SpectralState> split = states_of(dir / "one.jsim", true);
    ASSERT_EQ(split.size(), 3u);
    const std::size_t first[] = {0, 2, 3};
    const std::size_t count[] = {3, 2, 3};
    // The band nearest each state's centre (0.52, 0.55 → 0.54 on a tie, 0.58 µm).
    const std::size_t reference[] = {1, 2, 4};
    for (std::size_t c = 0; c < 3; ++c) {
        EXPECT_EQ(split[c].channel, std::optional<std::size_t>(c));
        EXPECT_EQ(split[c].bands.first, first[c]) << c;
        EXPECT_EQ(split[c].bands.count, count[c]) << c;
        EXPECT_EQ(split[c].reference_band, reference[c]) << c;
    }
}

TEST(SplitChannels, TheJsimEntryTakesPrecedenceOverTheOption) {
    for (const bool entry : {false, true}) {
        for (const bool option : {false, true}) {
            test::TempDir dir;
            write_simulation(dir.path(),
                             std::string("\"split_channels\": ") + (entry ? "true" : "false"));
            EXPECT_EQ(states_of(dir / "one.jsim", option).size(), entry ? 3u : 1u)
                << "entry " << entry << " option " << option;
        }
    }
    test::TempDir dir;
    write_simulation(dir.path());  // no entry: the option decides
    EXPECT_EQ(states_of(dir / "one.jsim", true).size(), 3u);
}

/// Renders capture 0 of the three-channel camera (8 × 6 pixels, 3 channels, float64) with
/// `samples` samples per pixel, split or not.
std::vector<double> render_image(const fs::path& dir, bool split, std::uint64_t samples,
                                 std::uint64_t seed, io::EnviHeader* header = nullptr) {
    const fs::path out = dir / ((split ? "split-" : "joint-") + std::to_string(seed));
    RenderOptions options = options_into(out);
    options.split_channels = split;
    options.schedule.seed = seed;
    options.convergence = radiometry::Convergence{samples, samples, 0.0};
    options.only_captures = {0};
    render(load(dir / "one.jsim"), options, Context{});
    return io::read_envi_bip(out / "frame.img", header);
}

TEST(SplitChannels, ASplitRenderIsStatisticallyEqualToTheJointOne) {
    // The grey plate with a white box: the box's edges cover pixels partly, it shadows the
    // plate and light bounces between them, so pixels vary from sample to sample. Split and
    // joint draw independent numbers; per channel, the mean over the 48 pixels of (split −
    // joint) is zero in expectation, and its standard error comes from the spread of the
    // pixel differences (each pixel's two estimates are independent). A 4σ bound fails with
    // probability 6e-5 for a normal mean, and the seeds are fixed.
    test::TempDir dir;
    write_simulation(dir.path());
    constexpr std::uint64_t kSamples = 128;
    io::EnviHeader joint_header;
    io::EnviHeader split_header;
    const std::vector<double> joint = render_image(dir.path(), false, kSamples, 5, &joint_header);
    const std::vector<double> split = render_image(dir.path(), true, kSamples, 5, &split_header);
    EXPECT_EQ(joint_header.find_extra("glint split channels"), "false");
    EXPECT_EQ(split_header.find_extra("glint split channels"), "true");
    ASSERT_EQ(joint.size(), 48u * 3u);
    ASSERT_EQ(split.size(), joint.size());
    EXPECT_NE(split, joint) << "the states draw their own numbers";

    for (std::size_t c = 0; c < 3; ++c) {
        double sum = 0.0;
        double sum_sq = 0.0;
        std::size_t differing = 0;
        for (std::size_t p = 0; p < 48; ++p) {
            const double d = split[p * 3 + c] - joint[p * 3 + c];
            sum += d;
            sum_sq += d * d;
            // Pixels that see the open plate in the sun are the same up to the sun disk's
            // draw (relative spread ~1e-3); the others vary.
            if (std::fabs(d) > 1e-2 * joint[p * 3 + c]) ++differing;
        }
        const double mean = sum / 48.0;
        const double variance = (sum_sq - 48.0 * mean * mean) / 47.0;
        const double standard_error = std::sqrt(variance / 48.0);
        EXPECT_GT(differing, 2u) << "channel " << c << ": too few noisy pixels to test";
        EXPECT_LE(std::fabs(mean), 4.0 * standard_error) << "channel " << c;
    }
}

TEST(SplitChannels, ASplitRenderIsTheSameForAnyThreadCount) {
    test::TempDir dir;
    write_simulation(dir.path(), "\"split_channels\": true");
    std::vector<std::vector<double>> images;
    for (const unsigned threads : {1u, 2u}) {
        const fs::path out = dir / ("t" + std::to_string(threads));
        RenderOptions options = options_into(out);
        options.convergence = radiometry::Convergence{4, 4, 0.0};
        options.only_captures = {0};
        Context context;
        context.threads = threads;
        render(load(dir / "one.jsim"), options, context);
        images.push_back(io::read_envi_bip(out / "frame.img", nullptr));
    }
    EXPECT_EQ(images[0], images[1]);
}

}  // namespace split_channels_test
}  // namespace glint::render
