// SPDX-License-Identifier: Apache-2.0
// Surface temperatures that vary by facet and time (THERM's, glint/thermal/therm.h): one row
// of temperatures per facet (instance, triangle) at a common ascending list of times, looked
// up by a hit's facet and its ray's time, linear between the times and held beyond them.
// Filled once before rendering; read from any thread.
#pragma once

#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

namespace glint::scene {

class FacetTemperatures {
public:
    /// Temperatures will be given at `times_s` (ascending, in the rays' clock).
    explicit FacetTemperatures(std::vector<double> times_s);

    /// The temperatures of one facet at every time, K (one per time). Throws glint::Error
    /// (internal) for a wrong count or a facet given twice.
    void add(std::uint32_t instance, std::uint32_t triangle, std::span<const double> kelvin);

    /// The facet's temperature at `time_s`, K; 0 when the facet has none.
    double at(std::uint32_t instance, std::uint32_t triangle, double time_s) const noexcept;

    std::size_t facets() const noexcept { return m_rows.size(); }
    std::span<const double> times_s() const noexcept { return m_times; }

private:
    static std::uint64_t key(std::uint32_t instance, std::uint32_t triangle) noexcept {
        return (std::uint64_t{instance} << 32) | triangle;
    }
    std::vector<double> m_times;
    std::unordered_map<std::uint64_t, std::uint32_t> m_rows;
    std::vector<float> m_kelvin;  ///< [row][time]
};

}  // namespace glint::scene
