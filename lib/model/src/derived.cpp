// SPDX-License-Identifier: Apache-2.0
// Quantities derived from the model: F-number and G-number of an instrument (the aperture
// term of the DIRSIG5 BasicPlatform manual, docs/references.md; docs/physics.md), the IFOV of
// a pixel pitch, the bandpass grid, and the channels' relative spectral responses sampled on
// it with their trapezoid integrals.
#include "glint/model/derived.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "glint/core/error.h"

namespace glint::model {
namespace {

/// Two wavelengths closer than this (µm) are the same sample: an edge of a tophat or the end
/// of a table that falls on a grid point, after rounding (0.4 + 20 × 0.01 > 0.6).
constexpr double kEdgeToleranceUm = 1e-9;

bool positive_finite(double value) { return std::isfinite(value) && value > 0.0; }

void check_width(const Channel& channel, const char* shape) {
    if (!positive_finite(channel.width_um)) {
        throw input_error("channel '" + channel.name + "': " + shape + " width " +
                              std::to_string(channel.width_um) + " µm is invalid, expected > 0",
                          channel.where);
    }
}

/// The fraction of sample i's cell (half-way to its neighbours, clipped to the grid) that
/// lies in [lo, hi]: 1 inside, 0 outside, ½ for an edge on a sample. Trapezoid weights are
/// the cell widths, so the trapezoid integral is exactly the overlap of [lo, hi] with the grid.
double box_fraction(std::span<const double> wavelengths, std::size_t i, double lo, double hi) {
    const std::size_t n = wavelengths.size();
    if (n == 1) return (wavelengths[0] >= lo && wavelengths[0] <= hi) ? 1.0 : 0.0;
    const double cell_lo = i == 0 ? wavelengths[0] : 0.5 * (wavelengths[i - 1] + wavelengths[i]);
    const double cell_hi =
        i + 1 == n ? wavelengths[n - 1] : 0.5 * (wavelengths[i] + wavelengths[i + 1]);
    const double overlap = std::min(cell_hi, hi) - std::max(cell_lo, lo);
    if (overlap <= kEdgeToleranceUm) return 0.0;
    const double fraction = overlap / (cell_hi - cell_lo);
    return fraction >= 1.0 - kEdgeToleranceUm / (cell_hi - cell_lo) ? 1.0 : fraction;
}

double triangle(double offset_um, double half_um) {
    const double value = 1.0 - std::abs(offset_um) / half_um;
    return value > 0.0 ? value : 0.0;
}

/// The response-weighted mean wavelength ∫λR dλ / ∫R dλ of the piecewise-linear table (exact).
double table_centroid_um(const Channel& channel) {
    const std::vector<double>& wl = channel.table_wavelength_um;
    const std::vector<double>& r = channel.table_value;
    double moment = 0.0;
    double area = 0.0;
    for (std::size_t i = 1; i < wl.size(); ++i) {
        const double a = wl[i - 1];
        const double b = wl[i];
        area += 0.5 * (b - a) * (r[i - 1] + r[i]);
        moment += (b - a) / 6.0 * (r[i - 1] * (2.0 * a + b) + r[i] * (a + 2.0 * b));
    }
    if (area > 0.0) return moment / area;
    // A one-point table (or an all-zero one, rejected earlier): its own wavelength(s).
    return 0.5 * (wl.front() + wl.back());
}

/// Distance between the outermost crossings of half the table's peak (µm).
double table_fwhm_um(const Channel& channel) {
    const std::vector<double>& wl = channel.table_wavelength_um;
    const std::vector<double>& r = channel.table_value;
    const double half = 0.5 * *std::max_element(r.begin(), r.end());
    std::size_t first = 0;  // the peak itself is >= half, so both loops stop at or before it
    while (first + 1 < r.size() && r[first] < half) ++first;
    std::size_t last = r.size() - 1;
    while (last > first && r[last] < half) --last;
    double left_um = wl[first];
    if (first > 0) {
        const double t = (half - r[first - 1]) / (r[first] - r[first - 1]);
        left_um = wl[first - 1] + t * (wl[first] - wl[first - 1]);
    }
    double right_um = wl[last];
    if (last + 1 < r.size()) {
        const double t = (r[last] - half) / (r[last] - r[last + 1]);
        right_um = wl[last] + t * (wl[last + 1] - wl[last]);
    }
    return right_um - left_um;
}

}  // namespace

std::optional<double> f_number(const InstrumentProperties& properties) {
    if (!properties.focal_length_m || !properties.aperture_diameter_m) return std::nullopt;
    const double focal = *properties.focal_length_m;
    const double aperture = *properties.aperture_diameter_m;
    if (!positive_finite(focal) || !positive_finite(aperture)) return std::nullopt;
    return focal / aperture;
}

std::optional<double> g_number(const InstrumentProperties& properties) {
    const std::optional<double> f = f_number(properties);
    const double tau = properties.aperture_throughput;
    if (!f || !positive_finite(tau)) return std::nullopt;
    return (1.0 + 4.0 * *f * *f) / (tau * std::numbers::pi);
}

std::optional<std::array<double, 2>> pixel_ifov_rad(const InstrumentProperties& properties,
                                                    const DetectorArray& array) {
    if (!properties.focal_length_m || !positive_finite(*properties.focal_length_m)) {
        return std::nullopt;
    }
    const double focal = *properties.focal_length_m;
    return std::array<double, 2>{array.x_spacing_m / focal, array.y_spacing_m / focal};
}

SpectralGrid bandpass_grid(const Bandpass& bandpass) {
    return SpectralGrid::regular(bandpass.min_um, bandpass.max_um, bandpass.delta_um,
                                 bandpass.where);
}

std::vector<double> channel_response(const Channel& channel, const SpectralGrid& grid) {
    std::vector<double> response(grid.size(), 0.0);
    const std::span<const double> wavelengths = grid.wavelengths_um();
    switch (channel.shape) {
        case ChannelShape::gaussian:
            check_width(channel, "gaussian");
            for (std::size_t i = 0; i < response.size(); ++i) {
                response[i] = gaussian_fwhm(wavelengths[i], channel.center_um, channel.width_um);
            }
            break;
        case ChannelShape::tophat:
            check_width(channel, "tophat");
            for (std::size_t i = 0; i < response.size(); ++i) {
                response[i] =
                    box_fraction(wavelengths, i, channel.center_um - 0.5 * channel.width_um,
                                 channel.center_um + 0.5 * channel.width_um);
            }
            break;
        case ChannelShape::triangle:
            check_width(channel, "triangle");
            for (std::size_t i = 0; i < response.size(); ++i) {
                response[i] = triangle(wavelengths[i] - channel.center_um, 0.5 * channel.width_um);
            }
            break;
        case ChannelShape::tabulated: {
            if (channel.table_wavelength_um.empty()) {
                throw input_error("channel '" + channel.name +
                                      "': tabulated response has no "
                                      "entries, expected at least 2",
                                  channel.where);
            }
            const SpectralCurve curve(channel.table_wavelength_um, channel.table_value,
                                      channel.where);
            const double first = channel.table_wavelength_um.front();
            const double last = channel.table_wavelength_um.back();
            for (std::size_t i = 0; i < response.size(); ++i) {
                // A grid point that misses a table end by rounding takes the end's value.
                double wavelength = wavelengths[i];
                if (wavelength < first && first - wavelength <= kEdgeToleranceUm)
                    wavelength = first;
                if (wavelength > last && wavelength - last <= kEdgeToleranceUm) wavelength = last;
                response[i] = curve.value_at(wavelength);
            }
            break;
        }
    }
    return response;
}

double channel_integral_um(const Channel& channel, const SpectralGrid& grid) {
    return integrate_trapezoid(grid, channel_response(channel, grid));
}

double channel_center_um(const Channel& channel) {
    return channel.shape == ChannelShape::tabulated ? table_centroid_um(channel)
                                                    : channel.center_um;
}

double channel_fwhm_um(const Channel& channel) {
    switch (channel.shape) {
        case ChannelShape::gaussian:  // width is the FWHM
        case ChannelShape::tophat:    // a box's FWHM is its full width
            return channel.width_um;
        case ChannelShape::triangle:  // half height at ±width/4
            return 0.5 * channel.width_um;
        case ChannelShape::tabulated:
            return table_fwhm_um(channel);
    }
    throw internal_error("unknown channel shape");
}

}  // namespace glint::model
