// SPDX-License-Identifier: Apache-2.0
// The index colour map of glint-envi convert: golden-ratio hues per label, the names of
// --colormap, and which bands hold labels (glint/app_envi/colormap.h).
#include "glint/app_envi/colormap.h"

#include <cmath>
#include <cstdint>

#include "glint/core/text.h"

namespace glint::app_envi {
namespace {

/// frac(1 / phi), frac(sqrt 2) and frac(sqrt 3) in 64-bit fixed point, made odd: k times one
/// of them, modulo 2^64, is frac(k x) (a Weyl sequence), exact for every k.
constexpr std::uint64_t kGoldenStep = 0x9E3779B97F4A7C15ull;
constexpr std::uint64_t kRoot2Step = 0x6A09E667F3BCC909ull;
constexpr std::uint64_t kRoot3Step = 0xBB67AE8584CAA73Bull;
constexpr double kMaxLabel = 9007199254740992.0;  // 2^53

/// frac(k x) in [0, 1) for the fixed-point x `step`.
double weyl(std::uint64_t k, std::uint64_t step) {
    return static_cast<double>((k * step) >> 11) * 0x1p-53;
}

std::array<double, 3> hsv_to_rgb(double hue, double saturation, double value) {
    const double h6 = hue * 6.0;
    const int sector = static_cast<int>(h6) % 6;
    const double f = h6 - std::floor(h6);
    const double p = value * (1.0 - saturation);
    const double q = value * (1.0 - saturation * f);
    const double t = value * (1.0 - saturation * (1.0 - f));
    switch (sector) {
        case 0:
            return {value, t, p};
        case 1:
            return {q, value, p};
        case 2:
            return {p, value, t};
        case 3:
            return {p, q, value};
        case 4:
            return {t, p, value};
        default:
            return {value, p, q};
    }
}

bool ends_with_index(std::string_view name) {
    constexpr std::string_view kSuffix = "index";
    name = trim(name);
    return name.size() >= kSuffix.size() &&
           iequals(name.substr(name.size() - kSuffix.size()), kSuffix);
}

}  // namespace

std::optional<Colormap> colormap_from_name(std::string_view name) {
    if (name == "auto") return Colormap::automatic;
    if (name == "index") return Colormap::index;
    if (name == "none") return Colormap::none;
    return std::nullopt;
}

const char* colormap_name(Colormap colormap) {
    switch (colormap) {
        case Colormap::automatic:
            return "auto";
        case Colormap::index:
            return "index";
        case Colormap::none:
            return "none";
    }
    return "none";
}

std::array<double, 3> index_colour(double value) {
    if (!(std::fabs(value) <= kMaxLabel)) return {0.0, 0.0, 0.0};  // NaN, ±inf, too large
    const auto k = static_cast<std::uint64_t>(static_cast<std::int64_t>(std::nearbyint(value)));
    return hsv_to_rgb(weyl(k, kGoldenStep), 1.0 - 0.45 * weyl(k, kRoot3Step),
                      1.0 - 0.4 * weyl(k, kRoot2Step));
}

bool is_index_band(std::string_view name, std::string_view unit) {
    unit = trim(unit);
    if (!unit.empty()) return iequals(unit, "index");
    return ends_with_index(name);
}

}  // namespace glint::app_envi
