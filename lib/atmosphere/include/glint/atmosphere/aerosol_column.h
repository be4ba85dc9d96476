// SPDX-License-Identifier: Apache-2.0
// The parametric atmosphere's aerosol: one or more regimes, each a vertical profile of its
// 550 nm extinction and its optics at every wavelength. Either one exponential regime with an
// Ångström spectrum and a Henyey–Greenstein phase function (the keys
// aerosol_optical_depth_550, angstrom_exponent, aerosol_scale_height_m, aerosol_asymmetry,
// aerosol_single_scatter_albedo), or LOWTRAN 7's layers (a boundary layer of the chosen type,
// the free troposphere, the stratosphere), or a user's profile (aerosol_profile: one regime per
// layer, its own mixture at its own humidity), each with the optics of OPAC's components
// (glint/atmosphere/aerosol_table.h, glint/model/aerosol_models.h). docs/physics.md
// ("Aerosol optics", "Vertical structure", "A user's aerosol profile").
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "glint/atmosphere/aerosol_table.h"
#include "glint/model/atmosphere.h"

namespace glint::atmosphere {

/// The optics of one regime at one wavelength.
struct RegimeOptics {
    /// Extinction relative to 550 nm: the regime's optical depth at λ is this × its 550 nm one.
    double extinction_ratio = 1.0;
    double single_scatter_albedo = 1.0;
    /// Legendre moments χ₀ … (χ₀ = 1), as many as asked for.
    std::vector<double> moments;
};

/// The aerosol of a parametric atmosphere.
class AerosolColumn {
public:
    /// The regimes `parameters` describe. Throws glint::Error (input) for an unknown aerosol
    /// type, a layered aerosol or a profile without `table`, a component the table lacks (at
    /// the profile's file:line), or parameters out of range.
    AerosolColumn(const model::ParametricAtmosphere& parameters,
                  std::shared_ptr<const AerosolTable> table);

    /// Number of regimes (1 for the exponential aerosol; 3 for LOWTRAN's layers; one per
    /// layer with particles for a profile).
    std::size_t regimes() const noexcept { return m_regimes.size(); }
    /// The 550 nm optical depth of regime `j` above `altitude_m` (vertical).
    double depth_550_above(std::size_t j, double altitude_m) const noexcept;
    /// The 550 nm optical depth of every regime above `altitude_m`.
    double depth_550_above(double altitude_m) const noexcept;
    /// The optics of regime `j` at `wavelength_um` with `moment_count` Legendre moments.
    RegimeOptics optics(std::size_t j, double wavelength_um, std::size_t moment_count) const;
    /// Regime `j`'s extinction at `wavelength_um` relative to 550 nm.
    double extinction_ratio(std::size_t j, double wavelength_um) const;
    /// The phase function of regime `j` at `wavelength_um` for each scattering-angle cosine
    /// of `cos_thetas`, normalised to ∫P dΩ / 4π = 1 (the table's linear in ln P between its
    /// angles).
    std::vector<double> phases(std::size_t j, double wavelength_um,
                               std::span<const double> cos_thetas) const;
    /// The optical depth of every regime above `altitude_m` at `wavelength_um`.
    double optical_depth(double wavelength_um, double altitude_m) const;
    /// What the aerosol is, for the outputs' provenance and the docs ("exponential, τ550 0.1,
    /// Ångström 1.3, g 0.7, ω 0.95" or "rural at 70 % humidity, visibility 23 km, …").
    const std::string& description() const noexcept { return m_description; }

private:
    struct Regime;
    void add_exponential(const model::ParametricAtmosphere& parameters);
    void add_lowtran_layers(const model::ParametricAtmosphere& parameters,
                            const std::shared_ptr<const AerosolTable>& table);
    void add_profile_layers(const model::ParametricAtmosphere& parameters,
                            const std::shared_ptr<const AerosolTable>& table);
    /// Scales every regime so that the column's 550 nm depth is `wanted` (when set); returns
    /// the column's depth.
    double scale_to(const std::optional<double>& wanted, double column);

    std::vector<std::shared_ptr<const Regime>> m_regimes;
    std::string m_description;
};

}  // namespace glint::atmosphere
