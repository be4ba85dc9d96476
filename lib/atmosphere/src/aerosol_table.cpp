// SPDX-License-Identifier: Apache-2.0
// The aerosol components' optics table and its interpolation (glint/atmosphere/aerosol_table.h).
#include "glint/atmosphere/aerosol_table.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::atmosphere {

namespace {

constexpr std::size_t kLeadingColumns = 7;  // component … particle_mass_g

/// a + t (b − a) for every element.
void blend(std::vector<double>& a, const std::vector<double>& b, double t) {
    for (std::size_t i = 0; i < a.size(); ++i) a[i] += t * (b[i] - a[i]);
}

}  // namespace

ComponentOptics interpolate(const ComponentOptics& a, const ComponentOptics& b, double t,
                            bool log_cross_sections) {
    ComponentOptics out = a;
    if (t == 0.0) return out;
    auto mix = [&](double x, double y) {
        if (log_cross_sections && x > 0.0 && y > 0.0) {
            return std::exp((1.0 - t) * std::log(x) + t * std::log(y));
        }
        return x + t * (y - x);
    };
    out.extinction_um2 = mix(a.extinction_um2, b.extinction_um2);
    out.particle_mass_g = a.particle_mass_g + t * (b.particle_mass_g - a.particle_mass_g);
    out.scattering_um2 = std::min(mix(a.scattering_um2, b.scattering_um2), out.extinction_um2);
    blend(out.moments, b.moments, t);
    blend(out.phase, b.phase, t);
    return out;
}

AerosolTable AerosolTable::from_csv(const std::string& text, const std::string& file) {
    AerosolTable out;
    std::size_t moments = 0;
    bool header = false;
    int line_number = 0;
    for (const std::string_view line : split_lines(text)) {
        ++line_number;
        if (line.empty() || line.front() == '#') continue;
        const ErrorContext where{file, line_number, {}};
        const std::vector<std::string> fields = split_list(line, ',');
        if (!header) {
            if (fields.size() < kLeadingColumns || fields[0] != "component" ||
                fields[kLeadingColumns - 1] != "particle_mass_g") {
                throw input_error(
                    "expected the header line component,rh_percent,wavelength_um,"
                    "extinction_um2,scattering_um2,asymmetry,particle_mass_g,...",
                    where);
            }
            for (std::size_t i = kLeadingColumns; i < fields.size(); ++i) {
                if (fields[i].starts_with("chi_")) {
                    if (fields[i] != "chi_" + std::to_string(moments + 1)) {
                        throw input_error("expected column chi_" + std::to_string(moments + 1) +
                                              ", found '" + fields[i] + "'",
                                          where);
                    }
                    ++moments;
                } else if (fields[i].starts_with("p_")) {
                    const auto angle = parse_double(fields[i].substr(2));
                    if (!angle || *angle < 0.0 || *angle > 180.0 ||
                        (!out.m_angles_deg.empty() && *angle <= out.m_angles_deg.back())) {
                        throw input_error("bad phase-function column '" + fields[i] +
                                              "' (angles in degrees, increasing in [0, 180])",
                                          where);
                    }
                    out.m_angles_deg.push_back(*angle);
                } else {
                    throw input_error("unknown column '" + fields[i] + "'", where);
                }
            }
            if (out.m_angles_deg.size() < 2 || out.m_angles_deg.front() != 0.0 ||
                out.m_angles_deg.back() != 180.0) {
                throw input_error("the phase function must be tabulated from 0 to 180 degrees",
                                  where);
            }
            out.m_moment_count = moments + 1;
            header = true;
            continue;
        }
        const std::size_t columns = kLeadingColumns + moments + out.m_angles_deg.size();
        if (fields.size() != columns) {
            throw input_error("expected " + std::to_string(columns) + " columns, found " +
                                  std::to_string(fields.size()),
                              where);
        }
        std::vector<double> values;
        for (std::size_t i = 1; i < fields.size(); ++i) {
            const auto v = parse_double(fields[i]);
            if (!v || !std::isfinite(*v)) {
                throw input_error("not a number: '" + fields[i] + "'", where);
            }
            values.push_back(*v);
        }
        Row row;
        row.wavelength_um = values[1];
        row.optics.extinction_um2 = values[2];
        row.optics.scattering_um2 = values[3];
        if (row.wavelength_um <= 0.0 || row.optics.scattering_um2 < 0.0 ||
            row.optics.scattering_um2 > row.optics.extinction_um2 * (1.0 + 1e-9)) {
            throw input_error("expected a wavelength > 0 and 0 <= scattering <= extinction", where);
        }
        row.optics.particle_mass_g = values[5];
        if (!(row.optics.particle_mass_g > 0.0)) {
            throw input_error("expected a particle mass > 0 g", where);
        }
        const auto first_moment = values.begin() + static_cast<std::ptrdiff_t>(kLeadingColumns - 1);
        row.optics.moments.push_back(1.0);
        row.optics.moments.insert(row.optics.moments.end(), first_moment,
                                  first_moment + static_cast<std::ptrdiff_t>(moments));
        row.optics.phase.assign(first_moment + static_cast<std::ptrdiff_t>(moments), values.end());
        for (double p : row.optics.phase) {
            if (p <= 0.0) throw input_error("phase-function values must be > 0", where);
        }
        const double rh = values[0];
        if (rh < 0.0 || rh > 100.0 || rh != std::round(rh)) {
            throw input_error("expected a humidity in whole percent 0-100", where);
        }
        std::vector<Row>& rows = out.m_components[fields[0]][static_cast<int>(rh)];
        if (!rows.empty() && row.wavelength_um <= rows.back().wavelength_um) {
            throw input_error("a component's wavelengths must increase", where);
        }
        rows.push_back(std::move(row));
    }
    if (out.m_components.empty()) {
        throw input_error("the aerosol optics table has no rows", {file, 0, {}});
    }
    for (const auto& [name, humidities] : out.m_components) {
        const std::vector<Row>& first = humidities.begin()->second;
        for (const auto& [rh, rows] : humidities) {
            bool same = rows.size() == first.size();
            for (std::size_t i = 0; same && i < rows.size(); ++i) {
                same = rows[i].wavelength_um == first[i].wavelength_um;
            }
            if (!same) {
                throw input_error("component " + name + " has different wavelengths at " +
                                      std::to_string(rh) + " % humidity",
                                  {file, 0, {}});
            }
        }
    }
    return out;
}

bool AerosolTable::has(std::string_view component) const {
    return m_components.find(component) != m_components.end();
}

std::vector<double> AerosolTable::wavelengths_um(std::string_view name) const {
    std::vector<double> out;
    for (const Row& r : component(name).begin()->second) out.push_back(r.wavelength_um);
    return out;
}

const std::map<int, std::vector<AerosolTable::Row>>& AerosolTable::component(
    std::string_view name) const {
    const auto found = m_components.find(name);
    if (found == m_components.end()) {
        throw input_error("the aerosol optics table has no component '" + std::string(name) + "'");
    }
    return found->second;
}

ComponentOptics AerosolTable::optics(std::string_view name, double wavelength_um,
                                     double rh_percent) const {
    const std::map<int, std::vector<Row>>& humidities = component(name);
    auto at_wavelength = [&](const std::vector<Row>& rows) {
        if (wavelength_um <= rows.front().wavelength_um) return rows.front().optics;
        if (wavelength_um >= rows.back().wavelength_um) return rows.back().optics;
        const auto above =
            std::upper_bound(rows.begin(), rows.end(), wavelength_um,
                             [](double w, const Row& r) { return w < r.wavelength_um; });
        const Row& hi = *above;
        const Row& lo = *(above - 1);
        const double t = std::log(wavelength_um / lo.wavelength_um) /
                         std::log(hi.wavelength_um / lo.wavelength_um);
        return interpolate(lo.optics, hi.optics, t, true);
    };
    const auto above = humidities.upper_bound(static_cast<int>(std::floor(rh_percent)));
    if (above == humidities.begin()) return at_wavelength(humidities.begin()->second);
    const auto below = std::prev(above);
    if (above == humidities.end() || rh_percent <= below->first) {
        return at_wavelength(below->second);
    }
    const double t = (rh_percent - below->first) / (above->first - below->first);
    return interpolate(at_wavelength(below->second), at_wavelength(above->second), t, false);
}

ComponentOptics AerosolTable::mixture(std::span<const MixtureShare> shares, double wavelength_um,
                                      double rh_percent) const {
    double total = 0.0;
    for (const MixtureShare& s : shares) total += s.number_per_cm3;
    if (shares.empty() || !(total > 0.0)) {
        throw input_error("an aerosol mixture needs at least one component with particles");
    }
    ComponentOptics out;
    out.moments.assign(m_moment_count, 0.0);
    out.phase.assign(m_angles_deg.size(), 0.0);
    for (const MixtureShare& s : shares) {
        const ComponentOptics c = optics(s.component, wavelength_um, rh_percent);
        const double f = s.number_per_cm3 / total;
        out.extinction_um2 += f * c.extinction_um2;
        out.scattering_um2 += f * c.scattering_um2;
        out.particle_mass_g += f * c.particle_mass_g;
        for (std::size_t l = 0; l < m_moment_count; ++l) {
            out.moments[l] += f * c.scattering_um2 * c.moments[l];
        }
        for (std::size_t i = 0; i < out.phase.size(); ++i) {
            out.phase[i] += f * c.scattering_um2 * c.phase[i];
        }
    }
    if (out.scattering_um2 > 0.0) {
        for (double& m : out.moments) m /= out.scattering_um2;
        for (double& p : out.phase) p /= out.scattering_um2;
    } else {
        out.moments.assign(m_moment_count, 0.0);
        out.moments[0] = 1.0;
        out.phase.assign(m_angles_deg.size(), 1.0);
    }
    return out;
}

}  // namespace glint::atmosphere
