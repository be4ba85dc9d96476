// SPDX-License-Identifier: Apache-2.0
// The normalized platform JSON of every test platform under tests/data/platform, checked
// field by field: counts, SI conversions (mm, µm, nm, degrees), resolved defaults, the
// derived F#, G# = (1 + 4F#²)/(τπ), pixel IFOV, and channel integrals against analytic or
// independently computed values.
#include "glint/app_platform2jsim/platform_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <string>

#include "glint/dirsig/readers.h"
#include "glint/test/angles.h"

namespace glint::app_platform2jsim {
namespace platform_json_test {

using Json = nlohmann::json;
using glint::test::kDeg;
using glint::test::kPi;

std::filesystem::path platform_path(const std::string& name) {
    return std::filesystem::path(GLINT_TEST_DATA_DIR) / "platform" / (name + ".platform");
}

/// Reads a test platform (which must have no error) and returns its parsed dump.
Json dump(const std::string& name) {
    Diagnostics diagnostics;
    const model::Platform platform =
        dirsig::read_platform(platform_path(name), dirsig::ReadOptions{}, diagnostics);
    for (const Diagnostic& d : diagnostics.items()) {
        if (d.severity == Diagnostic::Severity::error) ADD_FAILURE() << d.text();
    }
    return Json::parse(platform_to_json(platform));
}

double g_number(double focal_m, double aperture_m, double tau) {
    const double f = focal_m / aperture_m;
    return (1.0 + 4.0 * f * f) / (tau * kPi);
}

double gaussian_integral(double fwhm_um) {
    return fwhm_um * std::sqrt(kPi / (4.0 * std::numbers::ln2));
}

/// ∫ over [lo, hi] of the peak-1 Gaussian of that centre and FWHM (erf form).
double gaussian_integral(double fwhm_um, double center_um, double lo_um, double hi_um) {
    const double k = 2.0 * std::sqrt(std::numbers::ln2) / fwhm_um;
    return std::sqrt(kPi) / (2.0 * k) *
           (std::erf(k * (hi_um - center_um)) - std::erf(k * (lo_um - center_um)));
}

/// Trapezoid error allowed for a Gaussian cut by the bandpass (h²/12 × the slope jump at
/// the ends is about 1e-6 µm for these grids).
constexpr double kTruncatedTolerance = 5e-6;

std::set<std::string> keys(const Json& object) {
    std::set<std::string> out;
    for (const auto& [key, value] : object.items()) out.insert(key);
    return out;
}

/// Every key of the schema is present (never omitted), whatever the platform.
void expect_complete(const Json& d) {
    EXPECT_EQ(keys(d), (std::set<std::string>{"format", "version", "file", "metadata",
                                              "clock_table", "attachments", "instruments"}));
    for (const Json& instrument : d["instruments"]) {
        EXPECT_EQ(keys(instrument),
                  (std::set<std::string>{"index", "name", "type", "type_text", "path", "properties",
                                         "derived", "focal_planes", "recorder", "transmitter"}));
        if (instrument["type"] == "datarecorder") {
            EXPECT_EQ(keys(instrument["recorder"]),
                      (std::set<std::string>{"clock", "basename", "noise_sigma"}));
        } else {
            EXPECT_TRUE(instrument["recorder"].is_null());
        }
        EXPECT_EQ(keys(instrument["properties"]),
                  (std::set<std::string>{"focal_length_m", "aperture_diameter_m",
                                         "aperture_throughput", "focus_distance_m", "distortion"}));
        EXPECT_EQ(keys(instrument["derived"]),
                  (std::set<std::string>{"f_number", "g_number_per_sr"}));
        for (const Json& fp : instrument["focal_planes"]) {
            EXPECT_EQ(keys(fp), (std::set<std::string>{"index", "name", "enabled", "capture_method",
                                                       "spectral_response", "detector_array",
                                                       "truth_collections", "derived"}));
            EXPECT_EQ(keys(fp["capture_method"]),
                      (std::set<std::string>{"type", "name", "sample_strategy", "image_file",
                                             "spatial_response", "temporal_integration",
                                             "detector_model", "convergence", "psf",
                                             "active_area_image", "processing", "signal_gate"}));
            EXPECT_EQ(
                keys(fp["detector_array"]),
                (std::set<std::string>{"spatial_units", "x_count", "y_count", "x_size_m",
                                       "y_size_m", "x_spacing_m", "y_spacing_m", "x_offset_m",
                                       "y_offset_m", "x_flip", "y_flip", "rolling_line_time_s",
                                       "x_oversample", "y_oversample", "clock"}));
            EXPECT_EQ(keys(fp["detector_array"]["clock"]),
                      (std::set<std::string>{"type", "temporal_units", "rate_hz", "offset_s",
                                             "master", "divider", "offset_count", "trigger_file"}));
            for (const Json& c : fp["spectral_response"]["channels"]) {
                EXPECT_EQ(keys(c),
                          (std::set<std::string>{"index", "name", "shape", "normalize", "gain",
                                                 "bias", "center_um", "width_um", "table",
                                                 "polarizer", "data_output", "integral_um"}));
            }
        }
    }
}

class PlatformJsonAll : public ::testing::TestWithParam<const char*> {};

TEST_P(PlatformJsonAll, HasEveryKeyAndTheFormatHeader) {
    const Json d = dump(GetParam());
    EXPECT_EQ(d["format"], "glint-platform");
    EXPECT_EQ(d["version"], 1);
    EXPECT_EQ(d["file"], platform_path(GetParam()).string());
    expect_complete(d);
    // Instrument indices are their positions; G# follows F# and τ wherever both exist.
    for (std::size_t i = 0; i < d["instruments"].size(); ++i) {
        const Json& instrument = d["instruments"][i];
        EXPECT_EQ(instrument["index"], i);
        const Json& p = instrument["properties"];
        if (p["focal_length_m"].is_number() && p["aperture_diameter_m"].is_number()) {
            const double focal = p["focal_length_m"], aperture = p["aperture_diameter_m"];
            EXPECT_NEAR(instrument["derived"]["f_number"].get<double>(), focal / aperture,
                        1e-12 * focal / aperture);
            EXPECT_NEAR(instrument["derived"]["g_number_per_sr"].get<double>(),
                        g_number(focal, aperture, p["aperture_throughput"]), 1e-9);
        } else {
            EXPECT_TRUE(instrument["derived"]["f_number"].is_null());
            EXPECT_TRUE(instrument["derived"]["g_number_per_sr"].is_null());
        }
    }
}

TEST_P(PlatformJsonAll, IsDeterministic) {
    Diagnostics diagnostics;
    const model::Platform platform =
        dirsig::read_platform(platform_path(GetParam()), dirsig::ReadOptions{}, diagnostics);
    EXPECT_EQ(platform_to_json(platform), platform_to_json(platform));
    EXPECT_EQ(platform_to_json(platform, -1).find('\n'), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(TestPlatforms, PlatformJsonAll,
                         ::testing::Values("minimal", "two_instruments", "mounts", "clocks",
                                           "truth", "capture_full", "nanometers", "aviris",
                                           "superdove"));

TEST(PlatformJson, Minimal) {
    const Json d = dump("minimal");
    EXPECT_TRUE(d["metadata"].empty());
    EXPECT_TRUE(d["clock_table"].empty());
    ASSERT_EQ(d["attachments"].size(), 1u);
    const Json& top = d["attachments"][0];
    EXPECT_TRUE(top["transform"]["identity"].get<bool>());
    EXPECT_TRUE(top["transform"]["matrix"].is_null());
    ASSERT_EQ(top["mounts"].size(), 1u);
    const Json& belly = top["mounts"][0];
    EXPECT_EQ(belly["name"], "Belly");
    EXPECT_EQ(belly["type"], "static");
    EXPECT_EQ(belly["rotation_rad"], Json::array({0.0, 0.0, 0.0}));
    EXPECT_FALSE(belly["rotation_deviates"]["any"].get<bool>());
    ASSERT_EQ(belly["attachments"].size(), 1u);
    EXPECT_EQ(belly["attachments"][0]["instruments"], Json::parse(R"([{"index":0,"name":"Cam"}])"));

    ASSERT_EQ(d["instruments"].size(), 1u);
    const Json& cam = d["instruments"][0];
    EXPECT_EQ(cam["name"], "Cam");
    EXPECT_EQ(cam["type"], "generic");
    EXPECT_EQ(cam["path"], Json::array({"Belly"}));
    EXPECT_DOUBLE_EQ(cam["properties"]["focal_length_m"].get<double>(), 0.05);  // 50 mm
    EXPECT_DOUBLE_EQ(cam["properties"]["aperture_diameter_m"].get<double>(), 0.025);
    EXPECT_DOUBLE_EQ(cam["properties"]["aperture_throughput"].get<double>(), 0.9);
    EXPECT_TRUE(cam["properties"]["focus_distance_m"].is_null());
    EXPECT_EQ(cam["properties"]["distortion"],
              Json::parse(R"({"k1":0.0,"k2":0.0,"k3":0.0,"p1":0.0,"p2":0.0})"));
    EXPECT_NEAR(cam["derived"]["f_number"].get<double>(), 2.0, 1e-12);
    EXPECT_NEAR(cam["derived"]["g_number_per_sr"].get<double>(), 17.0 / (0.9 * kPi), 1e-12);

    ASSERT_EQ(cam["focal_planes"].size(), 1u);
    const Json& fp = cam["focal_planes"][0];
    EXPECT_EQ(fp["name"], "RGB");
    EXPECT_TRUE(fp["enabled"].get<bool>());
    const Json& cm = fp["capture_method"];
    EXPECT_EQ(cm["type"], "simple");
    EXPECT_EQ(cm["name"], "Simple");
    EXPECT_EQ(cm["sample_strategy"], Json::parse(R"({"type":"central",
                                                     "hypersampling_multiplier":1.0})"));
    EXPECT_EQ(cm["image_file"], Json::parse(R"({"basename":"rgb","extension":"img",
        "schedule":"capture","datatype":5,"area_units":"cm2","flux_units":"watts"})"));
    EXPECT_DOUBLE_EQ(cm["temporal_integration"]["time_s"].get<double>(), 0.001);
    EXPECT_EQ(cm["temporal_integration"]["samples"], 1);
    EXPECT_FALSE(cm["temporal_integration"]["tdi"].get<bool>());
    for (const char* absent :
         {"spatial_response", "detector_model", "convergence", "psf", "active_area_image"}) {
        EXPECT_TRUE(cm[absent].is_null()) << absent;
    }
    EXPECT_TRUE(cm["processing"].empty());

    const Json& sr = fp["spectral_response"];
    EXPECT_DOUBLE_EQ(sr["bandpass"]["min_um"].get<double>(), 0.4);
    EXPECT_DOUBLE_EQ(sr["bandpass"]["max_um"].get<double>(), 0.7);
    EXPECT_DOUBLE_EQ(sr["bandpass"]["delta_um"].get<double>(), 0.01);
    EXPECT_EQ(sr["bandpass"]["count"], 31);
    EXPECT_EQ(sr["bandpass"]["spectral_units"], "microns");
    EXPECT_TRUE(sr["pattern"].is_null());
    ASSERT_EQ(sr["channels"].size(), 1u);
    const Json& green = sr["channels"][0];
    EXPECT_EQ(green["name"], "Green");
    EXPECT_EQ(green["shape"], "gaussian");
    EXPECT_FALSE(green["normalize"].get<bool>());
    EXPECT_DOUBLE_EQ(green["gain"].get<double>(), 1.0);
    EXPECT_DOUBLE_EQ(green["bias"].get<double>(), 0.0);
    EXPECT_DOUBLE_EQ(green["center_um"].get<double>(), 0.55);
    EXPECT_DOUBLE_EQ(green["width_um"].get<double>(), 0.04);
    EXPECT_TRUE(green["table"]["wavelength_um"].empty());
    EXPECT_EQ(green["polarizer"], "none");
    EXPECT_EQ(green["data_output"], "total");
    // 0.4–0.7 µm covers ±3.75 FWHM: the truncated tails are below 1e-16.
    EXPECT_NEAR(green["integral_um"].get<double>(), gaussian_integral(0.04), 1e-12);

    const Json& da = fp["detector_array"];
    EXPECT_EQ(da["spatial_units"], "microns");
    EXPECT_EQ(da["x_count"], 64);
    EXPECT_EQ(da["y_count"], 48);
    for (const char* key : {"x_size_m", "y_size_m", "x_spacing_m", "y_spacing_m"}) {
        EXPECT_NEAR(da[key].get<double>(), 5e-6, 1e-18) << key;  // 5 µm
    }
    EXPECT_DOUBLE_EQ(da["x_offset_m"].get<double>(), 0.0);
    EXPECT_FALSE(da["x_flip"].get<bool>());
    EXPECT_TRUE(da["rolling_line_time_s"].is_null());
    EXPECT_EQ(da["clock"]["type"], "independent");
    EXPECT_EQ(da["clock"]["temporal_units"], "hertz");
    EXPECT_DOUBLE_EQ(da["clock"]["rate_hz"].get<double>(), 10.0);
    EXPECT_DOUBLE_EQ(da["clock"]["offset_s"].get<double>(), 0.0);
    EXPECT_TRUE(da["clock"]["trigger_file"].is_null());

    ASSERT_EQ(fp["truth_collections"].size(), 1u);
    const Json& truth = fp["truth_collections"][0];
    EXPECT_TRUE(truth["enabled"].get<bool>());
    EXPECT_EQ(truth["image_file"]["basename"], "rgb_truth");
    EXPECT_EQ(truth["collectors"],
              Json::parse(R"([{"name":"Material","materials":[],"tags":[]}])"));

    // IFOV = 5 µm / 50 mm; FOV = 2 atan(64 × 5 µm / 2 / 50 mm).
    EXPECT_NEAR(fp["derived"]["pixel_ifov_rad"][0].get<double>(), 1e-4, 1e-16);
    EXPECT_NEAR(fp["derived"]["pixel_ifov_rad"][1].get<double>(), 1e-4, 1e-16);
    EXPECT_NEAR(fp["derived"]["field_of_view_rad"][0].get<double>(),
                2.0 * std::atan(64 * 5e-6 / 2 / 0.05), 1e-15);
    EXPECT_NEAR(fp["derived"]["field_of_view_rad"][1].get<double>(),
                2.0 * std::atan(48 * 5e-6 / 2 / 0.05), 1e-15);
}

TEST(PlatformJson, TwoInstruments) {
    const Json d = dump("two_instruments");
    ASSERT_EQ(d["metadata"].size(), 4u);
    EXPECT_EQ(d["metadata"][0]["name"], "Author(s)");
    EXPECT_EQ(d["metadata"][0]["value"], "glint test suite");
    EXPECT_EQ(d["metadata"][2], Json::parse(R"({"name":"Name","value":"TwoCameras"})"));
    EXPECT_EQ(d["metadata"][3]["value"], "");

    ASSERT_EQ(d["attachments"].size(), 2u);
    const Json& first = d["attachments"][0];
    EXPECT_FALSE(first["transform"]["identity"].get<bool>());
    EXPECT_EQ(first["transform"]["translation_m"], Json::array({1.5, -0.25, 0.1}));
    const Json& gimbal = first["mounts"][0];
    EXPECT_EQ(gimbal["name"], "Gimbal");
    EXPECT_EQ(gimbal["rotation_order"], "zyx");
    EXPECT_NEAR(gimbal["rotation_rad"][1].get<double>(), -30 * kDeg, 1e-15);
    EXPECT_NEAR(gimbal["rotation_rad"][2].get<double>(), 90 * kDeg, 1e-15);
    const Json& tilt = gimbal["attachments"][0]["mounts"][0];
    EXPECT_EQ(tilt["name"], "Tilt");
    EXPECT_DOUBLE_EQ(tilt["rotation_rad"][0].get<double>(), 0.1);  // radians as written
    EXPECT_EQ(tilt["attachments"][0]["instruments"][0]["index"], 0);

    ASSERT_EQ(d["instruments"].size(), 2u);
    const Json& wide = d["instruments"][0];
    EXPECT_EQ(wide["name"], "Wide");
    EXPECT_EQ(wide["path"], Json::array({"Gimbal", "Tilt"}));
    EXPECT_NEAR(wide["properties"]["focal_length_m"].get<double>(), 0.035, 1e-15);
    EXPECT_NEAR(wide["derived"]["f_number"].get<double>(), 3.5, 1e-12);
    EXPECT_NEAR(wide["derived"]["g_number_per_sr"].get<double>(), 50.0 / (0.8 * kPi), 1e-12);
    ASSERT_EQ(wide["focal_planes"].size(), 2u);
    const Json& vis = wide["focal_planes"][0];
    EXPECT_EQ(vis["capture_method"]["image_file"]["schedule"], "task");
    const Json& da = vis["detector_array"];
    EXPECT_EQ(da["spatial_units"], "millimeters");
    EXPECT_EQ(da["x_count"], 320);
    EXPECT_EQ(da["y_count"], 240);
    EXPECT_NEAR(da["x_size_m"].get<double>(), 8e-6, 1e-18);  // 0.008 mm
    EXPECT_NEAR(da["y_size_m"].get<double>(), 9e-6, 1e-18);
    EXPECT_NEAR(da["x_spacing_m"].get<double>(), 1e-5, 1e-18);
    EXPECT_NEAR(da["x_offset_m"].get<double>(), 5e-4, 1e-18);
    EXPECT_NEAR(da["y_offset_m"].get<double>(), -2.5e-4, 1e-18);
    EXPECT_TRUE(da["x_flip"].get<bool>());
    EXPECT_FALSE(da["y_flip"].get<bool>());
    EXPECT_DOUBLE_EQ(da["clock"]["rate_hz"].get<double>(), 2.0);
    EXPECT_DOUBLE_EQ(da["clock"]["offset_s"].get<double>(), 0.25);
    EXPECT_NEAR(vis["derived"]["pixel_ifov_rad"][0].get<double>(), 1e-5 / 0.035, 1e-15);
    const Json& nir = wide["focal_planes"][1];
    EXPECT_FALSE(nir["enabled"].get<bool>());
    // Element size defaults to the spacing; offsets to 0.
    EXPECT_NEAR(nir["detector_array"]["x_size_m"].get<double>(), 20e-6, 1e-18);
    EXPECT_NEAR(nir["detector_array"]["y_size_m"].get<double>(), 20e-6, 1e-18);
    EXPECT_DOUBLE_EQ(nir["detector_array"]["x_offset_m"].get<double>(), 0.0);

    const Json& narrow = d["instruments"][1];
    EXPECT_EQ(narrow["path"], Json::array({"Belly"}));
    EXPECT_DOUBLE_EQ(narrow["properties"]["aperture_throughput"].get<double>(), 1.0);  // default
    EXPECT_DOUBLE_EQ(narrow["properties"]["focus_distance_m"].get<double>(), 2500.0);
    EXPECT_EQ(narrow["properties"]["distortion"],
              Json::parse(R"({"k1":0.01,"k2":-0.002,"k3":0.0,"p1":0.0005,"p2":-0.0001})"));
    EXPECT_NEAR(narrow["derived"]["f_number"].get<double>(), 3.0, 1e-12);
    EXPECT_NEAR(narrow["derived"]["g_number_per_sr"].get<double>(), 37.0 / kPi, 1e-12);
    const Json& pan = narrow["focal_planes"][0];
    EXPECT_EQ(pan["spectral_response"]["bandpass"]["count"], 10);  // 0.45–0.9 by 0.05
    EXPECT_TRUE(pan["spectral_response"]["channels"][0]["normalize"].get<bool>());
    EXPECT_DOUBLE_EQ(pan["capture_method"]["temporal_integration"]["time_s"].get<double>(), 0.0);
    EXPECT_EQ(pan["detector_array"]["y_count"], 1);
}

TEST(PlatformJson, Mounts) {
    const Json d = dump("mounts");
    ASSERT_EQ(d["attachments"].size(), 3u);
    const Json& pointer = d["attachments"][0]["mounts"][0];
    EXPECT_EQ(pointer["type"], "commanded");
    ASSERT_EQ(pointer["entries"].size(), 3u);
    EXPECT_DOUBLE_EQ(pointer["entries"][1]["time_s"].get<double>(), 1.5);
    EXPECT_NEAR(pointer["entries"][1]["rotation_rad"][0].get<double>(), 5 * kDeg, 1e-15);
    EXPECT_EQ(pointer["entries"][1]["translation_m"], Json::array({0.5, 0.0, -0.2}));
    EXPECT_NEAR(pointer["entries"][0]["rotation_rad"][1].get<double>(), -10 * kDeg, 1e-15);
    const Json& jitter = pointer["rotation_deviates"];
    EXPECT_TRUE(jitter["any"].get<bool>());
    EXPECT_EQ(jitter["axes"][0]["axis"], "x");  // along-track: about x
    EXPECT_EQ(jitter["axes"][0]["kind"], "normal");
    EXPECT_NEAR(jitter["axes"][0]["stddev_rad"].get<double>(), 0.01 * kDeg, 1e-18);
    EXPECT_EQ(jitter["axes"][1]["kind"], "psd");  // across-track: about y
    EXPECT_EQ(jitter["axes"][1]["psd_file"]["text"], "jitter_psd.txt");
    EXPECT_EQ(jitter["axes"][1]["psd_file"]["resolved"],
              (std::filesystem::path(GLINT_TEST_DATA_DIR) / "platform" / "jitter_psd.txt")
                  .lexically_normal()
                  .string());
    EXPECT_EQ(jitter["axes"][2]["kind"], "none");

    const Json& table = pointer["attachments"][0]["mounts"][0];
    EXPECT_EQ(table["type"], "tabulated");
    EXPECT_EQ(table["rotation_order"], "zyx");
    EXPECT_DOUBLE_EQ(table["period_s"].get<double>(), 2.0);
    EXPECT_DOUBLE_EQ(table["entries"][1]["rotation_rad"][2].get<double>(), 0.5);

    const Json& second = d["attachments"][1]["mounts"];
    ASSERT_EQ(second.size(), 3u);
    EXPECT_DOUBLE_EQ(second[0]["period_s"].get<double>(), 4.0);
    const Json& scanner = second[1];
    EXPECT_EQ(scanner["type"], "whisk");
    EXPECT_EQ(scanner["whisk"]["axis"], "across_track");
    EXPECT_NEAR(scanner["whisk"]["min_angle_rad"].get<double>(), -15 * kDeg, 1e-15);
    EXPECT_NEAR(scanner["whisk"]["max_angle_rad"].get<double>(), 15 * kDeg, 1e-15);
    EXPECT_DOUBLE_EQ(scanner["whisk"]["rate_hz"].get<double>(), 10.0);
    EXPECT_NEAR(scanner["whisk"]["phase_rad"].get<double>(), kPi / 2, 1e-15);
    EXPECT_FALSE(scanner["whisk"]["sinusoidal"].get<bool>());
    EXPECT_DOUBLE_EQ(scanner["rotation_deviates"]["axes"][0]["mean_rad"].get<double>(), 0.001);
    EXPECT_DOUBLE_EQ(scanner["rotation_deviates"]["axes"][0]["stddev_rad"].get<double>(), 2e-4);
    const Json& nodder = second[2];
    EXPECT_EQ(nodder["whisk"]["axis"], "along_track");
    EXPECT_TRUE(nodder["whisk"]["sinusoidal"].get<bool>());
    EXPECT_TRUE(nodder["whisk"].contains("phase_rad"));

    const Json& third = d["attachments"][2];
    EXPECT_EQ(third["transform"]["translation_m"], Json::array({0.0, 0.0, -0.5}));
    EXPECT_EQ(third["mounts"][0]["tracking"],
              Json::parse(R"({"name":"truck_01","offset_m":[0.0,1.5,2.0],"point_m":null})"));
    EXPECT_EQ(third["mounts"][1]["tracking"]["point_m"], Json::array({100.0, -50.5, 2.0}));
    EXPECT_TRUE(third["mounts"][1]["whisk"].is_null());

    // Instruments in document order, depth first: each with the mounts that hold it.
    ASSERT_EQ(d["instruments"].size(), 3u);
    EXPECT_EQ(d["instruments"][0]["name"], "Recorder");
    EXPECT_EQ(d["instruments"][0]["type"], "datarecorder");
    EXPECT_EQ(d["instruments"][0]["type_text"], "data_recorder");
    EXPECT_EQ(d["instruments"][0]["path"], Json::array({"Pointer", "Table"}));
    EXPECT_TRUE(d["instruments"][0]["focal_planes"].empty());
    EXPECT_TRUE(d["instruments"][0]["properties"]["focal_length_m"].is_null());
    EXPECT_EQ(d["instruments"][1]["path"], Json::array({"Scanner"}));
    const Json& track = d["instruments"][2];
    EXPECT_EQ(track["path"], Json::array({"Tracker"}));
    EXPECT_TRUE(track["properties"]["aperture_diameter_m"].is_null());
    EXPECT_TRUE(track["derived"]["f_number"].is_null());  // no aperture
    EXPECT_TRUE(track["derived"]["g_number_per_sr"].is_null());
    EXPECT_NEAR(track["focal_planes"][0]["derived"]["pixel_ifov_rad"][0].get<double>(), 10e-6 / 0.1,
                1e-16);  // needs only the focal length
}

TEST(PlatformJson, Clocks) {
    const Json d = dump("clocks");
    EXPECT_EQ(d["clock_table"], Json::parse(R"([{"name":"Master","rate_hz":100.0,"offset_s":0.01},
                                                {"name":"Slow","rate_hz":1.0,"offset_s":0.0}])"));
    ASSERT_EQ(d["instruments"].size(), 2u);
    const Json& framer = d["instruments"][0]["focal_planes"];
    ASSERT_EQ(framer.size(), 3u);
    const Json& sync = framer[0]["detector_array"]["clock"];
    EXPECT_EQ(sync["type"], "synchronous");
    EXPECT_EQ(sync["master"], "Master");
    EXPECT_EQ(sync["divider"], 4);
    EXPECT_EQ(sync["offset_count"], 2);
    const Json& slow = framer[1]["detector_array"]["clock"];
    EXPECT_EQ(slow["master"], "Slow");
    EXPECT_EQ(slow["divider"], 1);  // default
    EXPECT_EQ(slow["offset_count"], 0);
    const Json& rolling = framer[2]["detector_array"];
    EXPECT_DOUBLE_EQ(rolling["rolling_line_time_s"].get<double>(), 2.5e-5);
    EXPECT_DOUBLE_EQ(rolling["clock"]["rate_hz"].get<double>(), 30.0);
    EXPECT_DOUBLE_EQ(rolling["clock"]["offset_s"].get<double>(), 0.005);
    EXPECT_NEAR(d["instruments"][0]["derived"]["g_number_per_sr"].get<double>(), 17.0 / kPi,
                1e-12);  // τ = 1

    const Json& triggered = d["instruments"][1]["focal_planes"];
    ASSERT_EQ(triggered.size(), 2u);
    const Json& external = triggered[0]["detector_array"]["clock"];
    EXPECT_EQ(external["type"], "external");
    EXPECT_EQ(external["trigger_file"]["text"], "triggers.txt");
    const std::string resolved = external["trigger_file"]["resolved"];
    EXPECT_TRUE(std::filesystem::path(resolved).is_absolute());
    EXPECT_TRUE(std::filesystem::exists(resolved)) << resolved;
    EXPECT_EQ(triggered[1]["detector_array"]["clock"]["type"], "external");
    EXPECT_EQ(triggered[1]["detector_array"]["clock"]["trigger_file"]["text"],
              "sub/more_triggers.txt");
}

TEST(PlatformJson, Truth) {
    const Json d = dump("truth");
    const Json& truth = d["instruments"][0]["focal_planes"][0]["truth_collections"];
    ASSERT_EQ(truth.size(), 5u);
    for (std::size_t i = 0; i < truth.size(); ++i) EXPECT_EQ(truth[i]["index"], i);
    EXPECT_EQ(truth[0]["name"], "Geometry");
    EXPECT_EQ(truth[0]["collectors"].size(), 3u);
    EXPECT_EQ(truth[0]["collectors"][1]["name"], "GeoLocation");
    EXPECT_EQ(truth[1]["image_file"]["schedule"], "task");
    EXPECT_EQ(truth[1]["collectors"][0]["materials"], Json::array({"10", "grass"}));
    EXPECT_EQ(truth[1]["collectors"][1]["tags"], Json::array({"truck", "car"}));
    EXPECT_TRUE(truth[2]["collectors"].empty());  // the empty <truthcollection/>
    EXPECT_FALSE(truth[3]["enabled"].get<bool>());
    EXPECT_EQ(truth[3]["image_file"]["basename"], "geometry_truth_again");
    EXPECT_EQ(truth[4]["name"], "");
    EXPECT_EQ(truth[4]["image_file"]["schedule"], "simulation");
}

TEST(PlatformJson, CaptureFull) {
    const Json d = dump("capture_full");
    const Json& planes = d["instruments"][0]["focal_planes"];
    ASSERT_EQ(planes.size(), 4u);

    const Json& bayer = planes[0];
    const Json& cm = bayer["capture_method"];
    EXPECT_DOUBLE_EQ(cm["sample_strategy"]["hypersampling_multiplier"].get<double>(), 100.0);
    EXPECT_EQ(cm["image_file"], Json::parse(R"({"basename":"bayer","extension":"dat",
        "schedule":"capture","datatype":12,"area_units":"m2","flux_units":"photonspersecond"})"));
    EXPECT_EQ(cm["spatial_response"]["spatial_sampling"], "subsamples");
    EXPECT_EQ(cm["spatial_response"]["x_sub_elements"], 2);
    EXPECT_EQ(cm["spatial_response"]["y_sub_elements"], 3);
    EXPECT_EQ(cm["spatial_response"]["entries"].size(), 1u);
    EXPECT_EQ(cm["convergence"], Json::parse(R"({"minimum_samples":250,"maximum_samples":750,
                                                 "threshold_w_per_cm2_sr_um":1e-08})"));
    EXPECT_DOUBLE_EQ(cm["psf"]["width_px"].get<double>(), 3.8);
    EXPECT_TRUE(cm["psf"]["image"].is_null());
    EXPECT_EQ(cm["active_area_image"]["text"], "masks/pixel_mask.png");
    ASSERT_EQ(cm["processing"].size(), 2u);
    EXPECT_EQ(cm["processing"][0]["schedule"], "capture_completed");
    EXPECT_EQ(cm["processing"][0]["program"], "demosaic");
    EXPECT_EQ(cm["processing"][0]["arguments"],
              Json::array({"--pattern=bayer", "--input_filename=$$IMG_BASENAME$$.dat"}));
    EXPECT_TRUE(cm["processing"][0]["remove_file"].get<bool>());
    EXPECT_EQ(cm["processing"][1]["schedule"], "collection_completed");
    EXPECT_FALSE(cm["processing"][1]["remove_file"].get<bool>());

    const Json& sr = bayer["spectral_response"];
    EXPECT_EQ(sr["pattern"]["name"], "bayer");
    EXPECT_EQ(sr["pattern"]["mappings"][0], Json::parse(R"({"filter":"red",
                                                             "channel":"RedChannel"})"));
    const Json& channels = sr["channels"];
    ASSERT_EQ(channels.size(), 3u);
    // Centre 0.62 µm, 1.6 FWHM from the bandpass end: the tail beyond 0.7 µm is cut.
    EXPECT_NEAR(channels[0]["integral_um"].get<double>(), gaussian_integral(0.05, 0.62, 0.4, 0.7),
                kTruncatedTolerance);
    EXPECT_LT(channels[0]["integral_um"].get<double>(), gaussian_integral(0.05));
    EXPECT_EQ(channels[1]["shape"], "tophat");
    EXPECT_DOUBLE_EQ(channels[1]["gain"].get<double>(), 2.0);
    EXPECT_DOUBLE_EQ(channels[1]["bias"].get<double>(), 0.5);
    EXPECT_NEAR(channels[1]["integral_um"].get<double>(), 0.08, 1e-12);  // width
    EXPECT_EQ(channels[2]["shape"], "triangle");
    EXPECT_NEAR(channels[2]["integral_um"].get<double>(), 0.03, 1e-12);  // width / 2
    EXPECT_DOUBLE_EQ(channels[2]["gain"].get<double>(), 1.0);            // defaults
    EXPECT_FALSE(channels[2]["normalize"].get<bool>());

    const Json& truesense = planes[1];
    const Json& ts = truesense["capture_method"];
    EXPECT_EQ(ts["image_file"], Json::parse(R"({"basename":"truesense","extension":"img",
        "schedule":"simulation","datatype":5,"area_units":"cm2","flux_units":"watts"})"));
    EXPECT_TRUE(ts["psf"]["width_px"].is_null());
    EXPECT_EQ(ts["psf"]["image"]["text"], "airy_psf.png");
    EXPECT_DOUBLE_EQ(ts["psf"]["scale_px"].get<double>(), 10.0);
    EXPECT_EQ(ts["active_area_image"]["resolved"], "/masks/diamond.png");
    EXPECT_EQ(ts["convergence"]["minimum_samples"], 10);
    ASSERT_EQ(ts["processing"].size(), 4u);
    EXPECT_EQ(ts["processing"][0]["schedule"], "collection_started");
    EXPECT_EQ(ts["processing"][1]["schedule"], "task_started");
    EXPECT_EQ(ts["processing"][2]["schedule"], "capture_started");
    EXPECT_EQ(ts["processing"][3]["schedule"], "task_completed");
    const Json& tsr = truesense["spectral_response"];
    EXPECT_EQ(tsr["bandpass"]["spectral_units"], "microns");  // default
    EXPECT_EQ(tsr["pattern"]["name"], "truesense");
    EXPECT_EQ(tsr["pattern"]["mappings"].size(), 4u);
    const Json& pan = tsr["channels"][0];
    EXPECT_EQ(pan["shape"], "tabulated");
    EXPECT_TRUE(pan["center_um"].is_null());
    EXPECT_TRUE(pan["width_um"].is_null());
    EXPECT_EQ(pan["table"]["wavelength_um"], Json::array({0.4, 0.45, 0.75, 0.8}));
    EXPECT_EQ(pan["table"]["value"], Json::array({0.0, 0.8, 0.9, 0.0}));
    // Trapezoid over the table: 0.05·0.4 + 0.3·0.85 + 0.05·0.45.
    EXPECT_NEAR(pan["integral_um"].get<double>(), 0.02 + 0.255 + 0.0225, 1e-12);
    EXPECT_EQ(tsr["channels"][1]["shape"], "gaussian");  // default shape

    const Json& tdi = planes[2];
    EXPECT_TRUE(tdi["capture_method"]["temporal_integration"]["tdi"].get<bool>());
    EXPECT_DOUBLE_EQ(tdi["capture_method"]["temporal_integration"]["time_s"].get<double>(), 2e-5);
    EXPECT_EQ(tdi["capture_method"]["detector_model"],
              Json::parse(R"({"quantum_efficiency":0.8,"read_noise_e":20.0,
                  "dark_current_density_a_per_m2":8e-07,"min_electrons":0.0,
                  "max_electrons":1000.0,"bit_depth":12})"));
    EXPECT_EQ(tdi["detector_array"]["y_count"], 12);
    // A tophat that fills the bandpass integrates to the bandpass width.
    EXPECT_NEAR(tdi["spectral_response"]["channels"][0]["integral_um"].get<double>(), 0.5, 1e-12);

    const Json& raw = planes[3];
    EXPECT_FALSE(raw["enabled"].get<bool>());
    EXPECT_EQ(raw["capture_method"]["type"], "raw");
    EXPECT_EQ(raw["capture_method"]["image_file"]["flux_units"], "microwatts");
    EXPECT_EQ(raw["capture_method"]["image_file"]["datatype"], 4);
    EXPECT_EQ(raw["spectral_response"]["bandpass"]["count"], 211);  // 0.40–2.50 @ 0.01
    EXPECT_TRUE(raw["spectral_response"]["channels"].empty());
}

TEST(PlatformJson, NanometersAreConvertedToMicrometres) {
    const Json d = dump("nanometers");
    const Json& fp = d["instruments"][0]["focal_planes"][0];
    EXPECT_EQ(fp["capture_method"]["image_file"]["flux_units"], "milliwatts");
    const Json& bp = fp["spectral_response"]["bandpass"];
    EXPECT_EQ(bp["spectral_units"], "nanometers");
    EXPECT_NEAR(bp["min_um"].get<double>(), 0.4, 1e-12);
    EXPECT_NEAR(bp["max_um"].get<double>(), 0.7, 1e-12);
    EXPECT_NEAR(bp["delta_um"].get<double>(), 0.005, 1e-15);
    EXPECT_EQ(bp["count"], 61);
    const Json& channels = fp["spectral_response"]["channels"];
    ASSERT_EQ(channels.size(), 3u);
    EXPECT_NEAR(channels[0]["center_um"].get<double>(), 0.64, 1e-12);
    EXPECT_NEAR(channels[0]["width_um"].get<double>(), 0.04, 1e-12);
    EXPECT_NEAR(channels[0]["integral_um"].get<double>(), gaussian_integral(0.04, 0.64, 0.4, 0.7),
                kTruncatedTolerance);  // cut at 0.7 µm
    EXPECT_NEAR(channels[1]["integral_um"].get<double>(), gaussian_integral(0.04), 1e-12);
    const Json& blue = channels[2];
    EXPECT_EQ(blue["shape"], "tabulated");
    ASSERT_EQ(blue["table"]["wavelength_um"].size(), 3u);
    EXPECT_NEAR(blue["table"]["wavelength_um"][1].get<double>(), 0.45, 1e-12);
    // Table trapezoid 0.025 + 0.0275, plus the drop from 0.2 to 0 over the next 5 nm sample.
    EXPECT_NEAR(blue["integral_um"].get<double>(), 0.0525 + 0.0005, 1e-12);
}

TEST(PlatformJson, AvirisGaussianChannelsIntegrateToTheirFwhmTimesSqrtPiOver4Ln2) {
    const Json d = dump("aviris");
    const Json& sr = d["instruments"][0]["focal_planes"][0]["spectral_response"];
    EXPECT_EQ(sr["bandpass"]["count"], 2121);  // 0.38–2.5 µm by 1 nm
    const Json& channels = sr["channels"];
    ASSERT_EQ(channels.size(), 224u);
    const double min_um = sr["bandpass"]["min_um"], max_um = sr["bandpass"]["max_um"];
    std::size_t checked = 0;
    for (const Json& c : channels) {
        EXPECT_EQ(c["shape"], "gaussian");
        const double center = c["center_um"], fwhm = c["width_um"];
        if (center - 3 * fwhm < min_um || center + 3 * fwhm > max_um) continue;  // truncated
        EXPECT_NEAR(c["integral_um"].get<double>(), gaussian_integral(fwhm), 1e-9 * fwhm)
            << c["name"];
        ++checked;
    }
    EXPECT_GT(checked, 200u);
    // Channel #1 (centre 0.3734 µm) lies half outside the bandpass: less than the full area.
    EXPECT_LT(channels[0]["integral_um"].get<double>(),
              gaussian_integral(channels[0]["width_um"].get<double>()));
}

TEST(PlatformJson, SuperDoveTabulatedChannelsIntegrateAsTheirTables) {
    const Json d = dump("superdove");
    const Json& sr = d["instruments"][0]["focal_planes"][0]["spectral_response"];
    EXPECT_EQ(sr["bandpass"]["spectral_units"], "nanometers");
    EXPECT_EQ(sr["bandpass"]["count"], 471);  // 425–895 nm by 1 nm
    const double min_um = sr["bandpass"]["min_um"], max_um = sr["bandpass"]["max_um"];
    const double delta_um = sr["bandpass"]["delta_um"];
    const Json& channels = sr["channels"];
    ASSERT_EQ(channels.size(), 8u);
    for (const Json& c : channels) {
        EXPECT_EQ(c["shape"], "tabulated");
        const Json& w = c["table"]["wavelength_um"];
        const Json& v = c["table"]["value"];
        ASSERT_EQ(w.size(), v.size());
        ASSERT_GE(w.size(), 2u);
        double expected = 0.0;
        for (std::size_t i = 1; i < w.size(); ++i) {
            expected += 0.5 * (v[i].get<double>() + v[i - 1].get<double>()) *
                        (w[i].get<double>() - w[i - 1].get<double>());
        }
        // A table that starts or ends inside the bandpass (on a sample) rises from or drops
        // to 0 over one more sample.
        if (w.front().get<double>() > min_um + 1e-9) {
            expected += 0.5 * v.front().get<double>() * delta_um;
        }
        if (w.back().get<double>() < max_um - 1e-9) {
            expected += 0.5 * v.back().get<double>() * delta_um;
        }
        EXPECT_NEAR(c["integral_um"].get<double>(), expected, 1e-9) << c["name"];
        EXPECT_GT(c["integral_um"].get<double>(), 0.0);
    }
}

}  // namespace platform_json_test
}  // namespace glint::app_platform2jsim
