// SPDX-License-Identifier: Apache-2.0
// Facet temperatures over time (glint/scene/facet_temperatures.h).
#include "glint/scene/facet_temperatures.h"

#include <algorithm>
#include <string>

#include "glint/core/error.h"

namespace glint::scene {

FacetTemperatures::FacetTemperatures(std::vector<double> times_s) : m_times(std::move(times_s)) {
    if (m_times.empty() || !std::is_sorted(m_times.begin(), m_times.end())) {
        throw internal_error("facet temperatures need ascending times");
    }
}

void FacetTemperatures::add(std::uint32_t instance, std::uint32_t triangle,
                            std::span<const double> kelvin) {
    if (kelvin.size() != m_times.size()) {
        throw internal_error("facet temperatures: " + std::to_string(kelvin.size()) +
                             " values for " + std::to_string(m_times.size()) + " times");
    }
    const auto row = static_cast<std::uint32_t>(m_rows.size());
    if (!m_rows.emplace(key(instance, triangle), row).second) {
        throw internal_error("facet temperatures: a facet given twice");
    }
    for (double k : kelvin) m_kelvin.push_back(static_cast<float>(k));
}

double FacetTemperatures::at(std::uint32_t instance, std::uint32_t triangle,
                             double time_s) const noexcept {
    const auto it = m_rows.find(key(instance, triangle));
    if (it == m_rows.end()) return 0.0;
    const float* row = m_kelvin.data() + std::size_t{it->second} * m_times.size();
    if (m_times.size() == 1 || !(time_s > m_times.front())) return row[0];
    if (!(time_s < m_times.back())) return row[m_times.size() - 1];
    const auto after = std::upper_bound(m_times.begin(), m_times.end(), time_s);
    const auto i = static_cast<std::size_t>(after - m_times.begin());
    const double f = (time_s - m_times[i - 1]) / (m_times[i] - m_times[i - 1]);
    return (1.0 - f) * double{row[i - 1]} + f * double{row[i]};
}

}  // namespace glint::scene
