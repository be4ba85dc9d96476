// SPDX-License-Identifier: Apache-2.0
// ActiveArea: the importance draw over a pixel mask and its mean sensitivity (active_area.h).
#include "glint/sensor/active_area.h"

#include <algorithm>
#include <numeric>
#include <utility>

#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::sensor {
namespace {

const GreyImage& checked(const GreyImage& mask) {
    if (const auto problem = io::weight_image_problem(mask, 1.0)) throw input_error(*problem);
    return mask;
}

}  // namespace

ActiveArea::ActiveArea(const GreyImage& mask, std::string name)
    : m_table(checked(mask).values, mask.width, mask.height), m_values(mask.values) {
    m_mean = std::accumulate(mask.values.begin(), mask.values.end(), 0.0) /
             static_cast<double>(mask.values.size());
    m_description = std::move(name) + " " + std::to_string(mask.width) + " x " +
                    std::to_string(mask.height) + ", mean sensitivity " + format_shortest(m_mean);
}

ActiveArea ActiveArea::from_model(const model::FileRef& image, const model::WeightImage& mask) {
    if (mask.empty()) {
        throw internal_error(format_located(
            image.where, "<activearea><image> " + quote(image.text) + " was not read"));
    }
    try {
        return ActiveArea(GreyImage{mask.width, mask.height, mask.values}, image.text);
    } catch (const Error& e) {
        if (e.category() != ErrorCategory::input && e.category() != ErrorCategory::io) throw;
        throw input_error("<activearea><image> " + quote(image.text) + ": " + e.message(),
                          image.where);
    }
}

std::array<double, 2> ActiveArea::point(double r1, double r2) const noexcept {
    const std::array<double, 2> at = m_table.sample(r1, r2);
    return {at[0] / static_cast<double>(m_table.width()),
            at[1] / static_cast<double>(m_table.height())};
}

double ActiveArea::sensitivity(double u, double v) const noexcept {
    const std::size_t width = m_table.width();
    const std::size_t height = m_table.height();
    const auto column = std::min(
        width - 1, static_cast<std::size_t>(std::max(u, 0.0) * static_cast<double>(width)));
    const auto line = std::min(
        height - 1, static_cast<std::size_t>(std::max(v, 0.0) * static_cast<double>(height)));
    return m_values[line * width + column];
}

}  // namespace glint::sensor
