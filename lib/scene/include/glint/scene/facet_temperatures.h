// SPDX-License-Identifier: Apache-2.0
// Surface temperatures that vary over a facet and in time (THERM's, glint/thermal/therm.h):
// each facet (instance, triangle) is cut into n² cells of equal area along its barycentric
// coordinates, each cell holding its temperature at a common ascending list of times; a hit
// is looked up by its facet, its barycentrics (u, v) and its ray's time, linear between the
// times and held beyond them. Filled once before rendering; read from any thread.
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

    /// The cells of a facet cut `n` times along each edge: cell (i, j) with u in [i/n,
    /// (i+1)/n) and v in [j/n, (j+1)/n), `upper` the one of the pair whose corner is at
    /// ((i+1)/n, (j+1)/n) (i + j < n − 1), else the one at (i/n, j/n).
    static std::size_t cell_index(std::size_t n, std::size_t i, std::size_t j,
                                  bool upper) noexcept {
        return 2 * (i * n + j) + (upper ? 1 : 0);
    }
    /// The cell of barycentrics (u, v) (u, v ≥ 0, u + v ≤ 1) in a facet cut `n` times.
    static std::size_t cell_at(std::size_t n, double u, double v) noexcept;
    /// The cell slots of a facet cut `n` times (2n², of which n² are cells).
    static std::size_t cell_slots(std::size_t n) noexcept { return 2 * n * n; }

    /// The temperatures of a facet cut `n` times, K: [cell slot][time] (cell_slots(n) × the
    /// times; unused slots anything). Throws glint::Error (internal) for a wrong count or a
    /// facet given twice.
    void add(std::uint32_t instance, std::uint32_t triangle, std::size_t n,
             std::span<const double> kelvin);

    /// The temperature at barycentrics (u, v) of the facet at `time_s`, K; 0 when the facet
    /// has none.
    double at(std::uint32_t instance, std::uint32_t triangle, double u, double v,
              double time_s) const noexcept;

    std::size_t facets() const noexcept { return m_facets.size(); }
    std::span<const double> times_s() const noexcept { return m_times; }

private:
    struct Entry {
        std::size_t first = 0;  ///< into m_kelvin
        std::size_t n = 1;
    };
    static std::uint64_t key(std::uint32_t instance, std::uint32_t triangle) noexcept {
        return (std::uint64_t{instance} << 32) | triangle;
    }
    std::vector<double> m_times;
    std::unordered_map<std::uint64_t, Entry> m_facets;
    std::vector<float> m_kelvin;  ///< per facet: [cell slot][time]
};

}  // namespace glint::scene
