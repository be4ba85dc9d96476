// SPDX-License-Identifier: Apache-2.0
// Point sources through glint-render's capture loop: the street fixture at night
// (tests/data/dirsig_scene/lights: a lamp post, a parked car's headlight placed through its
// bundle, a driving car's headlight riding its motion) gives the sources their positions at
// the capture's time and their material's intensity on the focal plane's grid; and a grey
// plate under one lamp at night renders, pixel by pixel, the analytic radiance
// ρ I cos θ / (π r²) averaged over the pixel's footprint.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "../../../lib/render/src/render_parts.h"
#include "glint/atmosphere/atmosphere.h"
#include "glint/atmosphere/lunar.h"
#include "glint/core/error.h"
#include "glint/io/envi.h"
#include "glint/motion/moon.h"
#include "glint/motion/rigid.h"
#include "glint/motion/sun.h"
#include "glint/render/render.h"
#include "glint/test/temp_dir.h"
#include "render_fixture.h"

namespace glint::render {
namespace point_source_render_test {

namespace fs = std::filesystem;
using test_render::kRenderData;
using test_render::load;
using test_render::options_into;

const fs::path kLights = fs::path(GLINT_TEST_DATA_DIR) / "dirsig_scene" / "lights";

void write_text(const fs::path& path, const std::string& text) {
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
}

void expect_at(const radiometry::PointLights& lights, std::size_t i, motion::Vec3 expected_m) {
    // Positions come from a few exact products and sums of short decimals: 1e-12 m.
    EXPECT_NEAR(lights.position_m(i).x, expected_m.x, 1e-12) << "source " << i;
    EXPECT_NEAR(lights.position_m(i).y, expected_m.y, 1e-12) << "source " << i;
    EXPECT_NEAR(lights.position_m(i).z, expected_m.z, 1e-12) << "source " << i;
}

TEST(PointSources, StreetSourcesArePlacedAtTheCaptureTimeWithTheirMaterialsIntensity) {
    const auto prepared =
        detail::plan_render(load(kLights / "lights.jsim"), options_into(fs::path("unused")), {});
    const detail::RenderInputs& in = prepared.plan->inputs;
    ASSERT_EQ(in.scene.point_sources.size(), 3u);
    EXPECT_EQ(in.scene.point_sources[0].name, "lamp");
    EXPECT_EQ(in.scene.point_sources[1].name, "headlight");
    EXPECT_FALSE(in.scene.point_sources[1].dynamic());
    EXPECT_TRUE(in.scene.point_sources[2].dynamic());
    const SpectralGrid& grid = prepared.plan->states.at(0).grid;  // 0.50–0.60 µm at 0.02 µm

    const radiometry::PointLights at0 = in.light->point_lights_at(in.scene, grid, 0.0);
    ASSERT_EQ(at0.size(), 3u);
    expect_at(at0, 0, {0.4, 0.3, 0.5});
    // The parked car: headlight (0, 0.2, 0.05) in the bundle, turned 90° about z, moved to
    // (−0.4, −0.3, 0).
    expect_at(at0, 1, {-0.6, -0.3, 0.05});
    // The driving car starts at (−0.6, 0.3, 0) heading east at 2 m/s; its +y (forward) is
    // along the velocity.
    expect_at(at0, 2, {-0.4, 0.3, 0.05});
    expect_at(in.light->point_lights_at(in.scene, grid, 0.5), 2, {0.6, 0.3, 0.05});

    // The lamp's flat 2 W/(sr µm); the headlamp's curve interpolated (0.45 → 0.015,
    // 0.55 → 0.025, 0.70 → 0.03).
    for (std::size_t b = 0; b < grid.size(); ++b) {
        const double wavelength_um = grid.wavelength_um(b);
        EXPECT_DOUBLE_EQ(at0.intensity_w_per_sr_um(0)[b], 2.0) << wavelength_um;
        const double headlamp = wavelength_um <= 0.55
                                    ? 0.015 + 0.1 * (wavelength_um - 0.45)
                                    : 0.025 + (wavelength_um - 0.55) * 0.005 / 0.15;
        EXPECT_NEAR(at0.intensity_w_per_sr_um(1)[b], headlamp, 1e-12) << wavelength_um;
        EXPECT_NEAR(at0.intensity_w_per_sr_um(2)[b], headlamp, 1e-12) << wavelength_um;
    }
}

/// A DIRSIG scene folder in `dir`: a grey ground plane ρ = `rho` and one lamp of constant
/// intensity `intensity` at `lamp_m`, rendered by the render fixture's camera 1000 m up at
/// night (the sun well below the horizon) with no atmosphere (or `atmosphere`).
void write_lamp_scene(const fs::path& dir, double rho, double intensity, motion::Vec3 lamp_m,
                      const std::string& when = "2020-06-21T00:00:00.0000-04:00",
                      const fs::path& atmosphere = kRenderData / "none.atm.yaml") {
    write_text(dir / "plate.scene",
               "<classicscene>\n"
               "  <sceneorigin><location frame=\"geodetic\"><latitude>43.0</latitude>"
               "<longitude>-77.6</longitude><altitude>150.0</altitude></location></sceneorigin>\n"
               "  <geometrylist><geometrylistinclude>plate.glist</geometrylistinclude>"
               "</geometrylist>\n"
               "  <matfilename>plate.mat</matfilename>\n"
               "</classicscene>\n");
    write_text(dir / "plate.mat",
               "MATERIAL_ENTRY {\n ID = grey\n SURFACE_PROPERTIES {\n"
               "  REFLECTANCE_PROP { TXT_FILENAME = grey.txt }\n }\n}\n"
               "MATERIAL_ENTRY {\n ID = lamp\n OPTICAL_DESCRIPTION = SOURCE\n"
               " INTENSITY_FILENAME = lamp.txt\n}\n");
    write_text(dir / "grey.txt",
               "0.3 " + std::to_string(rho) + "\n1.0 " + std::to_string(rho) + "\n");
    write_text(dir / "lamp.txt",
               "0.3 " + std::to_string(intensity) + "\n1.0 " + std::to_string(intensity) + "\n");
    write_text(dir / "plate.glist",
               "<geometrylist>\n"
               " <object name=\"Plate\"><basegeometry><groundplane><matid>grey</matid>"
               "</groundplane></basegeometry><staticinstance/></object>\n"
               " <object name=\"Lamp\"><basesource><pointsource matid=\"lamp\"/></basesource>\n"
               "  <staticinstance><translation><point><x>" +
                   std::to_string(lamp_m.x) + "</x><y>" + std::to_string(lamp_m.y) + "</y><z>" +
                   std::to_string(lamp_m.z) +
                   "</z></point></translation></staticinstance></object>\n"
                   "</geometrylist>\n");
    write_text(
        dir / "night.tasks",
        "<tasklist><reference><datetime type=\"absolute\">" + when +
            "</datetime></reference><task><start><datetime type=\"relative\">0</datetime>"
            "</start><stop><datetime type=\"relative\">0</datetime></stop></task></tasklist>\n");
    write_text(dir / "plate.jsim",
               "[{\"scene_list\": [{\"inputs\": \"plate.scene\"}], \"plugin_list\": [\n"
               " {\"name\": \"BasicAtmosphere\", \"inputs\": {\"atmosphere_filename\": \"" +
                   atmosphere.string() +
                   "\"}},\n"
                   " {\"name\": \"BasicPlatform\", \"inputs\": {\"platform_filename\": \"" +
                   (kRenderData / "cam.platform").string() + "\", \"motion_filename\": \"" +
                   (kRenderData / "static.ppd").string() +
                   "\", \"tasks_filename\": \"night.tasks\"}}]}]\n");
}

/// The solid angle of pixel (column, row)'s element, from the pinhole camera's geometry alone:
/// s_x s_y cos³θ / f², θ the angle of its centre from the boresight (the element is 2e-4 rad
/// wide: the formula's error is of that order squared).
double pixel_solid_angle_sr(const sensor::CameraModel& camera, std::size_t column,
                            std::size_t row) {
    const motion::Vec3 d =
        motion::normalized(camera.direction(camera.focal_plane_point(column, row, 0.5, 0.5)));
    const double cos_theta = -d.z;
    const double f = camera.focal_length_m();
    return camera.element_size_m()[0] * camera.element_size_m()[1] * cos_theta * cos_theta *
           cos_theta / (f * f);
}

/// The pixel (column, row) whose footprint holds `point_m` for the camera at `pose`.
std::array<std::size_t, 2> pixel_of(const sensor::CameraModel& camera, const motion::Rigid& pose,
                                    const motion::Vec3& point_m) {
    const auto at = camera.project(
        motion::apply_direction(motion::inverse(pose), point_m - pose.translation_m));
    EXPECT_TRUE(at.has_value());
    return {static_cast<std::size_t>((*at)[0]), static_cast<std::size_t>((*at)[1])};
}

TEST(PointSources, PlateUnderALampFollowsIntensityCosineOverDistanceSquared) {
    constexpr double kRho = 0.25;
    constexpr double kIntensity = 40.0;  // W/(sr µm)
    const motion::Vec3 lamp_m{0.3, -0.2, 3.0};
    test::TempDir dir;
    write_lamp_scene(dir.path(), kRho, kIntensity, lamp_m);
    const fs::path out = dir / "out";
    RenderOptions options = options_into(out);
    constexpr std::uint64_t kSamples = 64;
    options.convergence = radiometry::Convergence{kSamples, kSamples, 0.0};

    // The expected pixel value: ρ I cos θ / (π r²) on the ground (z = 0) averaged over the
    // pixel's footprint by a 32 × 32 midpoint rule (samples are spread uniformly over each
    // pixel), in W/(cm² sr µm) (r in m: 10⁴ cm² per m²). The tophat channel is normalized and
    // the spectrum flat, so the channel value is the radiance itself.
    const auto prepared = detail::plan_render(load(dir / "plate.jsim"), options, {});
    const detail::RenderInputs& in = prepared.plan->inputs;
    const detail::FocalPlaneState& state = prepared.plan->states.at(0);
    const motion::Rigid pose = in.schedule->plugins()[0].poses->instrument_to_scene(0, 0.0);
    auto radiance_at = [&](const motion::Vec3& ground_m) {
        const motion::Vec3 to_lamp = lamp_m - ground_m;
        const double r2_m2 = motion::dot(to_lamp, to_lamp);
        const double cos_theta = to_lamp.z / std::sqrt(r2_m2);
        return kRho * kIntensity * cos_theta / (std::numbers::pi * r2_m2 * 1e4);
    };
    const std::size_t columns = state.camera.columns();
    const std::size_t rows = state.camera.rows();
    std::vector<double> expected(columns * rows, 0.0);
    constexpr int kGrid = 32;
    for (std::size_t row = 0; row < rows; ++row) {
        for (std::size_t column = 0; column < columns; ++column) {
            double sum = 0.0;
            for (int a = 0; a < kGrid; ++a) {
                for (int b = 0; b < kGrid; ++b) {
                    const double u = (a + 0.5) / kGrid;
                    const double v = (b + 0.5) / kGrid;
                    const motion::Vec3 d = motion::apply_direction(
                        pose,
                        state.camera.direction(state.camera.focal_plane_point(column, row, u, v)));
                    const double s = -pose.translation_m.z / d.z;
                    sum += radiance_at(pose.translation_m + d * s);
                }
            }
            expected[row * columns + column] = sum / (kGrid * kGrid);
        }
    }

    // The camera also sees the lamp itself, in the pixel whose footprint holds it: its
    // irradiance at the aperture I / r² over the pixel's solid angle.
    const auto [lamp_column, lamp_row] = pixel_of(state.camera, pose, lamp_m);
    const std::size_t lamp_pixel = lamp_row * columns + lamp_column;
    const double plate_at_lamp = expected[lamp_pixel];
    const motion::Vec3 to_lamp = lamp_m - pose.translation_m;
    const double range2_m2 = motion::dot(to_lamp, to_lamp);
    const double omega_sr = pixel_solid_angle_sr(state.camera, lamp_column, lamp_row);
    expected[lamp_pixel] += kIntensity / (range2_m2 * 1e4) / omega_sr;

    const RenderReport report = render(load(dir / "plate.jsim"), options, Context{});
    ASSERT_EQ(report.files, std::vector<fs::path>{out / "frame.img"});
    io::EnviHeader header;
    const std::vector<double> image = io::read_envi_bip(out / "frame.img", &header);
    ASSERT_EQ(image.size(), expected.size());
    // The lamp's pixel: recorded radiance × solid angle × range² = I within 1 % (the plate's
    // share of that pixel, 3e-5 of it, taken off first).
    EXPECT_NEAR((image[lamp_pixel] - plate_at_lamp) * omega_sr * range2_m2 * 1e4, kIntensity,
                0.01 * kIntensity);
    double lowest = plate_at_lamp;
    double highest = plate_at_lamp;
    for (std::size_t i = 0; i < image.size(); ++i) {
        if (i != lamp_pixel) {
            lowest = std::min(lowest, expected[i]);
            highest = std::max(highest, expected[i]);
        }
        // 1 %: the footprint of a pixel (0.2 m at 3 m from the lamp) spans a few per cent of
        // cos θ / r², and 64 samples leave a standard error of about 0.3 % of it.
        EXPECT_NEAR(image[i], expected[i], 0.01 * expected[i]) << "pixel " << i;
    }
    EXPECT_LT(lowest, 0.85 * highest) << "the image spans a range of cos θ / r² worth testing";
}

TEST(PointSources, TheCameraSeesALampThroughTheAtmosphere) {
    // The lamp 3 m over the ground under the parametric atmosphere, the camera 1000 m up: its
    // pixel records I T / (r² Ω), T the model's transmittance from the lamp's altitude to the
    // camera's (the sun is down: no path radiance at 0.5–0.6 µm). A lamp hidden by a roof
    // between it and the camera records nothing.
    constexpr double kIntensity = 40.0;
    const motion::Vec3 lamp_m{0.3, -0.2, 3.0};
    test::TempDir dir;
    write_lamp_scene(dir.path(), 0.0, kIntensity, lamp_m, "2020-06-21T00:00:00.0000-04:00",
                     fs::path(GLINT_TEST_DATA_DIR) / "atmosphere" / "parametric.yaml");
    RenderOptions options = options_into(dir / "out");
    options.convergence = radiometry::Convergence{4, 4, 0.0};
    const auto prepared = detail::plan_render(load(dir / "plate.jsim"), options, {});
    const detail::RenderInputs& in = prepared.plan->inputs;
    const detail::FocalPlaneState& state = prepared.plan->states.at(0);
    const motion::Rigid pose = in.schedule->plugins()[0].poses->instrument_to_scene(0, 0.0);
    const auto [column, row] = pixel_of(state.camera, pose, lamp_m);
    const motion::Vec3 to_camera = pose.translation_m - lamp_m;
    const double range2_m2 = motion::dot(to_camera, to_camera);
    const double omega_sr = pixel_solid_angle_sr(state.camera, column, row);

    glint::atmosphere::AtmosphereGeometry g;
    g.sun_zenith_deg =
        motion::sun_position(in.schedule->plugins()[0].tasks.reference, in.frame).zenith_deg;
    g.surface_altitude_m = 150.0 + lamp_m.z;
    g.sensor_altitude_m = 150.0 + pose.translation_m.z;
    g.view_zenith_deg = 0.0;  // 0.02° off the vertical: within 1e-7 of it in transmittance
    const std::vector<double> t = in.light->atmosphere_model().sensor_transmittance(state.grid, g);
    double mean_t = 0.0;
    for (const double v : t) mean_t += v / static_cast<double>(t.size());
    ASSERT_LT(mean_t, 0.95);

    render(load(dir / "plate.jsim"), options, Context{});
    const std::vector<double> image = io::read_envi_bip(dir / "out" / "frame.img", nullptr);
    const std::size_t pixel = row * state.camera.columns() + column;
    // The channel is a normalized tophat over a flat intensity: the band-mean transmittance.
    EXPECT_NEAR(image[pixel] * omega_sr * range2_m2 * 1e4, kIntensity * mean_t,
                0.01 * kIntensity * mean_t);
    // Every other pixel: a black plate and the night air's own glow (300 K at 0.55 µm:
    // 3e-31 W/(cm² sr µm)).
    for (std::size_t i = 0; i < image.size(); ++i) {
        if (i != pixel) {
            EXPECT_LT(image[i], 1e-20) << i;
        }
    }

    // A roof 10 m up over the lamp hides it.
    test::TempDir roofed;
    write_lamp_scene(roofed.path(), 0.0, kIntensity, lamp_m, "2020-06-21T00:00:00.0000-04:00",
                     fs::path(GLINT_TEST_DATA_DIR) / "atmosphere" / "parametric.yaml");
    {
        std::ifstream in_glist(roofed / "plate.glist");
        std::string text((std::istreambuf_iterator<char>(in_glist)), {});
        text.replace(text.rfind("</geometrylist>"), std::string("</geometrylist>").size(),
                     " <object name=\"Roof\"><basegeometry><box><matid>grey</matid>"
                     "<lowerextent><point><x>-1</x><y>-1</y><z>10</z></point></lowerextent>"
                     "<upperextent><point><x>1</x><y>1</y><z>10.1</z></point></upperextent>"
                     "</box></basegeometry><staticinstance/></object>\n</geometrylist>\n");
        write_text(roofed / "plate.glist", text);
    }
    RenderOptions roof_options = options_into(roofed / "out");
    roof_options.convergence = radiometry::Convergence{4, 4, 0.0};
    render(load(roofed / "plate.jsim"), roof_options, Context{});
    const std::vector<double> hidden = io::read_envi_bip(roofed / "out" / "frame.img", nullptr);
    EXPECT_LT(hidden[pixel], 1e-20);
}

TEST(Moonlight, TheMoonLightsTheNightScene) {
    // 2020-12-30 00:00 EST at 43° N, 77.6° W: the sun far below the horizon, the moon a day
    // before full, high in the south. With no atmosphere the moon is the directional
    // source: E_moon = E_sun · lunar_irradiance_ratio, and the grey plate's radiance is
    // ρ E_moon cos z / π (the lamp is off).
    constexpr double kRho = 0.25;
    test::TempDir dir;
    write_lamp_scene(dir.path(), kRho, 0.0, {0.0, 0.0, 3.0}, "2020-12-30T00:00:00.0000-05:00");
    const fs::path out = dir / "out";
    RenderOptions options = options_into(out);
    options.convergence = radiometry::Convergence{16, 16, 0.0};
    const auto prepared = detail::plan_render(load(dir / "plate.jsim"), options, {});
    const detail::RenderInputs& in = prepared.plan->inputs;
    const detail::FocalPlaneState& state = prepared.plan->states.at(0);
    const DateTime when = in.schedule->plugins()[0].tasks.reference;
    ASSERT_GT(motion::sun_position(when, in.frame).zenith_deg, 120.0);
    const motion::MoonPosition moon = motion::moon_position(when, in.frame);
    ASSERT_LT(moon.zenith_deg, 30.0);
    ASSERT_GT(moon.phase_fraction, 0.95);

    radiometry::SensorPathCache cache;
    const std::optional<schedule::Capture> first = in.schedule->captures().next();
    ASSERT_TRUE(first.has_value());
    const schedule::Capture& capture = *first;
    // No surfaces: the environment's one level is the origin's (no atmosphere here anyway).
    const scene::GeometryScene empty = scene::GeometryScene::build(model::Scene{}, {}, {});
    const radiometry::Environment env = detail::capture_environment(
        in, state.grid, capture, in.schedule->sources()[capture.source], empty, cache, 1);
    const double ratio =
        glint::atmosphere::lunar_irradiance_ratio(moon.phase_angle_deg, moon.distance_km);
    EXPECT_GT(ratio, 2e-6);
    EXPECT_LT(ratio, 3e-6);
    const motion::Vec3 d = env.sun_direction(capture.t0_s);
    EXPECT_NEAR(motion::dot(d, moon.direction_enu), 1.0, 1e-12);
    EXPECT_NEAR(env.sun_half_angle_rad(),
                glint::atmosphere::lunar_angular_radius_rad(moon.distance_km), 1e-15);
    const std::vector<double> toa = in.light->solar_spectrum().resample(
        state.grid, motion::sun_position(when, in.frame).distance_au);
    double mean = 0.0;
    for (std::size_t b = 0; b < state.grid.size(); ++b) {
        EXPECT_NEAR(env.sun_irradiance_w_per_cm2_um()[b], toa[b] * ratio, 1e-6 * toa[b] * ratio);
        mean += env.sun_irradiance_w_per_cm2_um()[b] / static_cast<double>(state.grid.size());
    }

    const RenderReport report = render(load(dir / "plate.jsim"), options, Context{});
    ASSERT_EQ(report.files, std::vector<fs::path>{out / "frame.img"});
    io::EnviHeader header;
    const std::vector<double> image = io::read_envi_bip(out / "frame.img", &header);
    const double expected =
        kRho * mean * std::cos(moon.zenith_deg * std::numbers::pi / 180.0) / std::numbers::pi;
    for (std::size_t i = 0; i < image.size(); ++i) {
        // 3 %: the channel's weights against the bands' plain mean over a solar spectrum that
        // varies by a few per cent across 0.50-0.60 um, and the disk's spread of cos z.
        EXPECT_NEAR(image[i], expected, 0.03 * expected) << "pixel " << i;
    }
}

TEST(PointSources, ANonFinitePositionIsAnInputErrorAtTheSource) {
    const auto prepared =
        detail::plan_render(load(kLights / "lights.jsim"), options_into(fs::path("unused")), {});
    detail::RenderInputs in = detail::make_render_inputs(load(kLights / "lights.jsim"),
                                                         options_into(fs::path("unused")), {});
    in.scene.point_sources[0].position_m[2] = std::nan("");
    try {
        (void)in.light->point_lights_at(in.scene, prepared.plan->states.at(0).grid, 0.0);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_NE(e.message().find("non-finite position"), std::string::npos) << e.message();
        EXPECT_NE(e.context().file.find("street.glist"), std::string::npos) << e.context().file;
    }
}

}  // namespace point_source_render_test
}  // namespace glint::render
