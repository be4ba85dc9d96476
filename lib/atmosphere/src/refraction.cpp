// SPDX-License-Identifier: Apache-2.0
// Atmospheric refraction (glint/atmosphere/refraction.h): the ray tracer through spherical
// shells of the refractivity profile (refractive_index.cpp: Ciddor's refractivity, the profile).
//
// The tracer: with c = n0 r0 sin z0 (Bouguer) and g(r) = n(r) r − c ≥ 0 along the ray, the
// path splits into pieces on which r is monotone; each runs from a lower radius r_lo (a
// tangent point, g = 0, or the lower end) up to r_hi. With r = r_lo + u² and
// n²r² − c² = g (g + 2c), every integrand carries 2u/√(g (g + 2c)), finite at u = 0 even at a
// tangent point, where g ≈ g'(r_lo) u². g is formed as g(r_lo) + [n r − n_lo r_lo] with the
// bracket u² n + r_lo (N − N_lo) (N = n − 1), so that it keeps its digits near u = 0.
#include "glint/atmosphere/refraction.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::atmosphere {
namespace refraction_detail {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;

/// A ray whose n r − c misses 0 by less than this at a tangent test counts as touching, m:
/// the rounding of n r near 6.4e6 m is ~1e-9 m.
constexpr double kTouchM = 1e-6;
/// Adaptive quadrature: the Kronrod–Gauss difference accepted on an interval for the angles
/// (rad) and the length (m), and the deepest bisection.
constexpr double kAngleToleranceRad = 1e-15;
constexpr double kLengthToleranceM = 1e-7;
constexpr int kMaxDepth = 40;

std::string kilometres(double altitude_m) { return format_ten_digits(altitude_m / 1000.0); }

/// The 15-point Kronrod rule on [−1, 1] (nodes ±x, weights) and the 7-point Gauss rule on the
/// odd ones (R. Piessens et al., QUADPACK, Springer, 1983).
constexpr std::array<double, 8> kKronrodNodes = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.0};
constexpr std::array<double, 8> kKronrodWeights = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr std::array<double, 4> kGaussWeights = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

/// Central angle, bending and length of a piece of a ray.
struct PathSums {
    double central_angle_rad = 0.0;
    double bending_rad = 0.0;
    double length_m = 0.0;
};

/// The integrands of one piece in u, r = r_lo + u².
class PieceIntegrand {
public:
    PieceIntegrand(const RefractiveProfile& profile, double earth_radius_m, double r_lo,
                   double g_lo, double c)
        : m_profile(profile), m_r_lo(r_lo), m_h_lo(r_lo - earth_radius_m), m_g_lo(g_lo), m_c(c) {}

    std::array<double, 3> operator()(double u) const {
        const double u2 = u * u;
        const double r = m_r_lo + u2;
        // The altitude from the piece's start, not from r: r's rounding (1e-9 m near 6.4e6 m)
        // would swamp N − N_lo, and with it g, at the smallest u.
        const double h = m_h_lo + u2;
        const double n = 1.0 + m_profile.refractivity(h);
        const double g = m_g_lo + u2 * n + m_r_lo * m_profile.refractivity_change(m_h_lo, u2);
        const double s = g * (g + 2.0 * m_c);  // n²r² − c²
        if (!(s > 0.0)) return {0.0, 0.0, 0.0};
        const double w = 2.0 * u / std::sqrt(s);
        return {w * m_c / r, -w * m_c * m_profile.refractivity_gradient_per_m(h) / n, w * n * r};
    }

private:
    const RefractiveProfile& m_profile;
    double m_r_lo;
    double m_h_lo;
    double m_g_lo;
    double m_c;
};

/// Adds the integral of `f` over [lo, hi] to `sums`, bisecting where the 7-point Gauss and
/// 15-point Kronrod rules differ by more than the tolerances.
void integrate(const PieceIntegrand& f, double lo, double hi, int depth, PathSums& sums) {
    const double half = 0.5 * (hi - lo);
    const double mid = 0.5 * (hi + lo);
    std::array<double, 3> kronrod{};
    std::array<double, 3> gauss{};
    for (std::size_t i = 0; i < kKronrodNodes.size(); ++i) {
        const double dx = half * kKronrodNodes[i];
        std::array<double, 3> value = f(mid - dx);
        if (dx > 0.0) {
            const std::array<double, 3> right = f(mid + dx);
            for (std::size_t k = 0; k < 3; ++k) value[k] += right[k];
        }
        for (std::size_t k = 0; k < 3; ++k) {
            kronrod[k] += kKronrodWeights[i] * value[k];
            if (i % 2 == 1) gauss[k] += kGaussWeights[i / 2] * value[k];
        }
    }
    const bool converged = std::abs(kronrod[0] - gauss[0]) * half <= kAngleToleranceRad &&
                           std::abs(kronrod[1] - gauss[1]) * half <= kAngleToleranceRad &&
                           std::abs(kronrod[2] - gauss[2]) * half <= kLengthToleranceM;
    if (converged || depth >= kMaxDepth) {
        sums.central_angle_rad += kronrod[0] * half;
        sums.bending_rad += kronrod[1] * half;
        sums.length_m += kronrod[2] * half;
        return;
    }
    integrate(f, lo, mid, depth + 1, sums);
    integrate(f, mid, hi, depth + 1, sums);
}

/// The central angle from the perigee of a straight line at distance `c` from the centre to its
/// point at radius r, and the length from the perigee (0 for r ≤ c).
double straight_angle_rad(double r, double c) {
    return std::atan2(std::sqrt(std::max((r - c) * (r + c), 0.0)), c);
}
double straight_length_m(double r, double c) { return std::sqrt(std::max((r - c) * (r + c), 0.0)); }

void check_altitude(const char* what, double altitude_m) {
    if (!std::isfinite(altitude_m) || altitude_m < 0.0) {
        throw input_error(std::string("refraction: the ") + what +
                          " must be at least 0 m (the ground), got " +
                          format_ten_digits(altitude_m) + " m");
    }
}

void check_zenith(const char* what, double zenith_deg) {
    if (!(zenith_deg >= 0.0 && zenith_deg <= 180.0)) {
        throw input_error(std::string("refraction: the ") + what +
                          " must lie in [0, 180] degrees, got " + format_ten_digits(zenith_deg));
    }
}

}  // namespace
}  // namespace refraction_detail

// ---- The tracer ----------------------------------------------------------------------------

namespace refraction_detail {
namespace {

/// One piece of a ray on which r is monotone: from r_lo (where n r − c = g_lo ≥ 0) to r_hi.
struct Piece {
    double r_lo = 0.0;
    double r_hi = 0.0;
    double g_lo = 0.0;
};

/// Central angle, bending and length of `piece` of the ray of invariant `c`.
PathSums integrate_piece(const RefractiveProfile& profile, double earth_radius_m,
                         const Piece& piece, double c) {
    PathSums sums;
    const double r_top = earth_radius_m + profile.top_altitude_m();
    if (piece.r_lo < r_top && piece.r_hi > piece.r_lo) {
        const double r_air = std::min(piece.r_hi, r_top);
        const PieceIntegrand f(profile, earth_radius_m, piece.r_lo, piece.g_lo, c);
        const double h_lo = piece.r_lo - earth_radius_m;
        const double h_air = r_air - earth_radius_m;
        double u_lo = 0.0;
        for (double level_m : profile.level_altitudes_m()) {
            if (level_m <= h_lo || level_m >= h_air) continue;
            const double u = std::sqrt(level_m - h_lo);
            integrate(f, u_lo, u, 0, sums);
            u_lo = u;
        }
        integrate(f, u_lo, std::sqrt(r_air - piece.r_lo), 0, sums);
    }
    if (piece.r_hi > r_top) {
        const double r_start = std::max(piece.r_lo, r_top);
        sums.central_angle_rad +=
            straight_angle_rad(piece.r_hi, c) - straight_angle_rad(r_start, c);
        sums.length_m += straight_length_m(piece.r_hi, c) - straight_length_m(r_start, c);
        if (piece.r_lo < r_top) {
            // The step of n at the top (n − 1 of order 1e-10 there) refracts the ray once:
            // the zenith angle jumps from asin(c/(n r)) to asin(c/r).
            const double g_top = (1.0 + profile.refractivity(profile.top_altitude_m())) * r_top - c;
            const double below = std::atan2(c, std::sqrt(std::max(g_top * (g_top + 2.0 * c), 0.0)));
            sums.bending_rad += std::atan2(c, straight_length_m(r_top, c)) - below;
        }
    }
    return sums;
}

}  // namespace
}  // namespace refraction_detail

RefractionTracer::RefractionTracer(RefractiveProfile profile, double earth_radius_m)
    : m_profile(std::move(profile)), m_earth_radius_m(earth_radius_m) {
    if (!(earth_radius_m > 0.0) || !std::isfinite(earth_radius_m)) {
        throw input_error("refraction: the Earth radius must be > 0 m and finite, got " +
                          format_ten_digits(earth_radius_m) + " m");
    }
    // d(n r)/dr = 1 + N + r dN/dh must stay > 0 from the ground to the top. Within a segment
    // it is monotone (its derivative 2 N' + r N'' keeps one sign: N' and N'' are N k and N k²
    // for the exponential, k and 0 for the linear law), so the segment's ends decide.
    const auto altitudes = m_profile.level_altitudes_m();
    for (std::size_t k = 0; k + 1 < altitudes.size(); ++k) {
        const double lo = k == 0 ? std::min(0.0, altitudes[0]) : altitudes[k];
        const double hi = altitudes[k + 1];
        if (hi <= 0.0) continue;
        const double ends[2] = {std::max(lo, 0.0), hi};
        for (double h : ends) {
            // The segment's own law at its upper end: step just inside it.
            const double inside = h == hi ? std::nextafter(hi, lo) : h;
            const double gradient = m_profile.refractivity_gradient_per_m(inside);
            const double slope =
                1.0 + m_profile.refractivity(inside) + (earth_radius_m + h) * gradient;
            if (!(slope > 0.0)) {
                throw input_error(
                    "refraction: n r decreases with height between " +
                    refraction_detail::kilometres(std::max(lo, 0.0)) + " and " +
                    refraction_detail::kilometres(hi) +
                    " km (d(n-1)/dh = " + format_ten_digits(gradient) +
                    " /m, steeper than -n/r: super-refraction); rays would be trapped, which the "
                    "tracer does not follow");
            }
        }
    }
}

RefractedPath RefractionTracer::trace(double observer_altitude_m, double apparent_zenith_deg,
                                      double end_altitude_m) const {
    using namespace refraction_detail;
    check_altitude("observer's altitude", observer_altitude_m);
    check_zenith("apparent zenith angle", apparent_zenith_deg);
    check_altitude("end altitude", end_altitude_m);

    const double a = m_earth_radius_m;
    const double r0 = a + observer_altitude_m;
    const double r_end = a + end_altitude_m;
    const double n0 = 1.0 + m_profile.refractivity(observer_altitude_m);
    const double zenith = apparent_zenith_deg * kRadPerDeg;
    const double sin_z = std::sin(zenith);
    const double cos_z = std::cos(zenith);
    const double c = n0 * r0 * sin_z;
    // n r − c at the observer, n0 r0 (1 − sin z) written without the cancellation.
    const double g0 = n0 * r0 * cos_z * cos_z / (1.0 + sin_z);
    const auto g_at = [&](double r) { return (1.0 + m_profile.refractivity(r - a)) * r - c; };
    const auto where = [&] {
        return "the ray from " + format_ten_digits(observer_altitude_m) + " m at zenith angle " +
               format_ten_digits(apparent_zenith_deg) + " degrees";
    };
    // The tangent radius of a descending ray, n r = c, between `r_lo` (where n r ≤ c) and the
    // observer or the top, whichever is lower (where n r > c).
    const double r_top = a + m_profile.top_altitude_m();
    const auto tangent_radius = [&](double r_lo) {
        if (c >= r_top) return std::min(c, r0);  // in the vacuum above the profile
        double lo = r_lo;
        double hi = std::min(r0, r_top);
        for (int i = 0; i < 200; ++i) {
            const double mid = 0.5 * (lo + hi);
            if (!(mid > lo && mid < hi)) break;
            (g_at(mid) > 0.0 ? hi : lo) = mid;
        }
        return lo;
    };

    RefractedPath path;
    std::vector<Piece> pieces;
    bool ends_ascending = true;
    double g_end = 0.0;
    if (apparent_zenith_deg <= 90.0) {
        if (end_altitude_m < observer_altitude_m) {
            throw input_error("refraction: " + where() + " rises and never comes down to " +
                              format_ten_digits(end_altitude_m) + " m");
        }
        if (r_end == r0) {
            path.geometric_zenith_deg = apparent_zenith_deg;
            path.end_zenith_deg = apparent_zenith_deg;
            return path;
        }
        pieces.push_back({r0, r_end, g0});
        g_end = r_end >= r_top ? r_end - c : g_at(r_end);
    } else if (end_altitude_m < observer_altitude_m) {
        g_end = g_at(r_end);
        if (g_end < -kTouchM) {
            throw input_error("refraction: " + where() + " turns back at its tangent point at " +
                              format_ten_digits(tangent_radius(r_end) - a) +
                              " m, above the end altitude " + format_ten_digits(end_altitude_m) +
                              " m");
        }
        g_end = std::max(g_end, 0.0);
        pieces.push_back({r_end, r0, g_end});
        ends_ascending = false;
    } else {
        const double g_ground = g_at(a);
        if (g_ground > kTouchM) {
            throw input_error("refraction: " + where() + " meets the ground before it reaches " +
                              format_ten_digits(end_altitude_m) + " m");
        }
        const double r_tangent = g_ground >= -kTouchM ? a : tangent_radius(a);
        path.tangent_altitude_m = r_tangent - a;
        pieces.push_back({r_tangent, r0, 0.0});
        pieces.push_back({r_tangent, r_end, 0.0});
        g_end = r_end >= r_top ? r_end - c : g_at(r_end);
    }

    PathSums sums;
    for (const Piece& piece : pieces) {
        const PathSums part = integrate_piece(m_profile, a, piece, c);
        sums.central_angle_rad += part.central_angle_rad;
        sums.bending_rad += part.bending_rad;
        sums.length_m += part.length_m;
    }
    const double phi = sums.central_angle_rad;
    const double half_sin = std::sin(0.5 * phi);
    path.central_angle_rad = phi;
    path.bending_rad = sums.bending_rad;
    path.path_length_m = sums.length_m;
    path.geometric_zenith_deg =
        std::atan2(r_end * std::sin(phi), (r_end - r0) - 2.0 * r_end * half_sin * half_sin) /
        kRadPerDeg;
    path.chord_length_m =
        std::sqrt((r_end - r0) * (r_end - r0) + 4.0 * r0 * r_end * half_sin * half_sin);
    g_end = std::max(g_end, 0.0);
    const double end_zenith = std::atan2(c, std::sqrt(g_end * (g_end + 2.0 * c))) / kRadPerDeg;
    path.end_zenith_deg = ends_ascending ? end_zenith : 180.0 - end_zenith;
    return path;
}

double RefractionTracer::astronomical_refraction_deg(double observer_altitude_m,
                                                     double apparent_zenith_deg) const {
    // To beyond the top, so that the ray also crosses the step of n there.
    const double beyond = std::max(m_profile.top_altitude_m(), observer_altitude_m) + 1000.0;
    return trace(observer_altitude_m, apparent_zenith_deg, beyond).bending_rad /
           refraction_detail::kRadPerDeg;
}

std::optional<double> RefractionTracer::apparent_zenith_for_true_deg(double observer_altitude_m,
                                                                     double true_zenith_deg) const {
    using namespace refraction_detail;
    check_altitude("observer's altitude", observer_altitude_m);
    check_zenith("true zenith angle", true_zenith_deg);
    if (true_zenith_deg == 0.0) return 0.0;
    // The lowest ray that misses the ground grazes it: n(0) a = n0 r0 sin z.
    const double a = m_earth_radius_m;
    const double r0 = a + observer_altitude_m;
    const double grazing = (1.0 + m_profile.refractivity(0.0)) * a /
                           ((1.0 + m_profile.refractivity(observer_altitude_m)) * r0);
    const double z_max = grazing >= 1.0 ? 90.0 : 180.0 - std::asin(grazing) / kRadPerDeg;
    const auto excess = [&](double z) {
        return z + astronomical_refraction_deg(observer_altitude_m, z) - true_zenith_deg;
    };
    double lo = 0.0;
    double f_lo = -true_zenith_deg;
    double hi = z_max;
    double f_hi = excess(z_max);
    constexpr double kToleranceDeg = 1e-10;
    if (f_hi < -kToleranceDeg) return std::nullopt;  // below the apparent horizon
    if (f_hi <= kToleranceDeg) return z_max;
    // Regula falsi with the Illinois halving (f is smooth and increasing).
    int side = 0;
    for (int i = 0; i < 200; ++i) {
        const double z = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
        const double f = excess(z);
        if (std::abs(f) <= kToleranceDeg || hi - lo <= 1e-12) return z;
        if (f > 0.0) {
            hi = z;
            f_hi = f;
            if (side == 1) f_lo *= 0.5;
            side = 1;
        } else {
            lo = z;
            f_lo = f;
            if (side == -1) f_hi *= 0.5;
            side = -1;
        }
    }
    return 0.5 * (lo + hi);
}

GroundIntersection RefractionTracer::ground_intersection(double sensor_altitude_m,
                                                         double nadir_angle_deg,
                                                         double ground_altitude_m) const {
    using namespace refraction_detail;
    check_altitude("ground altitude", ground_altitude_m);
    if (!(sensor_altitude_m > ground_altitude_m) || !std::isfinite(sensor_altitude_m)) {
        throw input_error("refraction: the sensor's altitude must lie above the ground's (" +
                          format_ten_digits(ground_altitude_m) + " m), got " +
                          format_ten_digits(sensor_altitude_m) + " m");
    }
    if (!(nadir_angle_deg >= 0.0 && nadir_angle_deg < 90.0)) {
        throw input_error("refraction: the nadir angle must lie in [0, 90) degrees, got " +
                          format_ten_digits(nadir_angle_deg));
    }
    const double r_sensor = m_earth_radius_m + sensor_altitude_m;
    const double r_ground = m_earth_radius_m + ground_altitude_m;
    const double nadir = nadir_angle_deg * kRadPerDeg;
    const double sin_ground = r_sensor * std::sin(nadir) / r_ground;
    if (sin_ground >= 1.0) {
        throw input_error(
            "refraction: the view ray at nadir angle " + format_ten_digits(nadir_angle_deg) +
            " degrees from " + format_ten_digits(sensor_altitude_m) +
            " m passes above the ground at " + format_ten_digits(ground_altitude_m) +
            " m (its horizon lies at nadir angle " +
            format_ten_digits(std::asin(r_ground / r_sensor) / kRadPerDeg) + " degrees)");
    }
    GroundIntersection out;
    const double straight_zenith = std::asin(sin_ground);
    out.straight_arc_m = r_ground * (straight_zenith - nadir);
    out.straight_view_zenith_deg = straight_zenith / kRadPerDeg;
    out.straight_range_m = r_sensor * std::cos(nadir) - r_ground * std::cos(straight_zenith);
    // Refraction only steepens the ray (n r > r), so a straight ray that meets the ground
    // leaves the refracted one meeting it too.
    const RefractedPath path = trace(sensor_altitude_m, 180.0 - nadir_angle_deg, ground_altitude_m);
    out.arc_m = r_ground * path.central_angle_rad;
    out.displacement_m = out.straight_arc_m - out.arc_m;
    out.view_zenith_deg = 180.0 - path.end_zenith_deg;
    out.path_length_m = path.path_length_m;
    return out;
}

}  // namespace glint::atmosphere
