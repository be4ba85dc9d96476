// SPDX-License-Identifier: Apache-2.0
// The aerosol types and LOWTRAN 7's aerosol profiles (glint/model/aerosol_models.h). The
// number densities are OPAC's standard mixtures (M. Hess, P. Koepke, I. Schult, Bulletin of the
// American Meteorological Society 79, 1998, 831–844, Table 4). The profiles are LOWTRAN 7's
// 550 nm extinction coefficients (F. X. Kneizys et al., AFGL-TR-88-0177, 1988; a U.S.
// Government work), as its BLOCK DATA holds them (the same numbers libRadtran 2.0's
// libsrc_f/prfinc.f carries), km⁻¹.
#include "glint/model/aerosol_models.h"

#include <algorithm>
#include <array>
#include <iterator>
#include <string>
#include <string_view>

namespace glint::model {

namespace {

constexpr std::string_view kComponentNames[] = {"inso", "waso", "soot", "ssam", "sscm",
                                                "minm", "miam", "micm", "mitr", "suso"};

constexpr AerosolComponentNumber kContinentalClean[] = {{"waso", 2600.0}, {"inso", 0.15}};
constexpr AerosolComponentNumber kContinentalAverage[] = {
    {"waso", 7000.0}, {"inso", 0.4}, {"soot", 8300.0}};
constexpr AerosolComponentNumber kContinentalPolluted[] = {
    {"waso", 15700.0}, {"inso", 0.6}, {"soot", 34300.0}};
constexpr AerosolComponentNumber kUrban[] = {{"waso", 28000.0}, {"inso", 1.5}, {"soot", 130000.0}};
constexpr AerosolComponentNumber kDesert[] = {
    {"waso", 2000.0}, {"minm", 269.5}, {"miam", 30.5}, {"micm", 0.142}};
constexpr AerosolComponentNumber kMaritimeClean[] = {
    {"waso", 1500.0}, {"ssam", 20.0}, {"sscm", 3.2e-3}};
constexpr AerosolComponentNumber kMaritimePolluted[] = {
    {"waso", 3800.0}, {"ssam", 20.0}, {"sscm", 3.2e-3}, {"soot", 5180.0}};
constexpr AerosolComponentNumber kMaritimeTropical[] = {
    {"waso", 590.0}, {"ssam", 10.0}, {"sscm", 1.3e-3}};
constexpr AerosolComponentNumber kArctic[] = {
    {"inso", 0.01}, {"waso", 1300.0}, {"ssam", 1.9}, {"soot", 5300.0}};
constexpr AerosolComponentNumber kAntarctic[] = {{"suso", 42.9}, {"ssam", 0.047}, {"miam", 0.0053}};
constexpr AerosolComponentNumber kTropospheric[] = {{"waso", 1.0}};
constexpr AerosolComponentNumber kStratospheric[] = {{"suso", 1.0}};

const AerosolMixture kMixtures[] = {
    {"continental_clean", kContinentalClean, true, "OPAC continental clean"},
    {"continental_average", kContinentalAverage, true, "OPAC continental average"},
    {"continental_polluted", kContinentalPolluted, true, "OPAC continental polluted"},
    {"urban", kUrban, true, "OPAC urban"},
    {"desert", kDesert, true, "OPAC desert"},
    {"maritime_clean", kMaritimeClean, true, "OPAC maritime clean"},
    {"maritime_polluted", kMaritimePolluted, true, "OPAC maritime polluted"},
    {"maritime_tropical", kMaritimeTropical, true, "OPAC maritime tropical"},
    {"arctic", kArctic, true, "OPAC arctic"},
    {"antarctic", kAntarctic, true, "OPAC antarctic"},
    {"rural", kContinentalAverage, true, "Shettle & Fenn's rural: OPAC continental average"},
    {"maritime", kMaritimeClean, true, "Shettle & Fenn's maritime: OPAC maritime clean"},
    {"tropospheric", kTropospheric, true,
     "Shettle & Fenn's tropospheric: OPAC's water-soluble component"},
    {"stratospheric", kStratospheric, false,
     "stratospheric background: OPAC's sulphate droplets, dry"},
};

/// LOWTRAN 7's aerosol levels, km, and its 550 nm extinction there, km⁻¹.
constexpr std::array<double, 33> kLevelsKm{0,  1,  2,  3,  4,  5,  6,  7,  8,  9,  10,
                                           11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21,
                                           22, 23, 24, 25, 30, 35, 40, 45, 50, 70, 100};
/// Boundary layer (0, 1, 2 km) for visibilities 50, 23, 10, 5 and 2 km.
constexpr double kVisibilitiesKm[] = {50.0, 23.0, 10.0, 5.0, 2.0};
constexpr double kBoundaryLayer[3][5] = {
    {6.62e-02, 1.58e-01, 3.79e-01, 7.70e-01, 1.94e+00},
    {4.15e-02, 9.91e-02, 3.79e-01, 7.70e-01, 1.94e+00},
    {2.60e-02, 6.21e-02, 6.21e-02, 6.21e-02, 6.21e-02},
};
/// Troposphere, 3–10 km (levels 3 … 10), for 50 and 23 km visibility.
constexpr double kSpringSummer50[8] = {1.46e-02, 1.02e-02, 9.31e-03, 7.71e-03,
                                       6.23e-03, 3.37e-03, 1.82e-03, 1.14e-03};
constexpr double kSpringSummer23[8] = {3.46e-02, 1.85e-02, 9.31e-03, 7.71e-03,
                                       6.23e-03, 3.37e-03, 1.82e-03, 1.14e-03};
constexpr double kFallWinter50[8] = {1.14e-02, 6.43e-03, 4.85e-03, 3.54e-03,
                                     2.31e-03, 1.41e-03, 9.80e-04, 7.87e-04};
constexpr double kFallWinter23[8] = {2.72e-02, 1.20e-02, 4.85e-03, 3.54e-03,
                                     2.31e-03, 1.41e-03, 9.80e-04, 7.87e-04};
/// Stratospheric background, 11–30 km (levels 11 … 26), then the upper atmosphere to 100 km
/// (levels 27 … 32: 35, 40, 45, 50, 70, 100 km; the same in both seasons).
constexpr double kBackgroundSpringSummer[16] = {
    7.99e-04, 6.41e-04, 5.17e-04, 4.42e-04, 3.95e-04, 3.82e-04, 4.25e-04, 5.20e-04,
    5.81e-04, 5.89e-04, 5.02e-04, 4.20e-04, 3.00e-04, 1.98e-04, 1.31e-04, 3.32e-05};
constexpr double kBackgroundFallWinter[16] = {
    7.14e-04, 6.64e-04, 6.23e-04, 6.45e-04, 6.43e-04, 6.41e-04, 6.00e-04, 5.62e-04,
    4.91e-04, 4.23e-04, 3.52e-04, 2.95e-04, 2.42e-04, 1.90e-04, 1.50e-04, 3.32e-05};
constexpr double kUpper[6] = {1.64e-05, 7.99e-06, 4.01e-06, 2.10e-06, 1.60e-07, 9.31e-10};

/// a + (b − a)(1/V − 1/Va)/(1/Vb − 1/Va): linear in 1/V through (Va, a) and (Vb, b).
double in_inverse_visibility(double a, double va, double b, double vb, double v) {
    return a + (b - a) * (1.0 / v - 1.0 / va) / (1.0 / vb - 1.0 / va);
}

}  // namespace

std::optional<AerosolMixture> aerosol_mixture_named(std::string_view name) noexcept {
    for (const AerosolMixture& m : kMixtures) {
        if (name == m.name) return m;
    }
    return std::nullopt;
}

const char* aerosol_mixture_names() noexcept {
    static const std::string names = [] {
        std::string out;
        for (const AerosolMixture& m : kMixtures) {
            if (!out.empty()) out += ", ";
            out += m.name;
        }
        return out;
    }();
    return names.c_str();
}

bool is_aerosol_component(std::string_view name) noexcept {
    return std::find(std::begin(kComponentNames), std::end(kComponentNames), name) !=
           std::end(kComponentNames);
}

const char* aerosol_component_names() noexcept {
    static const std::string names = [] {
        std::string out;
        for (std::string_view n : kComponentNames)
            out += (out.empty() ? "" : ", ") + std::string(n);
        return out;
    }();
    return names.c_str();
}

std::span<const double> aerosol_profile_levels_km() noexcept { return kLevelsKm; }

RegimeExtinction lowtran_aerosol_extinction(std::size_t level, double visibility_km,
                                            AerosolSeason season) noexcept {
    RegimeExtinction out;
    const double v = visibility_km;
    if (level <= 2) {
        // The tabulated pair around V (the outermost pair beyond the table).
        std::size_t j = 1;
        while (j < 4 && v < kVisibilitiesKm[j]) ++j;
        const double* row = kBoundaryLayer[level];
        out.boundary_layer = std::max(0.0, in_inverse_visibility(row[j - 1], kVisibilitiesKm[j - 1],
                                                                 row[j], kVisibilitiesKm[j], v));
        return out;
    }
    if (level <= 10) {
        const bool summer = season == AerosolSeason::spring_summer;
        const double* clear = summer ? kSpringSummer50 : kFallWinter50;
        const double* hazy = summer ? kSpringSummer23 : kFallWinter23;
        const std::size_t i = level - 3;
        if (kLevelsKm[level] > 4.0 || v <= 23.0) {
            out.troposphere = kLevelsKm[level] > 4.0 ? clear[i] : hazy[i];
        } else {
            out.troposphere =
                std::max(0.0, in_inverse_visibility(hazy[i], 23.0, clear[i], 50.0, v));
        }
        return out;
    }
    if (level <= 26) {
        out.stratosphere =
            (season == AerosolSeason::spring_summer ? kBackgroundSpringSummer
                                                    : kBackgroundFallWinter)[level - 11];
        return out;
    }
    out.stratosphere = kUpper[std::min<std::size_t>(level - 27, 5)];
    return out;
}

}  // namespace glint::model
