// SPDX-License-Identifier: Apache-2.0
// The scenes, camera and readers of the truth tests (truth_test.cpp,
// truth_convergence_test.cpp). Every case renders cam.platform's camera (tests/data/render: nadir,
// 1000 m up, focal length 100 mm, 20 µm pixels: 0.2 m on the ground at z = 0) as an 8 × 8 array
// over a scene written here, at capture 0 of three.tasks (2020-06-21 12:00 EDT at 43° N, 77.6° W),
// with no atmosphere and a black sky. Pixel (column i, row j) sees the ground square x ∈ [i − 4, i
// − 3] × 0.2 m, y ∈ [3 − j, 4 − j] × 0.2 m (camera.h: columns grow towards +X, rows towards −Y).
// The samples of a pixel are uniform over its element (independent u, v), so a fraction f of the
// pixel is hit with probability f by each sample: a binomial count.
#pragma once

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

#include "../../../lib/render/src/render_parts.h"
#include "glint/core/datetime.h"
#include "glint/core/text.h"
#include "glint/io/envi.h"
#include "glint/motion/frames.h"
#include "glint/motion/sun.h"
#include "glint/render/render.h"
#include "glint/test/temp_dir.h"
#include "render_fixture.h"

namespace glint::render::test_truth {

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
inline void write_simulation(const fs::path& dir, const std::string& scene,
                             const std::string& truth, const std::string& channels = {}) {
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
inline std::string truth_collection(const std::string& name, const std::string& basename,
                                    const std::string& collectors) {
    return "<truthcollection><name>" + name + "</name><imagefile><basename>" + basename +
           "</basename><extension>img</extension><schedule>simulation</schedule></imagefile>"
           "<collectorlist>" +
           collectors + "</collectorlist></truthcollection>";
}

/// One `<collector>`, with `<materials>` when given.
inline std::string collector(const std::string& name, const std::string& materials = {}) {
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

inline std::vector<char> read_bytes(const fs::path& path) {
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
inline Rendered render_into(const fs::path& dir, radiometry::Convergence convergence,
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
inline double covered(std::size_t column, std::size_t row, double x0, double x1, double y0,
                      double y1) {
    const double px0 = (static_cast<double>(column) - 4.0) * kPixel_m;
    const double py0 = (3.0 - static_cast<double>(row)) * kPixel_m;
    const double wx = std::max(0.0, std::min(x1, px0 + kPixel_m) - std::max(x0, px0));
    const double wy = std::max(0.0, std::min(y1, py0 + kPixel_m) - std::max(y0, py0));
    const double f = wx * wy / (kPixel_m * kPixel_m);
    // Snap the rounding of the products above (1 + 2e-16) to the exact 0 and 1 they are.
    return std::fabs(f - std::round(f)) < 1e-9 ? std::round(f) : f;
}

}  // namespace glint::render::test_truth
