// SPDX-License-Identifier: Apache-2.0
// Tests of the output units (the "Output Units" section and Table 1 of the DIRSIG5
// BasicPlatform manual, docs/references.md): every row of Table 1 against a value worked out
// by hand for a flat radiance through a Gaussian or tophat channel, the m2 / milli / micro /
// electron variants, gain and bias, mixed normalization, weights vs apply(), the trapezoid
// weights on an irregular grid, the ENVI centres and FWHMs, the errors, the docs/units.md
// table (all 80 combinations) and the capture_full.platform fixture read through the legacy
// reader.
#include "glint/sensor/output_units.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "glint/core/error.h"

namespace glint::sensor {
namespace output_units_test {

using model::AreaUnits;
using model::FluxUnits;

// Independent of glint's constants and helpers (CODATA exact values).
constexpr double kH = 6.62607015e-34;  // J s
constexpr double kC = 299792458.0;     // m/s
/// Photons per joule at λ (µm): λ / (h c) with λ converted to metres.
double photons_per_j(double wavelength_um) { return wavelength_um * 1e-6 / (kH * kC); }

constexpr double kRadiance = 2.5;  // flat L(λ), W/(cm² sr µm)
constexpr double kTime_s = 0.01;

/// Relative tolerance of values that differ from the hand result only by rounding in a sum
/// of a few hundred terms (the quadrature itself is exact or spectrally accurate, see each use).
constexpr double kRelTol = 1e-12;

model::Channel gaussian(const std::string& name, double center_um, double fwhm_um,
                        bool normalize = false) {
    model::Channel c;
    c.name = name;
    c.shape = model::ChannelShape::gaussian;
    c.center_um = center_um;
    c.width_um = fwhm_um;
    c.normalize = normalize;
    return c;
}

model::Channel shaped(model::ChannelShape shape, double center_um, double width_um,
                      bool normalize = false) {
    model::Channel c = gaussian("c", center_um, width_um, normalize);
    c.shape = shape;
    return c;
}

model::Channel tabulated(const std::string& name, std::vector<double> wavelengths_um,
                         std::vector<double> values, bool normalize = false) {
    model::Channel c;
    c.name = name;
    c.shape = model::ChannelShape::tabulated;
    c.table_wavelength_um = std::move(wavelengths_um);
    c.table_value = std::move(values);
    c.normalize = normalize;
    return c;
}

model::CaptureMethod method(std::vector<model::Channel> channels, FluxUnits flux = FluxUnits::watts,
                            AreaUnits area = AreaUnits::cm2, double time_s = 0.0) {
    model::CaptureMethod m;
    m.image_file.basename = "out";
    m.image_file.flux_units = flux;
    m.image_file.area_units = area;
    m.temporal_integration.time_s = time_s;
    m.spectral_response.channels = std::move(channels);
    return m;
}

/// A focal length but no aperture diameter: no aperture defined.
model::InstrumentProperties no_aperture() {
    model::InstrumentProperties p;
    p.focal_length_m = 0.1;
    return p;
}

/// F# = 0.1 m / 0.025 m = 4, τ = 0.8.
model::InstrumentProperties with_aperture() {
    model::InstrumentProperties p = no_aperture();
    p.aperture_diameter_m = 0.025;
    p.aperture_throughput = 0.8;
    return p;
}

/// The manual's G# = (1 + 4 F#²)/(τ π) for with_aperture(), written out.
double expected_g_number() { return (1.0 + 4.0 * 4.0 * 4.0) / (0.8 * std::numbers::pi); }

/// 0.4–0.7 µm at 1 nm (301 bands).
SpectralGrid fine_grid() { return SpectralGrid::regular(0.4, 0.7, 0.001); }

std::vector<double> flat(const SpectralGrid& grid, double value = kRadiance) {
    return std::vector<double>(grid.size(), value);
}

double apply_one(const OutputUnits& units, const std::vector<double>& radiance) {
    std::vector<double> out(units.channels());
    units.apply(radiance, out);
    return out.at(0);
}

// A Gaussian of FWHM w = 0.02 µm at 0.55 µm: σ = w/2.3548 = 8.5 nm, sampled every 1 nm on a
// grid symmetric about its centre reaching ±7.5 w (tails < 1e-60). The trapezoid rule on such
// a Gaussian is exact to far below 1e-15 (its error falls like exp(-2π²σ²/h²)), so
// ∫R dλ = w √(π/(4 ln 2)) and, by symmetry, ∫λR dλ = centre · ∫R dλ.
constexpr double kCenter_um = 0.55;
constexpr double kFwhm_um = 0.02;
double gaussian_area_um() { return kFwhm_um * std::sqrt(std::numbers::pi / (4.0 * std::log(2.0))); }

struct TableRow {
    FluxUnits flux;
    bool aperture;
    bool temporal;
    bool normalized;
    const char* units;
    double expected;  // for L = kRadiance, the Gaussian channel, cm2, gain 1, bias 0
};

std::vector<TableRow> table1_rows() {
    const double a = gaussian_area_um();
    const double g = expected_g_number();
    const double l = kRadiance;
    const double t = kTime_s;
    // Photons/s per (cm² sr): ∫ L λ/(hc) R dλ = L · photons_per_j(centre) · ∫R dλ.
    const double p = l * photons_per_j(kCenter_um) * a;
    return {
        {FluxUnits::watts, false, false, false, "Watts/(cm2 sr)", a * l},
        {FluxUnits::watts, false, false, true, "Watts/(cm2 sr um)", l},
        {FluxUnits::watts, true, false, false, "Watts/cm2", a * l / g},
        {FluxUnits::watts, true, false, true, "Watts/(cm2 um)", l / g},
        {FluxUnits::watts, false, true, false, "Joules/(cm2 sr)", a * l * t},
        {FluxUnits::watts, true, true, false, "Joules/cm2", a * l * t / g},
        {FluxUnits::photons_per_second, false, false, false, "Photons/s/(cm2 sr)", p},
        {FluxUnits::photons_per_second, true, false, false, "Photons/s/cm2", p / g},
        {FluxUnits::photons_per_second, false, true, false, "Photons/(cm2 sr)", p * t},
        {FluxUnits::photons_per_second, true, true, false, "Photons/cm2", p * t / g},
    };
}

TEST(OutputUnitsTable1, EveryRowGivesTheHandValueAndString) {
    const SpectralGrid grid = fine_grid();
    for (const TableRow& row : table1_rows()) {
        SCOPED_TRACE(row.units);
        const OutputUnits units(method({gaussian("G", kCenter_um, kFwhm_um, row.normalized)},
                                       row.flux, AreaUnits::cm2, row.temporal ? kTime_s : 0.0),
                                row.aperture ? with_aperture() : no_aperture(), grid);
        EXPECT_EQ(units.description().data_units, row.units);
        EXPECT_EQ(units.description().aperture, row.aperture);
        EXPECT_EQ(units.description().temporal_integration, row.temporal);
        EXPECT_EQ(units.description().normalized, row.normalized);
        EXPECT_NEAR(apply_one(units, flat(grid)), row.expected, kRelTol * row.expected);
    }
}

TEST(OutputUnitsTable1, TophatChannelIntegratesToItsWidth) {
    // A tophat's sampled response integrates to exactly its width (0.1 µm), so a flat
    // radiance gives width × L; normalized, L itself.
    const SpectralGrid grid = SpectralGrid::regular(0.4, 0.7, 0.005);
    const model::Channel box = shaped(model::ChannelShape::tophat, 0.55, 0.1);
    const OutputUnits plain(method({box}), no_aperture(), grid);
    EXPECT_NEAR(apply_one(plain, flat(grid)), 0.1 * kRadiance, kRelTol);
    model::Channel normalized = box;
    normalized.normalize = true;
    const OutputUnits norm(method({normalized}), no_aperture(), grid);
    EXPECT_NEAR(apply_one(norm, flat(grid)), kRadiance, kRelTol);
    // Photons through the box: L/(hc) ∫_{0.5}^{0.6} λ dλ = L · photons_per_j(1) · 0.055 (the
    // half-weighted edge samples err by ±Δ²/8 at either edge, which cancel for linear λ).
    const OutputUnits photons(method({box}, FluxUnits::photons_per_second), no_aperture(), grid);
    const double expected = kRadiance * photons_per_j(1.0) * 0.5 * (0.6 * 0.6 - 0.5 * 0.5);
    EXPECT_NEAR(apply_one(photons, flat(grid)), expected, kRelTol * expected);
}

TEST(OutputUnitsTable1, GNumberComesFromTheFNumber) {
    const OutputUnits units(method({gaussian("G", kCenter_um, kFwhm_um)}), with_aperture(),
                            fine_grid());
    EXPECT_TRUE(units.description().aperture);
    EXPECT_NEAR(units.description().g_number_per_sr, expected_g_number(), 1e-12);
    // Both lengths are needed: a diameter without a focal length is no aperture either.
    model::InstrumentProperties diameter_only;
    diameter_only.aperture_diameter_m = 0.025;
    const OutputUnits none(method({gaussian("G", kCenter_um, kFwhm_um)}), diameter_only,
                           fine_grid());
    EXPECT_FALSE(none.description().aperture);
    EXPECT_EQ(none.description().g_number_per_sr, 0.0);
    EXPECT_EQ(none.description().data_units, "Watts/(cm2 sr)");
}

TEST(OutputUnitsTable1, ZeroTimeIsNoTemporalIntegration) {
    const OutputUnits units(
        method({gaussian("G", kCenter_um, kFwhm_um)}, FluxUnits::watts, AreaUnits::cm2, 0.0),
        no_aperture(), fine_grid());
    EXPECT_FALSE(units.description().temporal_integration);
    EXPECT_EQ(units.description().integration_time_s, 0.0);
    const OutputUnits timed(
        method({gaussian("G", kCenter_um, kFwhm_um)}, FluxUnits::watts, AreaUnits::cm2, kTime_s),
        no_aperture(), fine_grid());
    EXPECT_TRUE(timed.description().temporal_integration);
    EXPECT_EQ(timed.description().integration_time_s, kTime_s);
}

// ---- Beyond Table 1: m2, milli/micro, electrons ---------------------------------------------

double value_for(FluxUnits flux, AreaUnits area, bool aperture, double time_s,
                 std::string* units_out = nullptr) {
    const SpectralGrid grid = fine_grid();
    const OutputUnits units(method({gaussian("G", kCenter_um, kFwhm_um)}, flux, area, time_s),
                            aperture ? with_aperture() : no_aperture(), grid);
    if (units_out) *units_out = units.description().data_units;
    return apply_one(units, flat(grid));
}

TEST(OutputUnitsVariants, SquareMetresAreTenThousandTimesSquareCentimetres) {
    std::string text;
    const double per_cm2 = value_for(FluxUnits::watts, AreaUnits::cm2, false, 0.0);
    const double per_m2 = value_for(FluxUnits::watts, AreaUnits::m2, false, 0.0, &text);
    EXPECT_NEAR(per_m2, 1e4 * per_cm2, kRelTol * per_m2);
    EXPECT_EQ(text, "Watts/(m2 sr)");
    const double p_cm2 = value_for(FluxUnits::photons_per_second, AreaUnits::cm2, true, kTime_s);
    const double p_m2 =
        value_for(FluxUnits::photons_per_second, AreaUnits::m2, true, kTime_s, &text);
    EXPECT_NEAR(p_m2, 1e4 * p_cm2, kRelTol * p_m2);
    EXPECT_EQ(text, "Photons/m2");
}

TEST(OutputUnitsVariants, MilliAndMicroWattsAndJoules) {
    std::string text;
    const double w = value_for(FluxUnits::watts, AreaUnits::cm2, false, 0.0);
    EXPECT_NEAR(value_for(FluxUnits::milliwatts, AreaUnits::cm2, false, 0.0, &text), 1e3 * w,
                kRelTol * 1e3 * w);
    EXPECT_EQ(text, "Milliwatts/(cm2 sr)");
    EXPECT_NEAR(value_for(FluxUnits::microwatts, AreaUnits::cm2, false, 0.0, &text), 1e6 * w,
                kRelTol * 1e6 * w);
    EXPECT_EQ(text, "Microwatts/(cm2 sr)");
    const double j = value_for(FluxUnits::watts, AreaUnits::cm2, true, kTime_s);
    EXPECT_NEAR(value_for(FluxUnits::milliwatts, AreaUnits::cm2, true, kTime_s, &text), 1e3 * j,
                kRelTol * 1e3 * j);
    EXPECT_EQ(text, "Millijoules/cm2");
    EXPECT_NEAR(value_for(FluxUnits::microwatts, AreaUnits::m2, true, kTime_s, &text),
                1e6 * 1e4 * j, kRelTol * 1e10 * j);
    EXPECT_EQ(text, "Microjoules/m2");
}

TEST(OutputUnitsVariants, ElectronsAreThePhotonNumbers) {
    // "electronspersecond (assumes response is quantum efficiency)": R_c is the QE.
    std::string text;
    for (const bool aperture : {false, true}) {
        for (const double time_s : {0.0, kTime_s}) {
            const double p =
                value_for(FluxUnits::photons_per_second, AreaUnits::cm2, aperture, time_s);
            EXPECT_EQ(
                value_for(FluxUnits::electrons_per_second, AreaUnits::cm2, aperture, time_s, &text),
                p);
        }
    }
    EXPECT_EQ(text, "Electrons/cm2");
    value_for(FluxUnits::electrons_per_second, AreaUnits::cm2, false, 0.0, &text);
    EXPECT_EQ(text, "Electrons/s/(cm2 sr)");
}

TEST(OutputUnitsVariants, NormalizedPhotonsKeepPerMicrometre) {
    const SpectralGrid grid = fine_grid();
    const OutputUnits units(
        method({gaussian("G", kCenter_um, kFwhm_um, true)}, FluxUnits::photons_per_second),
        no_aperture(), grid);
    EXPECT_EQ(units.description().data_units, "Photons/s/(cm2 sr um)");
    // ∫ L λ/(hc) R dλ / ∫R dλ = L · photons_per_j(centre) for the symmetric Gaussian.
    const double expected = kRadiance * photons_per_j(kCenter_um);
    EXPECT_NEAR(apply_one(units, flat(grid)), expected, kRelTol * expected);
}

// ---- Gain, bias, mixed normalization, weights ------------------------------------------------

TEST(OutputUnitsChannels, GainScalesAndBiasAddsInOutputUnits) {
    const SpectralGrid grid = fine_grid();
    model::Channel channel = gaussian("G", kCenter_um, kFwhm_um);
    channel.gain = 2.0;
    channel.bias = 0.5;
    // The bias is in the output units: it is not divided by G#, multiplied by the time or
    // by 1e4 for m2.
    const OutputUnits units(method({channel}, FluxUnits::watts, AreaUnits::m2, kTime_s),
                            with_aperture(), grid);
    const double expected =
        2.0 * 1e4 * gaussian_area_um() * kRadiance * kTime_s / expected_g_number() + 0.5;
    EXPECT_NEAR(apply_one(units, flat(grid)), expected, kRelTol * expected);
    EXPECT_EQ(units.bias(0), 0.5);
    EXPECT_NEAR(apply_one(units, flat(grid, 0.0)), 0.5, 1e-15);  // no light: the bias alone
}

TEST(OutputUnitsChannels, MixedNormalizationListsEachChannelsUnits) {
    const SpectralGrid grid = fine_grid();
    const OutputUnits units(
        method({gaussian("A", 0.5, 0.02, false), gaussian("B", 0.55, 0.02, true),
                gaussian("C", 0.6, 0.02, false)}),
        with_aperture(), grid);
    const UnitsDescription& d = units.description();
    EXPECT_FALSE(d.normalized);
    EXPECT_EQ(d.data_units, "Watts/cm2");  // the first channel's
    ASSERT_EQ(d.per_channel_units.size(), 3u);
    EXPECT_EQ(d.per_channel_units[0], "Watts/cm2");
    EXPECT_EQ(d.per_channel_units[1], "Watts/(cm2 um)");
    EXPECT_EQ(d.per_channel_units[2], "Watts/cm2");
    std::vector<double> out(3);
    units.apply(flat(grid), out);
    const double g = expected_g_number();
    EXPECT_NEAR(out[0], gaussian_area_um() * kRadiance / g, kRelTol * out[0]);
    EXPECT_NEAR(out[1], kRadiance / g, kRelTol * out[1]);
    EXPECT_NEAR(out[2], gaussian_area_um() * kRadiance / g, kRelTol * out[2]);

    const OutputUnits all(method({gaussian("A", 0.5, 0.02, true), gaussian("B", 0.6, 0.02, true)}),
                          no_aperture(), grid);
    EXPECT_TRUE(all.description().normalized);
    EXPECT_EQ(all.description().data_units, "Watts/(cm2 sr um)");
    EXPECT_TRUE(all.description().per_channel_units.empty());  // listed only when they differ
}

TEST(OutputUnitsChannels, ApplyIsTheWeightedSumPlusBias) {
    const SpectralGrid grid = fine_grid();
    model::Channel tab =
        tabulated("T", {0.45, 0.5, 0.62, 0.66}, {0.0, 0.7, 1.0, 0.0}, /*normalize=*/true);
    tab.gain = 3.0;
    tab.bias = -1.25;
    const OutputUnits units(method({gaussian("G", 0.5, 0.03), tab}, FluxUnits::photons_per_second,
                                   AreaUnits::m2, kTime_s),
                            with_aperture(), grid);
    ASSERT_EQ(units.channels(), 2u);
    ASSERT_EQ(units.bands(), grid.size());
    std::vector<double> radiance(grid.size());
    for (std::size_t b = 0; b < radiance.size(); ++b) {
        radiance[b] = 1.0 + std::sin(37.0 * grid.wavelengths_um()[b]);  // any spectrum
    }
    std::vector<double> out(2);
    units.apply(radiance, out);
    for (std::size_t c = 0; c < 2; ++c) {
        double sum = units.bias(c);
        for (std::size_t b = 0; b < grid.size(); ++b) sum += units.weight(c, b) * radiance[b];
        EXPECT_NEAR(out[c], sum, 1e-12 * std::abs(sum)) << "channel " << c;
    }
}

/// A tophat channel and a tabulated one with a bias, in W/(cm² sr µm), on `grid`.
OutputUnits tophat_and_tabulated(const SpectralGrid& grid) {
    model::Channel tab = tabulated("T", {0.45, 0.5, 0.62, 0.66}, {0.0, 0.7, 1.0, 0.0});
    tab.bias = 0.5;
    return OutputUnits(method({shaped(model::ChannelShape::tophat, 0.55, 0.05), tab},
                              FluxUnits::watts, AreaUnits::cm2, 0.0),
                       no_aperture(), grid);
}

TEST(OutputUnitsChannels, ChannelValueFromItsSupportEqualsApply) {
    // A split channel's state traces only the bands its weights cover: support() finds them
    // and channel_value() on them gives apply()'s value.
    const SpectralGrid grid = fine_grid();
    const OutputUnits units = tophat_and_tabulated(grid);
    std::vector<double> radiance(grid.size());
    for (std::size_t b = 0; b < radiance.size(); ++b) {
        radiance[b] = 1.0 + std::sin(37.0 * grid.wavelengths_um()[b]);
    }
    std::vector<double> out(2);
    units.apply(radiance, out);
    for (std::size_t c = 0; c < 2; ++c) {
        const BandRange r = units.support(c);
        ASSERT_GT(r.count, 0u) << c;
        EXPECT_NE(units.weight(c, r.first), 0.0);
        EXPECT_NE(units.weight(c, r.first + r.count - 1), 0.0);
        for (std::size_t b = 0; b < grid.size(); ++b) {
            if (b < r.first || b >= r.first + r.count) {
                EXPECT_EQ(units.weight(c, b), 0.0) << b;
            }
        }
        EXPECT_LT(r.count, grid.size()) << "channel " << c << " covers part of the grid";
        const std::span<const double> part(radiance.data() + r.first, r.count);
        EXPECT_NEAR(units.channel_value(c, r.first, part), out[c], 1e-12 * std::abs(out[c]));
        // A range that misses part of the support is refused.
        EXPECT_THROW(units.channel_value(c, r.first + 1, part.subspan(1)), Error);
    }
    EXPECT_THROW(units.channel_value(2, 0, radiance), Error);
}

TEST(OutputUnitsChannels, ListedBandsGiveApplysBits) {
    // A spectrally sampled pixel is 0 outside the bands its samples reached: apply() over
    // that list gives apply()'s bits over the whole spectrum; an empty list is every band.
    const SpectralGrid grid = fine_grid();
    const OutputUnits units = tophat_and_tabulated(grid);
    std::vector<double> radiance(grid.size(), 0.0);
    std::vector<std::uint32_t> listed;
    for (std::size_t b = 0; b < radiance.size(); b += 3) {
        radiance[b] = 1.0 + std::sin(37.0 * grid.wavelengths_um()[b]);
        listed.push_back(static_cast<std::uint32_t>(b));
    }
    listed.push_back(static_cast<std::uint32_t>(grid.size() - 1));  // a listed zero band
    std::vector<double> whole(2), sparse(2), empty(2);
    units.apply(radiance, whole);
    units.apply(radiance, listed, sparse);
    units.apply(radiance, {}, empty);
    for (std::size_t c = 0; c < 2; ++c) {
        EXPECT_EQ(sparse[c], whole[c]) << c;
        EXPECT_EQ(empty[c], whole[c]) << c;
    }
    const std::vector<std::uint32_t> beyond{static_cast<std::uint32_t>(grid.size())};
    EXPECT_THROW(units.apply(radiance, beyond, sparse), Error);
}

TEST(OutputUnitsRaw, OneBandPerGridSampleInTheFluxAndAreaUnits) {
    // Raw: S_b = k_area k_aperture k_time k_flux(λ_b) L(λ_b), per µm; here photons per
    // second per m² with an aperture and no integration time, the channel unused.
    const SpectralGrid grid({0.5, 0.6, 0.8});
    model::CaptureMethod raw =
        method({gaussian("unused", 0.6, 0.1)}, FluxUnits::photons_per_second, AreaUnits::m2);
    raw.type = model::CaptureMethodType::raw;
    const OutputUnits units(raw, with_aperture(), grid);
    ASSERT_EQ(units.channels(), 3u);
    const std::vector<double> radiance{1.0, 2.0, 4.0};
    std::vector<double> out(3);
    units.apply(radiance, out);
    for (std::size_t b = 0; b < 3; ++b) {
        const double expected =
            1e4 * photons_per_j(grid.wavelengths_um()[b]) * radiance[b] / expected_g_number();
        EXPECT_NEAR(out[b], expected, kRelTol * expected) << b;
        EXPECT_EQ(units.centers_um()[b], grid.wavelengths_um()[b]);
    }
    EXPECT_NEAR(units.fwhm_um()[0], 0.1, 1e-15);   // one-sided at the ends
    EXPECT_NEAR(units.fwhm_um()[1], 0.15, 1e-15);  // half the neighbours' distance
    EXPECT_NEAR(units.fwhm_um()[2], 0.2, 1e-15);
    EXPECT_EQ(units.band_names(),
              (std::vector<std::string>{"0.5000 um", "0.6000 um", "0.8000 um"}));
    EXPECT_EQ(units.description().data_units, "Photons/s/(m2 um)");
}

TEST(OutputUnitsChannels, TrapezoidWeightsReproduceIntegrateTrapezoid) {
    // An irregular grid and a response of 1 everywhere on it: weight(0, b) is Δ_b itself.
    const SpectralGrid grid({0.41, 0.415, 0.43, 0.47, 0.471, 0.52, 0.6, 0.61, 0.69});
    const OutputUnits units(method({tabulated("one", {0.3, 0.8}, {1.0, 1.0})}), no_aperture(),
                            grid);
    double total_um = 0.0;
    for (std::size_t b = 0; b < grid.size(); ++b) total_um += units.weight(0, b);
    EXPECT_NEAR(total_um, 0.69 - 0.41, 1e-15);  // Σ Δ_b = grid span
    EXPECT_NEAR(units.weight(0, 0), 0.5 * (0.415 - 0.41), 1e-16);
    EXPECT_NEAR(units.weight(0, 3), 0.5 * (0.471 - 0.43), 1e-16);
    std::vector<double> f(grid.size());
    for (std::size_t b = 0; b < f.size(); ++b) {
        f[b] = std::exp(grid.wavelengths_um()[b]) * (b % 2 ? 2.0 : 0.5);
    }
    double sum = 0.0;
    for (std::size_t b = 0; b < f.size(); ++b) sum += units.weight(0, b) * f[b];
    // Equal up to the rounding of the two summation orders (9 terms).
    EXPECT_NEAR(sum, integrate_trapezoid(grid, f), 1e-15 * std::abs(sum) * 9);
    EXPECT_NEAR(apply_one(units, f), integrate_trapezoid(grid, f), 1e-15 * std::abs(sum) * 9);
}

// ---- ENVI centres and FWHMs -------------------------------------------------------------------

TEST(OutputUnitsBands, CentersAndFwhmPerShape) {
    const SpectralGrid grid = fine_grid();
    const OutputUnits units(
        method({shaped(model::ChannelShape::gaussian, 0.5, 0.02),
                shaped(model::ChannelShape::tophat, 0.55, 0.04),
                shaped(model::ChannelShape::triangle, 0.6, 0.06),
                // A plateau from 0.55 to 0.65 with linear flanks: centroid 0.6 by symmetry,
                // half height at 0.525 and 0.675.
                tabulated("plateau", {0.5, 0.55, 0.65, 0.7}, {0.0, 2.0, 2.0, 0.0}),
                // A skewed triangle 0.5–0.6–0.9: centroid = mean of its corners, half height
                // half-way up each flank (0.55 and 0.75).
                tabulated("skew", {0.5, 0.6, 0.9}, {0.0, 1.0, 0.0})}),
        no_aperture(), grid);
    const std::vector<double>& c = units.centers_um();
    const std::vector<double>& w = units.fwhm_um();
    ASSERT_EQ(c.size(), 5u);
    ASSERT_EQ(w.size(), 5u);
    EXPECT_EQ(c[0], 0.5);
    EXPECT_EQ(w[0], 0.02);  // the Gaussian's width is its FWHM
    EXPECT_EQ(c[1], 0.55);
    EXPECT_EQ(w[1], 0.04);  // a box: full width
    EXPECT_EQ(c[2], 0.6);
    EXPECT_DOUBLE_EQ(w[2], 0.03);  // a triangle: half its base
    EXPECT_NEAR(c[3], 0.6, 1e-14);
    EXPECT_NEAR(w[3], 0.15, 1e-14);
    EXPECT_NEAR(c[4], (0.5 + 0.6 + 0.9) / 3.0, 1e-14);
    EXPECT_NEAR(w[4], 0.2, 1e-14);
}

TEST(OutputUnitsBands, TableEndAboveHalfPeakIsTheCrossing) {
    const OutputUnits units(method({tabulated("step", {0.45, 0.5, 0.6}, {1.0, 1.0, 0.0})}),
                            no_aperture(), fine_grid());
    EXPECT_NEAR(units.fwhm_um()[0], 0.55 - 0.45, 1e-14);
}

// ---- Errors -----------------------------------------------------------------------------------

model::Channel located(model::Channel channel) {
    channel.where = ErrorContext{"cam.platform", 42, "focalplane[F]/capturemethod[C]/channel"};
    return channel;
}

TEST(OutputUnitsErrors, NormalizedChannelWithoutResponseNamesTheChannelAndLine) {
    const model::Channel nir =
        located(tabulated("NIR", {0.8, 0.85, 0.9}, {0.0, 1.0, 0.0}, /*normalize=*/true));
    try {
        const OutputUnits units(method({gaussian("G", 0.5, 0.02), nir}), no_aperture(),
                                fine_grid());
        FAIL() << "expected glint::Error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_EQ(e.context().file, "cam.platform");
        EXPECT_EQ(e.context().line, 42);
        EXPECT_EQ(e.message(),
                  "channel 'NIR': normalized channel has no response on the bandpass 0.4-0.7 µm "
                  "(∫ R dλ = 0 µm), expected a response inside it");
        EXPECT_NE(std::string(e.what()).find("cam.platform:42: "), std::string::npos) << e.what();
    }
}

TEST(OutputUnitsErrors, UnnormalizedChannelWithoutResponseToo) {
    const model::Channel dark = located(tabulated("Dark", {0.5, 0.6}, {0.0, 0.0}));
    try {
        const OutputUnits units(method({dark}), no_aperture(), fine_grid());
        FAIL() << "expected glint::Error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_EQ(e.context().line, 42);
        EXPECT_EQ(e.message(),
                  "channel 'Dark': has no response on the bandpass 0.4-0.7 µm (∫ R dλ = 0 µm), "
                  "expected a response inside it");
    }
}

TEST(OutputUnitsErrors, InvalidWidthComesFromTheChannelResponse) {
    const model::Channel bad = located(shaped(model::ChannelShape::tophat, 0.5, 0.0));
    try {
        const OutputUnits units(method({bad}), no_aperture(), fine_grid());
        FAIL() << "expected glint::Error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_EQ(e.context().line, 42);
    }
}

TEST(OutputUnitsErrors, ApplyChecksSizes) {
    const SpectralGrid grid = fine_grid();
    const OutputUnits units(method({gaussian("G", 0.5, 0.02)}), no_aperture(), grid);
    std::vector<double> out(1);
    const std::vector<double> short_radiance(grid.size() - 1, 1.0);
    EXPECT_THROW(units.apply(short_radiance, out), Error);
    std::vector<double> two(2);
    EXPECT_THROW(units.apply(flat(grid), two), Error);
}

TEST(OutputUnitsErrors, NoChannelsIsAnEmptyMap) {
    const OutputUnits units(method({}), with_aperture(), fine_grid());
    EXPECT_EQ(units.channels(), 0u);
    EXPECT_FALSE(units.description().normalized);
    EXPECT_EQ(units.description().data_units, "Watts/cm2");
    EXPECT_TRUE(units.description().per_channel_units.empty());
    std::vector<double> out;
    units.apply(flat(fine_grid()), out);
}

}  // namespace output_units_test
}  // namespace glint::sensor
