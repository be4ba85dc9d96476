// SPDX-License-Identifier: Apache-2.0
// The aerosol components' optics as glint ships them (data/atmosphere/aerosol_optics.csv,
// written by tests/tools/aerosol_tables.cpp from OPAC's components through glint's Mie code:
// glint/atmosphere/aerosol_optics.h), and mixtures of them. Parsed from the file's text (the
// readers open it: glint/inputs/data_tables.h). docs/physics.md, "Aerosol optics".
#pragma once

#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace glint::atmosphere {

/// The optics of one particle (or of a mixture, per unit number density) at one wavelength.
struct ComponentOptics {
    double extinction_um2 = 0.0;  ///< cross section per particle, µm²
    double scattering_um2 = 0.0;  ///< cross section per particle, µm²
    /// The mean mass of one particle as grown at the humidity, g (a mixture's: the
    /// number-weighted mean).
    double particle_mass_g = 0.0;
    /// Legendre moments χ₀ … χ_L of the phase function (χ₀ = 1).
    std::vector<double> moments;
    /// The phase function at AerosolTable::angles_deg(), ∫P dΩ / 4π = 1.
    std::vector<double> phase;

    double single_scatter_albedo() const noexcept {
        return extinction_um2 > 0.0 ? scattering_um2 / extinction_um2 : 1.0;
    }
};

/// `a` + t (`b` − `a`) member by member: the cross sections in ln σ when
/// `log_cross_sections` (linearly where either is 0), the scattering never above the
/// extinction; the particle mass, the moments and the phase function linearly (they must have
/// a's sizes).
ComponentOptics interpolate(const ComponentOptics& a, const ComponentOptics& b, double t,
                            bool log_cross_sections);

/// One component of a mixture and its number density.
struct MixtureShare {
    std::string component;
    double number_per_cm3 = 0.0;
};

/// data/atmosphere/aerosol_optics.csv.
class AerosolTable {
public:
    /// The file's path under glint's data folder.
    static constexpr const char* kRelativePath = "atmosphere/aerosol_optics.csv";

    /// Parses the file's text; `file` names it in errors. Throws glint::Error (input, with
    /// file:line) for a malformed row, a component whose wavelengths do not increase or
    /// differ between its humidities, or a file without rows.
    static AerosolTable from_csv(const std::string& text, const std::string& file);

    /// The scattering angles of every phase function, degrees, increasing from 0 to 180.
    const std::vector<double>& angles_deg() const noexcept { return m_angles_deg; }
    /// The number of Legendre moments of every optics (χ₀ included).
    std::size_t moment_count() const noexcept { return m_moment_count; }
    /// The wavelengths at which `component` is tabulated, µm (increasing; the same at each of
    /// its humidities). Throws glint::Error (input) for a component the table lacks.
    std::vector<double> wavelengths_um(std::string_view component) const;
    /// Whether the table holds `component`.
    bool has(std::string_view component) const;

    /// The optics of one particle of `component` at `wavelength_um` and relative humidity
    /// `rh_percent`: linear in ln λ between the table's wavelengths (the cross sections in
    /// ln σ), clamped to its first and last; linear in humidity between the component's
    /// humidities, clamped likewise (a component that does not take up water has one).
    /// Throws glint::Error (input) for a component the table lacks.
    ComponentOptics optics(std::string_view component, double wavelength_um,
                           double rh_percent) const;

    /// The optics of a mixture per unit of its total number density: the cross sections are
    /// the number-weighted means, the moments and phase function the scattering-weighted
    /// ones. Throws as optics() does, or for an empty mixture.
    ComponentOptics mixture(std::span<const MixtureShare> shares, double wavelength_um,
                            double rh_percent) const;

private:
    struct Row {
        double wavelength_um = 0.0;
        ComponentOptics optics;
    };
    /// Per component, per humidity (increasing), rows by increasing wavelength.
    std::map<std::string, std::map<int, std::vector<Row>>, std::less<>> m_components;
    std::vector<double> m_angles_deg;
    std::size_t m_moment_count = 0;

    const std::map<int, std::vector<Row>>& component(std::string_view name) const;
};

}  // namespace glint::atmosphere
