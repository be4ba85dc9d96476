// SPDX-License-Identifier: Apache-2.0
// Facet temperatures over cells and time (glint/scene/facet_temperatures.h).
#include "glint/scene/facet_temperatures.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "glint/core/error.h"

namespace glint::scene {

FacetTemperatures::FacetTemperatures(std::vector<double> times_s) : m_times(std::move(times_s)) {
    if (m_times.empty() || !std::is_sorted(m_times.begin(), m_times.end())) {
        throw internal_error("facet temperatures need ascending times");
    }
}

std::size_t FacetTemperatures::cell_at(std::size_t n, double u, double v) noexcept {
    const double a = std::max(u, 0.0) * static_cast<double>(n);
    const double b = std::max(v, 0.0) * static_cast<double>(n);
    const std::size_t i = std::min(static_cast<std::size_t>(a), n - 1);
    const std::size_t j = std::min(static_cast<std::size_t>(b), n - 1 - i);
    const bool upper =
        i + j < n - 1 && (a - static_cast<double>(i)) + (b - static_cast<double>(j)) > 1.0;
    return cell_index(n, i, j, upper);
}

void FacetTemperatures::add(std::uint32_t instance, std::uint32_t triangle, std::size_t n,
                            std::span<const double> kelvin) {
    if (n < 1 || kelvin.size() != cell_slots(n) * m_times.size()) {
        throw internal_error("facet temperatures: " + std::to_string(kelvin.size()) +
                             " values for " + std::to_string(cell_slots(n)) + " cell slots × " +
                             std::to_string(m_times.size()) + " times");
    }
    if (!m_facets.emplace(key(instance, triangle), Entry{m_kelvin.size(), n}).second) {
        throw internal_error("facet temperatures: a facet given twice");
    }
    for (double k : kelvin) m_kelvin.push_back(static_cast<float>(k));
}

double FacetTemperatures::at(std::uint32_t instance, std::uint32_t triangle, double u, double v,
                             double time_s) const noexcept {
    const auto it = m_facets.find(key(instance, triangle));
    if (it == m_facets.end()) return 0.0;
    const std::size_t cell = cell_at(it->second.n, u, v);
    const float* row = m_kelvin.data() + it->second.first + cell * m_times.size();
    if (m_times.size() == 1 || !(time_s > m_times.front())) return row[0];
    if (!(time_s < m_times.back())) return row[m_times.size() - 1];
    const auto after = std::upper_bound(m_times.begin(), m_times.end(), time_s);
    const auto i = static_cast<std::size_t>(after - m_times.begin());
    const double f = (time_s - m_times[i - 1]) / (m_times[i] - m_times[i - 1]);
    return (1.0 - f) * double{row[i - 1]} + f * double{row[i]};
}

}  // namespace glint::scene
