// SPDX-License-Identifier: Apache-2.0
// Truth collection (docs/truth.md) against analytic answers: abundance is the covered area
// fraction, the geolocation the camera model's projection of the pixel centre, the distance
// the geometric range, the shadow fraction the share of the pixel the sun does not light,
// the sample count what the convergence settings give, the standard error the spread of the
// samples (∝ 1/√N); and collecting truth changes neither the radiance nor, with the thread
// count, the truth's bytes.
//
// Every case renders cam.platform's camera (tests/data/render: nadir, 1000 m up, focal length
// 100 mm, 20 µm pixels: 0.2 m on the ground at z = 0) as an 8 × 8 array over a scene written
// here, at capture 0 of three.tasks (2020-06-21 12:00 EDT at 43° N, 77.6° W), with no
// atmosphere and a black sky. Pixel (column i, row j) sees the ground square
// x ∈ [i − 4, i − 3] × 0.2 m, y ∈ [3 − j, 4 − j] × 0.2 m (camera.h: columns grow towards +X,
// rows towards −Y). The samples of a pixel are uniform over its element (independent u, v), so
// a fraction f of the pixel is hit with probability f by each sample: a binomial count.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "../../../lib/sensor/src/render_parts.h"
#include "glint/core/datetime.h"
#include "glint/core/text.h"
#include "glint/io/envi.h"
#include "glint/motion/frames.h"
#include "glint/motion/sun.h"
#include "glint/sensor/render.h"
#include "glint/test/temp_dir.h"
#include "render_fixture.h"

namespace glint::sensor {
namespace {

namespace fs = std::filesystem;
using test_render::kRenderData;
using test_render::load;
using test_render::options_into;
using test_render::read_text;

constexpr std::size_t kSide = 8;      // columns and rows
constexpr double kPixel_m = 0.2;      // ground sample at z = 0
constexpr double kCamera_m = 1000.0;  // camera height above z = 0 (static.ppd)

/// Every scene's first line (scene.yaml's origin).
constexpr const char* kOrigin = "origin: {latitude: 43.0, longitude: -77.6, altitude: 150}\n";

/// The files of a one-camera simulation in `dir`: `scene` as scene.yaml; cam.platform as an
/// 8 × 8 array with `truth` (`<truthcollection>` elements, may be empty) in its focal plane
/// and, when given, `channels` for its `<channellist>`; static.ppd, three.tasks, no
/// atmosphere.
void write_simulation(const fs::path& dir, const std::string& scene, const std::string& truth,
                      const std::string& channels = {}) {
    fs::create_directories(dir);
    for (const char* name : {"none.atm.yaml", "static.ppd", "three.tasks", "one.jsim"}) {
        fs::copy_file(kRenderData / name, dir / name, fs::copy_options::overwrite_existing);
    }
    std::ofstream(dir / "scene.yaml") << kOrigin << scene;
    std::string platform = read_text(kRenderData / "cam.platform");
    const std::string rows = "<yelementcount>6</yelementcount>";
    const std::string end = "</focalplane>";
    ASSERT_NE(platform.find(rows), std::string::npos);
    platform.replace(platform.find(rows), rows.size(), "<yelementcount>8</yelementcount>");
    ASSERT_NE(platform.find(end), std::string::npos);
    platform.insert(platform.find(end), truth);
    if (!channels.empty()) {
        const std::size_t begin = platform.find("<channellist>");
        const std::string close = "</channellist>";
        ASSERT_NE(begin, std::string::npos);
        platform.replace(begin, platform.find(close) + close.size() - begin, channels);
    }
    std::ofstream(dir / "cam.platform") << platform;
}

/// A `<truthcollection>` named `name` writing `basename`.img with `collectors` (the inner XML
/// of its `<collectorlist>`).
std::string truth_collection(const std::string& name, const std::string& basename,
                             const std::string& collectors) {
    return "<truthcollection><name>" + name + "</name><imagefile><basename>" + basename +
           "</basename><extension>img</extension><schedule>simulation</schedule></imagefile>"
           "<collectorlist>" +
           collectors + "</collectorlist></truthcollection>";
}

/// One `<collector>`, with `<materials>` when given.
std::string collector(const std::string& name, const std::string& materials = {}) {
    return "<collector><name>" + name + "</name>" +
           (materials.empty() ? "" : "<materials>" + materials + "</materials>") + "</collector>";
}

/// A truth image read back, its values looked up by band name.
struct TruthImage {
    io::EnviHeader header;
    std::vector<double> values;

    std::size_t band(const std::string& name) const {
        for (std::size_t b = 0; b < header.band_names.size(); ++b) {
            if (header.band_names[b] == name) return b;
        }
        ADD_FAILURE() << "no truth band " << name;
        return 0;
    }
    double at(const std::string& name, std::size_t column, std::size_t row) const {
        return values.at((row * kSide + column) * header.bands + band(name));
    }
};

std::vector<char> read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// What one render wrote.
struct Rendered {
    fs::path folder;
    RenderReport report;
    std::vector<double> image;  ///< frame.img: one channel, W/(cm² sr µm), pixel after pixel
    TruthImage truth;           ///< t.img, when written

    double radiance(std::size_t column, std::size_t row) const {
        return image.at(row * kSide + column);
    }
};

/// Renders capture 0 of the simulation in `dir` into `dir`/out with `convergence`.
Rendered render_into(const fs::path& dir, radiometry::Convergence convergence,
                     unsigned threads = 0) {
    Rendered r;
    r.folder = dir / "out";
    RenderOptions options = options_into(r.folder);
    options.convergence = convergence;
    options.only_captures = {0};
    Context context;
    context.threads = threads;
    r.report = render(load(dir / "one.jsim"), options, context);
    r.image = io::read_envi_bip(r.folder / "frame.img", nullptr);
    if (fs::exists(r.folder / "t.img")) {
        r.truth.values = io::read_envi_bip(r.folder / "t.img", &r.truth.header);
    }
    return r;
}

/// Fraction of pixel (column, row) that the rectangle [x0, x1] × [y0, y1] (m, at z = 0)
/// covers.
double covered(std::size_t column, std::size_t row, double x0, double x1, double y0, double y1) {
    const double px0 = (static_cast<double>(column) - 4.0) * kPixel_m;
    const double py0 = (3.0 - static_cast<double>(row)) * kPixel_m;
    const double wx = std::max(0.0, std::min(x1, px0 + kPixel_m) - std::max(x0, px0));
    const double wy = std::max(0.0, std::min(y1, py0 + kPixel_m) - std::max(y0, py0));
    const double f = wx * wy / (kPixel_m * kPixel_m);
    // Snap the rounding of the products above (1 + 2e-16) to the exact 0 and 1 they are.
    return std::fabs(f - std::round(f)) < 1e-9 ? std::round(f) : f;
}

// --- Abundance and material index ---------------------------------------------------------

TEST(Truth, AbundanceIsTheCoveredAreaFractionAndTheMaterialIndexItsMajority) {
    // Material a everywhere but on two 1 mm slabs of b: "east" (x ≥ 0, y ≤ 0.26 m) starts on
    // the boundary between columns 3 and 4 and ends 0.3 of the way up row 2; "west" (x ≤
    // −0.45 m) covers column 0 and 0.75 of column 1. The slab tops are 1 mm up: their edges
    // move by 1e-6 of their distance from nadir (< 1 µm), nothing against a 0.2 m pixel.
    test::TempDir dir;
    write_simulation(
        dir.path(), R"(materials:
  - {id: a, reflectance: {wavelengths: [0.3, 1.0], values: [0.2, 0.2]}}
  - {id: b, reflectance: {wavelengths: [0.3, 1.0], values: [0.6, 0.6]}}
objects:
  - {name: ground, primitive: ground_plane, material: a}
  - {name: east, primitive: box, material: b, lower: [0, -1000, 0], upper: [1000, 0.26, 0.001]}
  - {name: west, primitive: box, material: b, lower: [-1000, -1000, 0], upper: [-0.45, 1000, 0.001]}
)",
        truth_collection("T", "t", collector("Material") + collector("Abundance", "a,b")));
    constexpr std::uint64_t kSamples = 4096;
    const Rendered r = render_into(dir.path(), {kSamples, kSamples, 0.0});
    ASSERT_EQ(r.truth.header.bands, 3u);
    std::size_t partial = 0;
    for (std::size_t row = 0; row < kSide; ++row) {
        for (std::size_t column = 0; column < kSide; ++column) {
            const double f = covered(column, row, 0.0, 1000.0, -1000.0, 0.26) +
                             covered(column, row, -1000.0, -0.45, -1000.0, 1000.0);
            const double a = r.truth.at("Material Abundance 'a'", column, row);
            const double b = r.truth.at("Material Abundance 'b'", column, row);
            // Every sample hits a or b: the two fractions are k/N and (N − k)/N.
            EXPECT_NEAR(a + b, 1.0, 1e-12) << column << ", " << row;
            if (f == 0.0 || f == 1.0) {
                // Wholly on one side (the x = 0 edge is a pixel boundary): no sample strays.
                EXPECT_EQ(b, f) << column << ", " << row;
            } else {
                // Binomial: standard error √(f(1 − f)/N) (0.0072 for f = 0.3, 0.0068 for 0.75
                // at N = 4096); 4 standard errors fail with probability 6e-5 (fixed seed).
                ++partial;
                EXPECT_NEAR(b, f, 4.0 * std::sqrt(f * (1.0 - f) / kSamples))
                    << column << ", " << row << " covered " << f;
            }
            // The majority material (scene order: a = 0, b = 1); f is 0.3 or 0.75, at least
            // 28 standard errors from 0.5.
            EXPECT_EQ(r.truth.at("Material Index", column, row), f > 0.5 ? 1.0 : 0.0)
                << column << ", " << row;
        }
    }
    EXPECT_EQ(partial, 4u + 8u) << "row 2 of columns 4–7 and column 1";
    EXPECT_EQ(r.truth.header.find_extra("glint material ids"), "{a, b}");
}

TEST(Truth, APixelThatSeesNothingHasNoAbundanceAndNaNFirstHitQuantities) {
    // A 0.8 m ground square under the middle 4 × 4 pixels (its edges on pixel boundaries),
    // nothing elsewhere: the outer pixels' samples all leave the scene downwards (radiance 0).
    test::TempDir dir;
    write_simulation(dir.path(), R"(materials:
  - {id: a, reflectance: {wavelengths: [0.3, 1.0], values: [0.2, 0.2]}}
objects:
  - {name: ground, primitive: ground_plane, material: a, size: 0.8}
)",
                     truth_collection("T", "t",
                                      collector("Material") + collector("Abundance", "a") +
                                          collector("Intersection") + collector("Shadow") +
                                          collector("SampleCount") + collector("StandardError")));
    const Rendered r = render_into(dir.path(), {16, 16, 0.0});
    for (std::size_t row = 0; row < kSide; ++row) {
        for (std::size_t column = 0; column < kSide; ++column) {
            const bool inside = column >= 2 && column <= 5 && row >= 2 && row <= 5;
            EXPECT_EQ(r.truth.at("Material Abundance 'a'", column, row), inside ? 1.0 : 0.0);
            EXPECT_EQ(r.truth.at("Sample Count", column, row), 16.0);
            for (const char* band :
                 {"Material Index", "Scene X", "Normal Z", "Distance", "Shadow Fraction"}) {
                EXPECT_EQ(std::isnan(r.truth.at(band, column, row)), !inside)
                    << band << " at " << column << ", " << row;
            }
            if (!inside) {
                EXPECT_EQ(r.radiance(column, row), 0.0);
                EXPECT_EQ(r.truth.at("Standard Error 'Green'", column, row), 0.0);
            }
        }
    }
    EXPECT_EQ(r.truth.header.find_extra("data ignore value"), "NaN");
}

// --- Geolocation and distance --------------------------------------------------------------

constexpr double kPlate_m = 20.0;  // height of the plate that fills the view

/// Samples per pixel of the plate renders.
constexpr std::uint64_t kPlateSamples = 1024;

/// A plate render and where each pixel's centre lands on the plate (pixel after pixel).
struct PlateRender {
    Rendered rendered;
    std::vector<motion::Vec3> centres;
};

/// Renders a 100 m plate of material b, kPlate_m high, on a ground plane of a, collecting
/// `collectors` (kPlateSamples per pixel); the centres come from the camera model and the
/// pose that the render uses (prepare()).
PlateRender render_plate(const fs::path& dir, const std::string& collectors) {
    write_simulation(dir,
                     R"(materials:
  - {id: a, reflectance: {wavelengths: [0.3, 1.0], values: [0.2, 0.2]}}
  - {id: b, reflectance: {wavelengths: [0.3, 1.0], values: [0.5, 0.5]}}
objects:
  - {name: ground, primitive: ground_plane, material: a}
  - {name: plate, primitive: box, material: b, lower: [-50, -50, 0], upper: [50, 50, )" +
                         format_shortest(kPlate_m) + "]}\n",
                     truth_collection("T", "t", collectors));
    PlateRender plate;
    const auto prepared =
        detail::prepare(load(dir / "one.jsim"), options_into(dir / "prep"), Context{});
    const CameraModel& camera = prepared->states.at(0).camera;
    const schedule::PluginSchedule& plugin = prepared->inputs.schedule->plugins().at(0);
    const std::size_t instrument = prepared->inputs.schedule->sources().at(0).instrument_index;
    const motion::Rigid pose = plugin.poses->instrument_to_scene(instrument, 0.0);
    const motion::Vec3 origin = motion::apply_point(pose, {});
    for (std::size_t row = 0; row < kSide; ++row) {
        for (std::size_t column = 0; column < kSide; ++column) {
            const motion::Vec3 d = motion::apply_direction(
                pose, camera.direction(camera.focal_plane_point(column, row, 0.5, 0.5)));
            const double t = (kPlate_m - origin.z) / d.z;
            plate.centres.push_back({origin.x + t * d.x, origin.y + t * d.y, origin.z + t * d.z});
        }
    }
    plate.rendered = render_into(dir, {kPlateSamples, kPlateSamples, 0.0});
    return plate;
}

TEST(Truth, GeoLocationIsTheCameraModelsProjectionOfThePixelCentre) {
    // On a plane parallel to the focal plane a nadir pinhole maps the element linearly, so
    // the mean of uniformly drawn element points is the projection of the element centre.
    test::TempDir dir;
    const PlateRender plate = render_plate(dir.path(), collector("GeoLocation"));
    const Rendered& r = plate.rendered;
    ASSERT_EQ(r.truth.header.bands, 6u);

    // WGS84, for the independent conversion below.
    constexpr double kA = 6378137.0;
    constexpr double kF = 1.0 / 298.257223563;
    constexpr double kE2 = kF * (2.0 - kF);
    constexpr double kDeg = 3.14159265358979323846 / 180.0;
    const double lat0 = 43.0 * kDeg;
    const double w = std::sqrt(1.0 - kE2 * std::sin(lat0) * std::sin(lat0));
    const double meridian = kA * (1.0 - kE2) / (w * w * w);  // M
    const double normal = kA / w;                            // N
    constexpr double kH0 = 150.0;

    // The footprint of a pixel on the plate is 0.2 × 0.98 = 0.196 m square: one sample's
    // point spreads 0.196/√12 = 57 mm per axis about the centre, the mean of 1024 by 1.8 mm;
    // 1 cm is 5.6 of those (probability 3e-8 per value, 128 values, fixed seed).
    constexpr double kPosition_m = 0.01;
    for (std::size_t row = 0; row < kSide; ++row) {
        for (std::size_t column = 0; column < kSide; ++column) {
            const motion::Vec3& c = plate.centres[row * kSide + column];
            // The camera model is the closed form of camera.h for this camera.
            const double scale = (kCamera_m - kPlate_m) / kCamera_m * kPixel_m;
            ASSERT_NEAR(c.x, (static_cast<double>(column) - 3.5) * scale, 1e-9);
            ASSERT_NEAR(c.y, (3.5 - static_cast<double>(row)) * scale, 1e-9);
            const double x = r.truth.at("Scene X", column, row);
            const double y = r.truth.at("Scene Y", column, row);
            const double z = r.truth.at("Scene Z", column, row);
            EXPECT_NEAR(x, c.x, kPosition_m) << column << ", " << row;
            EXPECT_NEAR(y, c.y, kPosition_m) << column << ", " << row;
            // Every hit is on the plate's top: z is exact but for Embree's float32 hit
            // distance (ulp(980 m) = 61 µm).
            EXPECT_NEAR(z, kPlate_m, 1e-3) << column << ", " << row;

            // Latitude, longitude and altitude of the truth's own scene point, from the ENU
            // frame's definition (up = the ellipsoid normal at the origin): to first order
            // a step north y turns the normal by y / (M + h), a step east x by x / ((N + h)
            // cos φ0), and the tangent plane rises above the ellipsoid by x²/2N + y²/2M. The
            // second-order terms neglected are ~(1 m / 6.4e6 m)² rad; the tolerances (1e-8°
            // ≈ 1 mm, 1 mm) are the frame conversions' accuracy (< 1 mm against
            // GeographicLib, VALIDATION.md).
            const double h = kH0 + z;
            EXPECT_NEAR(r.truth.at("Latitude", column, row), 43.0 + y / (meridian + h) / kDeg,
                        1e-8);
            EXPECT_NEAR(r.truth.at("Longitude", column, row),
                        -77.6 + x / ((normal + h) * std::cos(lat0)) / kDeg, 1e-8);
            EXPECT_NEAR(r.truth.at("Altitude", column, row),
                        h + 0.5 * (x * x / normal + y * y / meridian), 1e-3);
        }
    }
}

TEST(Truth, DistanceIsTheGeometricRangeToTheMeanHitPoint) {
    test::TempDir dir;
    const PlateRender plate = render_plate(dir.path(), collector("Intersection"));
    const Rendered& r = plate.rendered;
    ASSERT_EQ(r.truth.header.bands, 7u);
    constexpr double kDepth_m = kCamera_m - kPlate_m;
    constexpr double kSide_m = kPixel_m * kDepth_m / kCamera_m;  // the footprint on the plate
    for (std::size_t row = 0; row < kSide; ++row) {
        for (std::size_t column = 0; column < kSide; ++column) {
            const double x = r.truth.at("Scene X", column, row);
            const double y = r.truth.at("Scene Y", column, row);
            const double z = r.truth.at("Scene Z", column, row);
            const double distance = r.truth.at("Distance", column, row);
            // (a) The range of the mean hit point from the camera (0, 0, 1000). The mean of
            // the ranges exceeds it by Var(point)/2R = 2 × (0.057 m)²/(2 × 980 m) = 3e-6 m
            // (3e-9 relative, Jensen); Embree's float32 hit distance is good to ~1e-7
            // relative: 1e-6 relative bounds both with margin.
            const double range = std::sqrt(x * x + y * y + (kCamera_m - z) * (kCamera_m - z));
            EXPECT_NEAR(distance / range, 1.0, 1e-6) << column << ", " << row;
            // (b) The analytic mean of the range over the element's footprint (the mean of
            // √(D² + x² + y²) over the 0.196 m square about the projected centre; midpoint
            // rule, 64 × 64). The range varies across a pixel by at most (1.1 m / 980 m) ×
            // 0.196 m = 0.2 mm, so the Monte-Carlo mean of 1024 samples is within ~2e-6 m
            // (2e-9 relative) of it; 1e-6 relative again leaves room for float32.
            const motion::Vec3& c = plate.centres[row * kSide + column];
            double sum = 0.0;
            constexpr int kSteps = 64;
            for (int a = 0; a < kSteps; ++a) {
                for (int b = 0; b < kSteps; ++b) {
                    const double px = c.x + ((a + 0.5) / kSteps - 0.5) * kSide_m;
                    const double py = c.y + ((b + 0.5) / kSteps - 0.5) * kSide_m;
                    sum += std::sqrt(kDepth_m * kDepth_m + px * px + py * py);
                }
            }
            const double mean = sum / (kSteps * kSteps);
            EXPECT_NEAR(distance / mean, 1.0, 1e-6) << column << ", " << row;
            // A flat plate facing the camera: the normal is +Z.
            EXPECT_NEAR(r.truth.at("Normal X", column, row), 0.0, 1e-12);
            EXPECT_NEAR(r.truth.at("Normal Y", column, row), 0.0, 1e-12);
            EXPECT_NEAR(r.truth.at("Normal Z", column, row), 1.0, 1e-12);
        }
    }
}

// --- Shadow ----------------------------------------------------------------------------------

TEST(Truth, ShadowFractionIsTheShareOfThePixelTheSunDoesNotLight) {
    // A wall along x (y ∈ [−1.1, −1.0] m, south of the view) of the height that puts the
    // edge of its shadow on the ground at y = 0.1 m, the centre line of row 3: rows 4–7 lie
    // in its shadow, rows 0–2 in the sun, row 3 half and half. The ground is black for x < 0
    // (the first hit's shadow ray is traced for truth alone) and grey for x ≥ 0 (the
    // radiance's own shadow ray), two boxes whose tops are at z = 0.
    const motion::SunPosition sun = motion::sun_position(
        parse_iso8601("2020-06-21T12:00:00.0000-04:00"), motion::SceneFrame(43.0, -77.6, 150.0));
    const motion::Vec3 s = sun.direction_enu;
    ASSERT_LT(s.y, -0.1) << "the sun must be to the south";
    ASSERT_GT(s.z, 0.1);
    // A ground point at y sees the wall's north face (y = −1) at height (y + 1) s_z / −s_y.
    constexpr double kEdge_m = 0.1;
    const double wall_m = (kEdge_m + 1.0) * s.z / -s.y;
    test::TempDir dir;
    write_simulation(dir.path(),
                     R"(materials:
  - {id: black, reflectance: {wavelengths: [0.3, 1.0], values: [0, 0]}}
  - {id: grey, reflectance: {wavelengths: [0.3, 1.0], values: [0.3, 0.3]}}
objects:
  - {name: west, primitive: box, material: black, lower: [-1000, -1000, -1], upper: [0, 1000, 0]}
  - {name: east, primitive: box, material: grey, lower: [0, -1000, -1], upper: [1000, 1000, 0]}
  - {name: wall, primitive: box, material: grey, lower: [-1000, -1.1, 0], upper: [1000, -1.0, )" +
                         format_shortest(wall_m) + "]}\n",
                     truth_collection("T", "t", collector("Shadow")));
    // Row 3's shadow fraction is binomial with p = 0.5: standard error 0.5/√N = 0.005 for
    // N = 10000, so 0.02 is 4 standard errors. The sun's disc (0.27° radius) blurs the edge
    // symmetrically about it (the share of the disc behind the wall's top edge), over
    // ±(h / sin²α) × 0.0049 rad ≈ ±18 mm for the sun's elevation seen along x, α ≈ 72°, and a
    // wall h ≈ 3.3 m high: no bias at row 3, and rows 2 and 4 (whose nearest points are
    // 0.1 m from the edge) are wholly lit or shadowed.
    constexpr std::uint64_t kSamples = 10000;
    const Rendered r = render_into(dir.path(), {kSamples, kSamples, 0.0});
    double row_sum = 0.0;
    for (std::size_t row = 0; row < kSide; ++row) {
        for (std::size_t column = 0; column < kSide; ++column) {
            const double shadow = r.truth.at("Shadow Fraction", column, row);
            if (row < 3) {
                EXPECT_EQ(shadow, 0.0) << column << ", " << row;
            } else if (row > 3) {
                EXPECT_EQ(shadow, 1.0) << column << ", " << row;
            } else {
                EXPECT_NEAR(shadow, 0.5, 0.02) << column << ", " << row;
                row_sum += shadow;
            }
        }
    }
    // The mean of row 3's 8 pixels has a standard error of 0.5/√80000 = 0.0018: a bias of
    // the edge (a shifted or lopsided penumbra) larger than 4 of those would show here.
    EXPECT_NEAR(row_sum / kSide, 0.5, 4.0 * 0.5 / std::sqrt(kSide * kSamples));
}

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

}  // namespace
}  // namespace glint::sensor
