// SPDX-License-Identifier: Apache-2.0
// glint-demosaic's entry point in-process: ENVI in and out (values, type, header keys), image
// outputs with the stretch, option checks, and no file left behind by any failure.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "glint/app_demosaic/demosaic_tool.h"
#include "glint/core/error.h"
#include "glint/io/envi.h"
#include "glint/io/image.h"
#include "glint/test/temp_dir.h"

namespace glint::app_demosaic {
namespace demosaic_file_test {

using glint::test::TempDir;
namespace dm = glint::demosaic;

/// Writes a one-band (or `bands`-band) uint16 ENVI file of pseudo-random values.
dm::Plane write_mosaic(const std::filesystem::path& path, std::size_t w, std::size_t h,
                       std::size_t bands = 1, const std::string& cfa_pattern = {},
                       const std::string& cfa_phase = {}) {
    io::EnviHeader header;
    if (!cfa_pattern.empty()) header.set_extra("glint cfa pattern", cfa_pattern);
    if (!cfa_phase.empty()) header.set_extra("glint cfa phase", cfa_phase);
    header.samples = w;
    header.lines = h;
    header.bands = bands;
    header.data_type = io::EnviDataType::uint16;
    header.data_units = "DN";
    io::EnviWriter writer(path, header);
    dm::Plane plane{w, h, {}};
    for (std::size_t y = 0; y < h; ++y) {
        std::vector<double> line;
        for (std::size_t x = 0; x < w; ++x) {
            const double v = static_cast<double>((x * 7919 + y * 104729) % 4096);
            plane.values.push_back(v);
            for (std::size_t b = 0; b < bands; ++b) line.push_back(v);
        }
        writer.write_line(line);
    }
    writer.commit();
    return plane;
}

Options options(const std::filesystem::path& input, const std::filesystem::path& output) {
    Options o;
    o.input = input;
    o.output = output;
    return o;
}

Error run_expecting_error(const Options& options) {
    Context ctx;
    try {
        demosaic_file(options, ctx);
    } catch (const Error& e) {
        return e;
    }
    ADD_FAILURE() << "no error";
    return internal_error("no error");
}

TEST(RunDemosaic, EnviOutputHoldsTheDemosaicedValuesAndProvenance) {
    TempDir dir;
    const dm::Plane plane = write_mosaic(dir / "in.img", 9, 7);
    Options o;
    o.input = dir / "in.img";
    o.output = dir / "out.img";
    o.phase = dm::BayerPhase::gbrg;
    o.method = dm::DemosaicMethod::mhc;
    Context ctx;
    ctx.arguments = {"glint-demosaic", "in.img", "out.img"};  // as the runner records them
    const Result result = demosaic_file(o, ctx);
    EXPECT_EQ(result.kind, io::OutputKind::envi);
    EXPECT_EQ(result.stored_type, "uint16");
    EXPECT_EQ(result.used.method, dm::DemosaicMethod::mhc);

    io::EnviHeader h;
    const std::vector<double> values = io::read_envi_bip(dir / "out.img", &h);
    EXPECT_EQ(h.bands, 3u);
    EXPECT_EQ(h.data_type, io::EnviDataType::uint16);
    EXPECT_EQ(h.band_names, (std::vector<std::string>{"R", "G", "B"}));
    EXPECT_EQ(h.data_units, "DN");
    EXPECT_EQ(h.find_extra("glint tool"), "glint-demosaic");
    EXPECT_EQ(h.find_extra("glint cfa pattern"), "bayer");
    EXPECT_EQ(h.find_extra("glint cfa phase"), "gbrg");
    EXPECT_EQ(h.find_extra("glint demosaic method"), "mhc");
    EXPECT_EQ(h.find_extra("glint source"), (dir / "in.img").string());
    EXPECT_EQ(h.find_extra("glint command line"), "glint-demosaic in.img out.img");

    const dm::RgbImage expected = dm::demosaic_bayer_mhc(plane, dm::BayerPhase::gbrg);
    ASSERT_EQ(values.size(), expected.rgb.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        EXPECT_EQ(values[i], std::clamp(std::round(expected.rgb[i]), 0.0, 65535.0)) << i;
    }
}

TEST(RunDemosaic, Float32KeepsMhcOvershoot) {
    TempDir dir;
    const dm::Plane plane = write_mosaic(dir / "in.img", 12, 10);
    Options o = options(dir / "in.img", dir / "out.img");
    o.method = dm::DemosaicMethod::mhc;
    o.data_type = io::EnviDataType::float32;
    Context ctx;
    demosaic_file(o, ctx);
    const std::vector<double> values = io::read_envi_bip(dir / "out.img", nullptr);
    const dm::RgbImage expected = dm::demosaic_bayer_mhc(plane, dm::BayerPhase::rggb);
    for (std::size_t i = 0; i < values.size(); ++i) {
        EXPECT_EQ(values[i], static_cast<double>(static_cast<float>(expected.rgb[i])));
    }
}

TEST(RunDemosaic, PngGetsAMinMaxStretchOverTheThreeChannels) {
    TempDir dir;
    const dm::Plane plane = write_mosaic(dir / "in.img", 16, 12);
    Options o = options(dir / "in.img", dir / "out.png");
    Context ctx;
    const Result result = demosaic_file(o, ctx);
    ASSERT_TRUE(result.limits);
    const dm::RgbImage rgb = dm::demosaic_bayer_bilinear(plane, dm::BayerPhase::rggb);
    EXPECT_EQ(result.limits->low, *std::min_element(rgb.rgb.begin(), rgb.rgb.end()));
    EXPECT_EQ(result.limits->high, *std::max_element(rgb.rgb.begin(), rgb.rgb.end()));
    const io::Image image = io::read_image(dir / "out.png");
    EXPECT_EQ(image.info.channels, 3u);
    EXPECT_EQ(image.info.channel_names, (std::vector<std::string>{"R", "G", "B"}));
    for (std::size_t i = 0; i < rgb.rgb.size(); ++i) {
        const double s =
            (rgb.rgb[i] - result.limits->low) / (result.limits->high - result.limits->low);
        EXPECT_EQ(image.pixels[i], std::round(255.0 * s)) << i;
    }
}

TEST(RunDemosaic, ExrKeepsTheValuesUnlessAStretchIsAsked) {
    TempDir dir;
    const dm::Plane plane = write_mosaic(dir / "in.img", 8, 8);
    Options o = options(dir / "in.img", dir / "out.exr");
    o.pattern = dm::CfaPattern::truesense;
    Context ctx;
    const Result result = demosaic_file(o, ctx);
    EXPECT_FALSE(result.limits);
    EXPECT_EQ(result.used.method, dm::DemosaicMethod::pan_guided);
    const io::Image image = io::read_image(dir / "out.exr");
    const dm::RgbImage rgb = dm::demosaic_truesense(plane);
    for (std::size_t i = 0; i < rgb.rgb.size(); ++i) {
        EXPECT_EQ(image.pixels[i], static_cast<double>(static_cast<float>(rgb.rgb[i])));
    }
}

TEST(RunDemosaic, PatternAndPhaseDefaultToWhatTheInputHeaderRecords) {
    TempDir dir;
    write_mosaic(dir / "ts.img", 8, 8, 1, "truesense");
    write_mosaic(dir / "bayer.img", 8, 8, 1, "bayer", "bggr");
    Context ctx;
    Result r = demosaic_file(options(dir / "ts.img", dir / "ts_rgb.img"), ctx);
    EXPECT_EQ(r.used.pattern, dm::CfaPattern::truesense);
    EXPECT_EQ(r.used.method, dm::DemosaicMethod::pan_guided);
    r = demosaic_file(options(dir / "bayer.img", dir / "bayer_rgb.img"), ctx);
    EXPECT_EQ(r.used.pattern, dm::CfaPattern::bayer);
    EXPECT_EQ(r.used.phase, dm::BayerPhase::bggr);
    io::EnviHeader h;
    io::read_envi_bip(dir / "bayer_rgb.img", &h);
    EXPECT_EQ(h.find_extra("glint cfa phase"), "bggr");

    // Given options win (with a warning); a phase cannot apply to a recorded TrueSense.
    std::vector<std::string> warnings;
    ctx.log =
        Log([&](LogLevel, const std::string& m) { warnings.push_back(m); }, LogLevel::warning);
    Options o = options(dir / "bayer.img", dir / "grbg.img");
    o.phase = dm::BayerPhase::grbg;
    r = demosaic_file(o, ctx);
    EXPECT_EQ(r.used.phase, dm::BayerPhase::grbg);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("records the Bayer phase bggr; using grbg as asked"),
              std::string::npos);
    o = options(dir / "ts.img", dir / "out.png");
    o.phase = dm::BayerPhase::rggb;
    const Error e = run_expecting_error(o);
    EXPECT_EQ(e.category(), ErrorCategory::usage);
    EXPECT_NE(e.message().find("not to truesense (" + (dir / "ts.img").string() + " records it)"),
              std::string::npos)
        << e.message();
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

TEST(RunDemosaic, RefusesContradictoryOptions) {
    TempDir dir;
    write_mosaic(dir / "in.img", 8, 8);
    Options o = options(dir / "in.img", dir / "out.img");
    o.percent = 1.0;
    EXPECT_EQ(run_expecting_error(o).category(), ErrorCategory::usage);
    o = options(dir / "in.img", dir / "out.png");
    o.data_type = io::EnviDataType::float32;
    EXPECT_EQ(run_expecting_error(o).category(), ErrorCategory::usage);
    o = options(dir / "in.img", dir / "out.png");
    o.pattern = dm::CfaPattern::truesense;
    o.phase = dm::BayerPhase::rggb;
    EXPECT_EQ(run_expecting_error(o).category(), ErrorCategory::usage);
    o = options(dir / "in.img", dir / "out.png");
    o.min = 1.0;
    EXPECT_EQ(run_expecting_error(o).category(), ErrorCategory::usage);
    o = options(dir / "in.img", dir / "out.jpg");
    o.raw = true;
    o.gamma = 2.2;
    EXPECT_EQ(run_expecting_error(o).category(), ErrorCategory::usage);
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"in.img", "in.img.hdr"}));
}

TEST(RunDemosaic, BadInputsLeaveNoOutput) {
    TempDir dir;
    write_mosaic(dir / "cube.img", 8, 8, 2);
    write_mosaic(dir / "small.img", 8, 3);
    Options o = options(dir / "cube.img", dir / "out.png");
    Error e = run_expecting_error(o);
    EXPECT_EQ(e.category(), ErrorCategory::input);
    EXPECT_EQ(e.context().file, (dir / "cube.img").string());
    EXPECT_NE(e.message().find("has one band, this file has 2"), std::string::npos);

    o = options(dir / "small.img", dir / "out.img");
    o.pattern = dm::CfaPattern::truesense;
    e = run_expecting_error(o);
    EXPECT_EQ(e.category(), ErrorCategory::input);
    EXPECT_EQ(e.context().file, (dir / "small.img").string());

    o = options(dir / "small.img", dir / "small.img.hdr");
    o.format = "envi";
    EXPECT_EQ(run_expecting_error(o).category(), ErrorCategory::usage);
    EXPECT_EQ(dir.entries(),
              (std::vector<std::string>{"cube.img", "cube.img.hdr", "small.img", "small.img.hdr"}));
}

TEST(RunDemosaic, CancelledRunLeavesNoOutput) {
    TempDir dir;
    write_mosaic(dir / "in.img", 8, 8);
    Options o = options(dir / "in.img", dir / "out.img");
    Context ctx;
    ctx.cancel.cancel();
    try {
        demosaic_file(o, ctx);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::cancelled);
    }
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"in.img", "in.img.hdr"}));
}

TEST(RunDemosaic, NamesAreParsedOrRefusedWithTheChoices) {
    EXPECT_EQ(parse_pattern("TrueSense"), dm::CfaPattern::truesense);
    EXPECT_EQ(parse_phase("grbg"), dm::BayerPhase::grbg);
    EXPECT_EQ(parse_method("pan-guided"), dm::DemosaicMethod::pan_guided);
    try {
        parse_method("vng");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::usage);
        EXPECT_NE(e.message().find("expected bilinear or mhc for bayer"), std::string::npos);
    }
}

}  // namespace demosaic_file_test
}  // namespace glint::app_demosaic
