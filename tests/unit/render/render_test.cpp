// SPDX-License-Identifier: Apache-2.0
// In-process tests of glint-render's capture loop (glint/render/render.h and its internals in
// lib/render/src/render_parts.h) on the tiny simulations of tests/data/render (an 8 × 6
// camera 1000 m above a plate, exo-atmospheric sun, 10 Hz): dry_run() of a frame camera under
// the three <imagefile> schedules and of a pushbroom (captures, pixels, planned file names,
// memory estimate; nothing written); render() of a Lambertian plate giving the analytic
// radiance ρ E cos θs / π in the focal plane's output units, read back from the ENVI file;
// the per-focal-plane state (spectral grid, reference band, units, convergence from
// <convergence> or the options, detection only with a detector model unless radiance-only);
// and the hypersampling mask of a capture seeing an ::IMPORTANT:: instance.
#include "glint/render/render.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "../../../lib/render/src/render_parts.h"
#include "glint/core/datetime.h"
#include "glint/core/error.h"
#include "glint/inputs/load.h"
#include "glint/io/envi.h"
#include "glint/motion/sun.h"
#include "glint/test/temp_dir.h"
#include "render_fixture.h"

namespace glint::render {
namespace render_test {

namespace fs = std::filesystem;
using test_render::kRenderData;
using test_render::load;
using test_render::options_into;
using test_render::read_text;

/// Values the memory estimate counts per pixel for the test cameras: their one channel (the
/// capture is rendered a band of lines at a time, each pixel's spectrum reduced to its
/// channels as it is solved: the bandpass's 6 samples are not held per pixel).
constexpr std::uint64_t kBandsPerPixel = 1;
/// Bytes the memory estimate counts per triangle (render.h).
constexpr std::uint64_t kBytesPerTriangle = 85;

void write_text(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

/// Copies the render fixture files `names` into `dir`.
void copy_fixture(const fs::path& dir, const std::vector<std::string>& names) {
    for (const std::string& name : names) fs::copy_file(kRenderData / name, dir / name);
}

/// one.jsim and what it names but cam.platform.
const std::vector<std::string> kOneJsim{"scene.yaml", "none.atm.yaml", "static.ppd", "three.tasks",
                                        "one.jsim"};

/// Copies the render fixture files `names` into `dir` and cam.platform with `from` replaced
/// by `to`.
void copy_with_camera(const fs::path& dir, const std::vector<std::string>& names,
                      const std::string& from, const std::string& to) {
    copy_fixture(dir, names);
    write_text(dir / "cam.platform", replaced(read_text(kRenderData / "cam.platform"), from, to));
}

std::uint64_t triangles_of(const model::SimulationInputs& in) {
    std::uint64_t n = 0;
    for (const model::Instance& instance : in.scene.instances) {
        n += in.scene.objects[instance.object_index].mesh.triangles.size();
    }
    return n;
}

std::vector<std::string> names_of(const std::vector<fs::path>& files, const fs::path& folder) {
    std::vector<std::string> names;
    for (const fs::path& f : files) {
        EXPECT_EQ(f.parent_path(), folder) << f;
        names.push_back(f.filename().string());
    }
    return names;
}

// ---- dry_run() ----------------------------------------------------------------------------------

struct ScheduleCase {
    const char* schedule;
    std::vector<std::string> files;
};

class PlanSchedules : public ::testing::TestWithParam<ScheduleCase> {};

TEST_P(PlanSchedules, FrameCameraCapturesPixelsFilesAndMemory) {
    // two_tasks.jsim: 3 + 2 captures (10 Hz over 0–0.25 s and 1.0–1.15 s) of 8 × 6 pixels.
    const ScheduleCase& c = GetParam();
    test::TempDir dir;
    copy_with_camera(
        dir.path(), {"scene.yaml", "none.atm.yaml", "static.ppd", "two.tasks", "two_tasks.jsim"},
        "<schedule>simulation</schedule>", std::string("<schedule>") + c.schedule + "</schedule>");
    model::SimulationInputs inputs = load(dir / "two_tasks.jsim");
    const std::uint64_t triangles = triangles_of(inputs);
    const fs::path out = dir / "out";
    const RenderReport report = dry_run(std::move(inputs), options_into(out), Context{});

    ASSERT_EQ(report.captures.size(), 5u);
    for (std::size_t i = 0; i < report.captures.size(); ++i) {
        EXPECT_EQ(report.captures[i].index, i);
        EXPECT_EQ(report.captures[i].pixels, 48u);
        EXPECT_EQ(report.captures[i].rays, 0u) << "dry_run() traces nothing";
    }
    EXPECT_EQ(report.pixels, 5u * 48u);
    EXPECT_EQ(names_of(report.files, out), c.files);
    EXPECT_EQ(report.memory_estimate_bytes,
              triangles * kBytesPerTriangle + 48 * kBandsPerPixel * 8);
    EXPECT_FALSE(fs::exists(out)) << "dry_run() writes nothing";
}

INSTANTIATE_TEST_SUITE_P(
    Render, PlanSchedules,
    ::testing::Values(ScheduleCase{"simulation", {"frame.img"}},
                      ScheduleCase{"task", {"frame-t0000.img", "frame-t0001.img"}},
                      ScheduleCase{"capture",
                                   {"frame-t0000-c0000.img", "frame-t0000-c0001.img",
                                    "frame-t0000-c0002.img", "frame-t0001-c0000.img",
                                    "frame-t0001-c0001.img"}}),
    [](const ::testing::TestParamInfo<ScheduleCase>& test_case) {
        return std::string(test_case.param.schedule);
    });

TEST(Render, PlanTwoPlatformsPrefixesTheirFiles) {
    // two.jsim: the same camera twice, prefixes a_ and b_, 3 captures each (the dry-run CLI
    // case's 6 captures and 288 pixels).
    const test::TempDir dir;
    const fs::path out = dir / "out";
    const RenderReport report =
        dry_run(load(kRenderData / "two.jsim"), options_into(out), Context{});
    EXPECT_EQ(report.captures.size(), 6u);
    EXPECT_EQ(report.pixels, 288u);
    EXPECT_EQ(names_of(report.files, out),
              (std::vector<std::string>{"a_frame.img", "b_frame.img"}));
}

/// A copy of one.jsim whose camera is a pushbroom: one row of 8 pixels, one line per 10 Hz
/// tick, every line appended to one file (<schedule>simulation).
void write_pushbroom(const fs::path& dir) {
    copy_with_camera(dir, kOneJsim, "<yelementcount>6</yelementcount>",
                     "<yelementcount>1</yelementcount>");
}

TEST(Render, PlanPushbroomOneLinePerCapture) {
    test::TempDir dir;
    write_pushbroom(dir.path());
    model::SimulationInputs inputs = load(dir / "one.jsim");
    const std::uint64_t triangles = triangles_of(inputs);
    const fs::path out = dir / "out";
    const RenderReport report = dry_run(std::move(inputs), options_into(out), Context{});
    ASSERT_EQ(report.captures.size(), 3u);  // 0, 0.1, 0.2 s of 0–0.25 s
    for (const CaptureReport& c : report.captures) EXPECT_EQ(c.pixels, 8u);
    EXPECT_EQ(report.pixels, 24u);
    EXPECT_EQ(names_of(report.files, out), std::vector<std::string>{"frame.img"});
    EXPECT_EQ(report.memory_estimate_bytes, triangles * kBytesPerTriangle + 8 * kBandsPerPixel * 8);

    const auto prepared = detail::plan_render(load(dir / "one.jsim"), options_into(out), Context{});
    ASSERT_EQ(prepared.plan->inputs.schedule->sources().size(), 1u);
    const schedule::ClockedFocalPlane& source = prepared.plan->inputs.schedule->sources()[0];
    EXPECT_EQ(source.lines_per_capture(), 1u);
    EXPECT_EQ(source.x_count, 8u);
    EXPECT_EQ(prepared.plan->captures.size(), 3u);
    for (std::size_t i = 0; i < prepared.plan->captures.size(); ++i) {
        EXPECT_EQ(prepared.plan->captures[i].file, out / "frame.img");
        EXPECT_EQ(prepared.plan->captures[i].event_number, i + 1);  // DIRSIG's "Event #N of 3"
        EXPECT_EQ(prepared.plan->captures[i].event_count, 3u);
    }
}

TEST(Render, PushbroomRenderAppendsOneLinePerCapture) {
    test::TempDir dir;
    write_pushbroom(dir.path());
    const fs::path out = dir / "out";
    RenderOptions options = options_into(out);
    options.convergence = radiometry::Convergence{1, 1, 0.0};
    const RenderReport report = render(load(dir / "one.jsim"), options, Context{});
    ASSERT_EQ(report.files, std::vector<fs::path>{out / "frame.img"});
    io::EnviHeader header;
    const std::vector<double> image = io::read_envi_bip(out / "frame.img", &header);
    EXPECT_EQ(header.samples, 8u);
    EXPECT_EQ(header.lines, 3u);
    EXPECT_EQ(header.bands, 1u);
    EXPECT_EQ(header.find_extra("glint captures"), "3");
    EXPECT_EQ(header.find_extra("glint lines per capture"), "1");
    EXPECT_EQ(header.find_extra("glint capture ids"), "{t0c0, t0c1, t0c2}");
    EXPECT_EQ(image.size(), 24u);
}

TEST(Render, ScheduleSelectionOutsideTheRenderedCapturesIsAnInputError) {
    const test::TempDir dir;
    RenderOptions options = options_into(dir / "out");
    options.only_captures = {1, 7};  // one.jsim has captures 0, 1, 2
    try {
        dry_run(load(kRenderData / "one.jsim"), options, Context{});
        FAIL() << "expected an input error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_NE(e.message().find("capture 7 of the --schedule selection"), std::string::npos)
            << e.message();
    }
}

// ---- render() of a Lambertian plate ----------------------------------------------------------

/// Plate reflectance (spectrally flat over the bandpass).
constexpr double kPlateReflectance = 0.4;
/// Relative tolerance per pixel. The only randomness under a black sky is the direction
/// inside the sun disk (radius α = 4.65e-3 rad): its cosine spreads by ≈ α tan θs ≈ 2.2e-3
/// at θs ≈ 25°, so 4 samples per pixel give a standard error below 1.1e-3 / √3 ≈ 6.5e-4.
/// The rendered values also sit ≈ 0.07 % below this expectation on every pixel (a systematic
/// offset, not noise; the e2e Table 1 test allows 0.5 %), so 3e-3 leaves 3.5 standard errors
/// above it. The file holds float64 (<datatype> 5 by default): no rounding.
constexpr double kPlateRelative = 3e-3;

TEST(Render, LambertianPlateGivesTheAnalyticRadianceInTheOutputUnits) {
    test::TempDir dir;
    copy_fixture(dir.path(),
                 {"none.atm.yaml", "static.ppd", "three.tasks", "one.jsim", "cam.platform"});
    write_text(dir / "scene.yaml",
               "origin: {latitude: 43.0, longitude: -77.6, altitude: 150}\n"
               "materials:\n"
               "  - {id: plate, reflectance: {wavelengths: [0.3, 1.0], values: [" +
                   std::to_string(kPlateReflectance) + ", " + std::to_string(kPlateReflectance) +
                   "]}}\n"
                   "objects:\n"
                   "  - {name: ground, primitive: ground_plane, material: plate}\n");
    const fs::path out = dir / "out";
    RenderOptions options = options_into(out);
    options.convergence = radiometry::Convergence{4, 4, 0.0};

    // The expected value from the pieces render() starts from: the sun's position and the
    // ASTM G173 spectrum at the capture's time, the focal plane's grid and output units.
    const auto prepared = detail::plan_render(load(dir / "one.jsim"), options, Context{});
    const detail::RenderInputs& in = prepared.plan->inputs;
    const detail::FocalPlaneState& state = prepared.plan->states.at(0);
    const DateTime reference = in.schedule->plugins()[0].tasks.reference;
    auto expected_at = [&](double t_s) {
        const motion::SunPosition sun = motion::sun_position(add_seconds(reference, t_s), in.frame);
        EXPECT_LT(sun.zenith_deg, 40.0);  // 16:00 UTC near the June solstice at 43° N
        const std::vector<double> e =
            in.light->solar_spectrum().resample(state.grid, sun.distance_au);
        std::vector<double> radiance(e.size());
        for (std::size_t b = 0; b < e.size(); ++b) {
            radiance[b] = kPlateReflectance * e[b] * sun.direction_enu.z / std::numbers::pi;
        }
        std::vector<double> value(state.units.channels());
        state.units.apply(radiance, value);
        return value;
    };

    const RenderReport report = render(load(dir / "one.jsim"), options, Context{});
    ASSERT_EQ(report.files, std::vector<fs::path>{out / "frame.img"});
    ASSERT_EQ(report.captures.size(), 3u);
    for (const CaptureReport& c : report.captures) {
        EXPECT_EQ(c.pixels, 48u);
        EXPECT_EQ(c.min_samples, 4u);
        EXPECT_EQ(c.max_samples, 4u);
        EXPECT_GT(c.rays, 0u);
    }
    io::EnviHeader header;
    const std::vector<double> image = io::read_envi_bip(out / "frame.img", &header);
    EXPECT_EQ(header.data_units, "Watts/(cm2 sr um)");  // watts, cm2, normalized channel
    EXPECT_EQ(header.data_units, state.units.description().data_units);
    ASSERT_EQ(header.samples, 8u);
    ASSERT_EQ(header.lines, 18u);  // 3 captures × 6 rows
    ASSERT_EQ(header.bands, 1u);
    for (std::size_t capture = 0; capture < 3; ++capture) {
        const double expected = expected_at(0.1 * static_cast<double>(capture))[0];
        for (std::size_t i = 0; i < 48; ++i) {
            EXPECT_NEAR(image[capture * 48 + i], expected, kPlateRelative * expected)
                << "capture " << capture << " pixel " << i;
        }
    }
}

// ---- make_focal_plane_state -------------------------------------------------------------------

TEST(Render, FocalPlaneStateOfAFrameCamera) {
    const auto prepared = detail::plan_render(load(kRenderData / "one.jsim"),
                                              options_into("/nonexistent/out"), Context{});
    const detail::FocalPlaneState& state = prepared.plan->states.at(0);
    ASSERT_EQ(state.grid.size(), 6u);               // 0.50–0.60 µm at 0.02 µm
    EXPECT_NEAR(state.grid.min_um(), 0.50, 1e-12);  // µm; exact up to rounding
    EXPECT_NEAR(state.grid.max_um(), 0.60, 1e-12);
    // One spectral state over every band; its reference band is the one nearest the bandpass
    // centre (0.55 µm lies between two).
    ASSERT_EQ(state.spectral_states.size(), 1u);
    const detail::SpectralState& spectral = state.spectral_states[0];
    EXPECT_EQ(spectral.bands.first, 0u);
    EXPECT_EQ(spectral.bands.count, 6u);
    EXPECT_FALSE(spectral.channel.has_value());
    EXPECT_LE(std::fabs(state.grid.wavelength_um(spectral.reference_band) - 0.55), 0.01 + 1e-12);
    EXPECT_EQ(state.camera.columns(), 8u);
    EXPECT_EQ(state.camera.rows(), 6u);
    EXPECT_EQ(state.units.channels(), 1u);
    EXPECT_EQ(state.units.description().data_units, "Watts/(cm2 sr um)");
    EXPECT_FALSE(state.detection.has_value()) << "no detector model";
    EXPECT_EQ(state.convergence.min_samples, kDefaultConvergence.min_samples);
    EXPECT_EQ(state.convergence.max_samples, kDefaultConvergence.max_samples);
    EXPECT_EQ(state.convergence.threshold_w_per_cm2_sr_um,
              kDefaultConvergence.threshold_w_per_cm2_sr_um);
    EXPECT_EQ(state.header.samples, 8u);
    EXPECT_EQ(state.header.bands, 1u);
    EXPECT_EQ(state.header.band_names, std::vector<std::string>{"Green"});
    EXPECT_EQ(state.header.find_extra("glint focal plane"), "Frame");
    EXPECT_EQ(state.header.find_extra("glint instrument"), "Cam");
}

struct ConvergenceCase {
    const char* name;
    const char* element;  ///< <convergence> in the capture method, or "" for none
    std::optional<radiometry::Convergence> option;
    radiometry::Convergence expected;
};

class FocalPlaneConvergence : public ::testing::TestWithParam<ConvergenceCase> {};

TEST_P(FocalPlaneConvergence, FromTheFocalPlaneElseTheOptionsElseTheDefault) {
    const ConvergenceCase& c = GetParam();
    test::TempDir dir;
    copy_with_camera(dir.path(), kOneJsim, "</capturemethod>",
                     std::string(c.element) + "</capturemethod>");
    RenderOptions options = options_into(dir / "out");
    options.convergence = c.option;
    const auto prepared = detail::plan_render(load(dir / "one.jsim"), options, Context{});
    const radiometry::Convergence& got = prepared.plan->states.at(0).convergence;
    EXPECT_EQ(got.min_samples, c.expected.min_samples);
    EXPECT_EQ(got.max_samples, c.expected.max_samples);
    EXPECT_EQ(got.threshold_w_per_cm2_sr_um, c.expected.threshold_w_per_cm2_sr_um);
}

constexpr const char* kConvergence3To7 =
    "<convergence><minimumsamples>3</minimumsamples><maximumsamples>7</maximumsamples>"
    "<threshold>1e-4</threshold></convergence>";

INSTANTIATE_TEST_SUITE_P(
    Render, FocalPlaneConvergence,
    ::testing::Values(ConvergenceCase{"Default", "", std::nullopt, kDefaultConvergence},
                      ConvergenceCase{
                          "Option", "", radiometry::Convergence{2, 5, 1e-3}, {2, 5, 1e-3}},
                      ConvergenceCase{"FocalPlane", kConvergence3To7, std::nullopt, {3, 7, 1e-4}},
                      ConvergenceCase{"FocalPlaneOverOption",
                                      kConvergence3To7,
                                      radiometry::Convergence{2, 5, 1e-3},
                                      {3, 7, 1e-4}}),
    [](const ::testing::TestParamInfo<ConvergenceCase>& test_case) {
        return std::string(test_case.param.name);
    });

TEST(Render, BadConvergenceIsAnInputErrorAtTheElement) {
    // The platform reader already refuses such a <convergence>; the focal plane's state checks
    // it again for a model built otherwise.
    model::SimulationInputs inputs = load(kRenderData / "one.jsim");
    auto platform = std::make_shared<model::Platform>(*inputs.platforms.at(0).platform);
    platform->attachments.at(0).instruments.at(0).focal_planes.at(0).capture_method.convergence =
        model::Convergence{9, 4, 0.0, ErrorContext{"cam.platform", 42, "convergence"}};
    inputs.platforms.at(0).platform = platform;
    try {
        detail::plan_render(std::move(inputs), options_into("/nonexistent/out"), Context{});
        FAIL() << "expected an input error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_EQ(e.message(), "<convergence> needs 1 <= minimumsamples <= maximumsamples");
        EXPECT_EQ(e.context().file, "cam.platform");
        EXPECT_EQ(e.context().line, 42);
    }
}

TEST(Render, DetectionChainOnlyWithADetectorModelUnlessRadianceOnly) {
    RenderOptions options = options_into("/nonexistent/out");
    {
        const auto prepared =
            detail::plan_render(load(kRenderData / "detector.jsim"), options, Context{});
        const detail::FocalPlaneState& state = prepared.plan->states.at(0);
        EXPECT_TRUE(state.detection.has_value());
        // The in-render detection writes counts (glint-detect's header).
        EXPECT_EQ(state.header.data_units, "DN");
        // The photon product detection starts from, whatever the <imagefile> asks (mW/m²).
        EXPECT_EQ(state.units.description().data_units, "Photons/cm2");
    }
    options.radiance_only = true;
    {
        const auto prepared =
            detail::plan_render(load(kRenderData / "detector.jsim"), options, Context{});
        const detail::FocalPlaneState& state = prepared.plan->states.at(0);
        EXPECT_FALSE(state.detection.has_value());
        EXPECT_EQ(state.header.data_type, io::EnviDataType::float64);  // the photon product
        EXPECT_EQ(state.header.data_units, "Photons/cm2");
    }
}

TEST(Render, RendersOnlyEnabledGenericFocalPlanesWithAnImageFile) {
    const auto prepared = detail::plan_render(load(kRenderData / "one.jsim"),
                                              options_into("/nonexistent/out"), Context{});
    schedule::ClockedFocalPlane source = prepared.plan->inputs.schedule->sources()[0];
    std::string why;
    EXPECT_TRUE(detail::renders(source, why));
    EXPECT_EQ(why, "");

    model::FocalPlane disabled = *source.focal_plane;
    disabled.enabled = false;
    source.focal_plane = &disabled;
    EXPECT_FALSE(detail::renders(source, why));
    EXPECT_EQ(why, "focal plane \"Frame\" is disabled");

    model::FocalPlane no_file = *prepared.plan->inputs.schedule->sources()[0].focal_plane;
    no_file.capture_method.image_file.basename.clear();
    source.focal_plane = &no_file;
    EXPECT_FALSE(detail::renders(source, why));
    EXPECT_EQ(why, "focal plane \"Frame\" has no <imagefile>");
}

// ---- hypersampling ----------------------------------------------------------------------------

/// The mask of capture 0 of `simulation`'s only source.
std::vector<std::uint8_t> mask_of(const fs::path& simulation) {
    const RenderOptions options = options_into("/nonexistent/out");
    const auto prepared = detail::plan_render(load(simulation), options, Context{});
    const detail::RenderInputs& in = prepared.plan->inputs;
    const schedule::ClockedFocalPlane& source = in.schedule->sources()[0];
    const scene::GeometryScene geometry =
        in.scene_motion->build(in.scene, detail::build_options(options, 0.0, source.window_s()));
    const sensor::CaptureTiming timing{0.0, source.window_s(), 0.0, source.tdi_stages};
    return sensor::hypersampled_pixels(in.scene, geometry, prepared.plan->states.at(0).camera,
                                       *in.schedule->plugins()[source.plugin].poses,
                                       source.instrument_index, timing);
}

TEST(Render, HypersamplingMarksThePixelsAroundTheImportantBox) {
    // The 0.6 m box (0.5 m tall) under the centre of the 8 × 6 array at 0.2 m per pixel spans
    // pixel columns 2.5–5.5 and rows 1.5–4.5; with one pixel of margin columns 1–6 and rows
    // 0–5 are marked: 36 of 48 (the hypersampling CLI case).
    const std::vector<std::uint8_t> mask = mask_of(kRenderData / "hyper.jsim");
    ASSERT_EQ(mask.size(), 48u);
    for (std::size_t row = 0; row < 6; ++row) {
        for (std::size_t column = 0; column < 8; ++column) {
            EXPECT_EQ(mask[row * 8 + column], (column >= 1 && column <= 6) ? 1 : 0)
                << "column " << column << " row " << row;
        }
    }
}

TEST(Render, NoImportantInstanceNoHypersamplingMask) {
    EXPECT_TRUE(mask_of(kRenderData / "one.jsim").empty());
}

TEST(Render, TdiHypersamplingMarksColumns) {
    // tdi_hyper.jsim: the same box under a 6-stage TDI array: one entry per column.
    const std::vector<std::uint8_t> mask = mask_of(kRenderData / "tdi_hyper.jsim");
    ASSERT_EQ(mask.size(), 8u);
    EXPECT_EQ(std::count(mask.begin(), mask.end(), 1), 6);
    EXPECT_EQ(mask.front(), 0);
    EXPECT_EQ(mask.back(), 0);
}

TEST(Render, HypersampledPixelsTakeTheMultipliedSampleCount) {
    // hyper.jsim (multiplier 8) at a fixed 2 samples: 36 pixels take 16, 12 take 2, mean
    // (36 × 16 + 12 × 2) / 48 = 12.5.
    const test::TempDir dir;
    RenderOptions options = options_into(dir / "out");
    options.convergence = radiometry::Convergence{2, 2, 0.0};
    options.only_captures = {0};
    const RenderReport report = render(load(kRenderData / "hyper.jsim"), options, Context{});
    ASSERT_EQ(report.captures.size(), 1u);
    EXPECT_EQ(report.captures[0].min_samples, 2u);
    EXPECT_EQ(report.captures[0].max_samples, 16u);
    EXPECT_DOUBLE_EQ(report.captures[0].mean_samples, 12.5);
}

}  // namespace render_test
}  // namespace glint::render
