// SPDX-License-Identifier: Apache-2.0
// A focal plane's active-area mask (the BasicPlatform manual's "Active Area Mask",
// docs/camera.md §8): a grey image of one pixel's element giving its relative sensitivity,
// 0 (black) insensitive to 1 (white, 255 in 8 bits), line 0 at the top of the element
// (v = 0), column 0 at its left (u = 0). It replaces the uniform draw of (u, v) over the
// element by importance sampling of the mask (PixelTable), and each pixel's response is
// multiplied by the mask's mean sensitivity: a half-masked pixel collects half the flux of an
// unmasked one, where an unweighted importance draw alone would only move where it looks.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "glint/model/capture.h"
#include "glint/model/common.h"
#include "glint/sensor/pixel_table.h"

namespace glint::sensor {

class ActiveArea {
public:
    /// From the mask's values in [0, 1]. Throws glint::Error (input, no context) with
    /// io::weight_image_problem's message (maximum 1) otherwise.
    explicit ActiveArea(const GreyImage& mask, std::string name = "mask");
    /// The mask an <activearea><image> names, from its values (CaptureMethod::active_area,
    /// read with the platform by glint/inputs/load.h). Throws glint::Error (input, at the
    /// element) for values the constructor refuses, (internal) when the image was not read.
    static ActiveArea from_model(const model::FileRef& image, const model::WeightImage& mask);

    /// The element point (u, v) ∈ [0, 1]² for two uniforms, its density proportional to the
    /// mask.
    std::array<double, 2> point(double r1, double r2) const noexcept;
    /// The mask's mean over the element, in (0, 1]: the factor on the pixel's response.
    double mean_sensitivity() const noexcept { return m_mean; }
    /// The mask's value at the element point (u, v) ∈ [0, 1)² (the mask pixel holding it).
    double sensitivity(double u, double v) const noexcept;
    /// "mask.png 32 x 32, mean sensitivity 0.5", for headers and logs.
    const std::string& description() const noexcept { return m_description; }

private:
    PixelTable m_table;
    std::vector<double> m_values;  ///< the mask, row-major, line 0 at v = 0
    double m_mean = 1.0;
    std::string m_description;
};

}  // namespace glint::sensor
