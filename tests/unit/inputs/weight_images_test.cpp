// SPDX-License-Identifier: Apache-2.0
// read_weight_image and read_weight_images (glint/inputs/load.h): the PSF and active-area
// images a platform names, read with the platform so that glint-render and
// glint-platform2jsim --check refuse the same images with the same messages.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "glint/inputs/load.h"
#include "glint/io/image.h"
#include "glint/test/temp_dir.h"

namespace glint::inputs {
namespace weight_images_test {

/// Every diagnostic's text, one per line.
std::string all_text(const Diagnostics& diagnostics) {
    std::string text;
    for (const Diagnostic& d : diagnostics.items()) text += d.text() + "\n";
    return text;
}

TEST(WeightImages, AnImageIsReadAsWeightsOrRefusedAtTheElement) {
    const test::TempDir dir;
    const model::FileRef ref{"mask.png", dir / "mask.png", ErrorContext{"cam.platform", 9, {}}};
    const ErrorContext where{"cam.platform", 12, "activearea"};
    Diagnostics missing;
    EXPECT_FALSE(read_weight_image(ref, "<activearea><image>", where, 1.0, missing));
    ASSERT_EQ(missing.error_count(), 1u);
    EXPECT_NE(all_text(missing).find("cam.platform:12: activearea: <activearea><image> "
                                     "\"mask.png\": "),
              std::string::npos)
        << all_text(missing);

    io::write_image(ref.resolved, 2, 1, 1, std::vector<double>{0, 0}, {});
    Diagnostics dark;
    EXPECT_FALSE(read_weight_image(ref, "<activearea><image>", where, 1.0, dark));
    EXPECT_NE(all_text(dark).find("\"mask.png\": the image is all zero"), std::string::npos)
        << all_text(dark);

    // An 8-bit image: 255 is unity, 0 blind.
    io::write_image(ref.resolved, 2, 1, 1, std::vector<double>{255, 0}, {});
    Diagnostics fine;
    const std::optional<model::WeightImage> mask =
        read_weight_image(ref, "<activearea><image>", where, 1.0, fine);
    EXPECT_EQ(fine.error_count(), 0u);
    ASSERT_TRUE(mask);
    EXPECT_EQ(mask->width, 2u);
    EXPECT_EQ(mask->height, 1u);
    EXPECT_EQ(mask->values, (std::vector<double>{1.0, 0.0}));
}

TEST(WeightImages, EveryEnabledFocalPlanesPsfAndMaskAreRead) {
    const test::TempDir dir;
    io::write_image(dir / "psf.png", 2, 2, 1, std::vector<double>{0, 255, 0, 0}, {});
    model::Platform platform;
    platform.attachments.emplace_back();
    model::Instrument& instrument = platform.attachments.back().instruments.emplace_back();
    for (const bool enabled : {true, false}) {
        model::FocalPlane& plane = instrument.focal_planes.emplace_back();
        plane.enabled = enabled;
        model::Psf psf;
        psf.image = model::FileRef{"psf.png", dir / "psf.png", {}};
        psf.scale_px = 3.0;
        plane.capture_method.psf = psf;
        plane.capture_method.active_area_image = psf.image;
    }
    Diagnostics diagnostics;
    read_weight_images(platform, diagnostics);
    EXPECT_EQ(diagnostics.error_count(), 0u) << all_text(diagnostics);
    const model::CaptureMethod& read = instrument.focal_planes[0].capture_method;
    EXPECT_EQ(read.psf->weights.values, (std::vector<double>{0, 1, 0, 0}));
    EXPECT_EQ(read.active_area.values, (std::vector<double>{0, 1, 0, 0}));
    const model::CaptureMethod& disabled = instrument.focal_planes[1].capture_method;
    EXPECT_TRUE(disabled.psf->weights.empty()) << "a disabled focal plane is not rendered";
    EXPECT_TRUE(disabled.active_area.empty());
}

}  // namespace weight_images_test
}  // namespace glint::inputs
