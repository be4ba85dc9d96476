// SPDX-License-Identifier: Apache-2.0
// Quantities derived from the model that several stages (and --dump-platform) need:
// F-number, G-number, pixel IFOV, the bandpass grid and channel responses on it.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/spectral.h"
#include "glint/model/instrument.h"
#include "glint/model/spectral_response.h"

namespace glint::model {

/// F# = focal length / aperture diameter; none without both.
std::optional<double> f_number(const InstrumentProperties& properties);
/// G# = (1 + 4 F#²) / (τ π) in 1/sr (the aperture term of the DIRSIG5 BasicPlatform manual,
/// docs/references.md); none without an aperture.
std::optional<double> g_number(const InstrumentProperties& properties);
/// Instantaneous field of view of one pixel pitch, x and y, in rad (pitch / focal length).
std::optional<std::array<double, 2>> pixel_ifov_rad(const InstrumentProperties& properties,
                                                    const DetectorArray& array);
/// The bandpass as a regular spectral grid in µm (throws glint::Error (input) when invalid).
SpectralGrid bandpass_grid(const Bandpass& bandpass);
/// The channel's relative response sampled on `grid` (shape only: gain and bias excluded).
/// Gaussian: peak 1 at the centre, FWHM `width_um`; tophat: 1 within ±width/2, sampled as
/// the fraction of each sample's cell (half-way to its neighbours) inside it — ½ for an edge
/// on a sample —, so that its trapezoid integral is exactly the width within the grid; triangle:
/// 1 at the centre falling linearly to 0 at ±width/2; tabulated: linear interpolation, 0
/// outside the table. Throws glint::Error (input, at the channel) for a width <= 0 or an
/// invalid table.
std::vector<double> channel_response(const Channel& channel, const SpectralGrid& grid);
/// ∫ R(λ) dλ over the grid (trapezoid), in µm.
double channel_integral_um(const Channel& channel, const SpectralGrid& grid);
/// The channel's ENVI `wavelength`, µm: its centre (gaussian, tophat, triangle), or a table's
/// response-weighted mean wavelength ∫λR dλ / ∫R dλ of the piecewise-linear table (exact).
double channel_center_um(const Channel& channel);
/// The channel's ENVI `fwhm`, µm: a gaussian's width, a tophat's full width, half a
/// triangle's base, a table's distance between the outermost crossings of half its peak.
double channel_fwhm_um(const Channel& channel);

}  // namespace glint::model
