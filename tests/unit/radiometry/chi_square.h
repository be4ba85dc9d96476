// SPDX-License-Identifier: Apache-2.0
// Test helpers for the radiometry sampling tests: a chi-square goodness-of-fit test of a
// direction sampler against its pdf, in the manner of pbrt-v4's chi2test. Directions are
// binned in (θ, φ) cells; each cell's expected count is N times the pdf integrated over the
// cell (composite Simpson on a sub-grid, in θ with the sin θ Jacobian); cells expected to
// hold fewer than 5 samples are pooled (smallest first) before the statistic is formed; the
// p-value is the upper tail of the chi-square distribution (regularised incomplete gamma).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "glint/core/rng.h"
#include "glint/radiometry/sampling.h"

namespace glint::radiometry::testing {

/// The p-value threshold of every chi-square test: a correct sampler fails a given seed with
/// probability 1e-3; with the fixed seeds the outcome is deterministic.
inline constexpr double kChiSquarePValueThreshold = 1e-3;

/// Upper regularised incomplete gamma Q(a, x) (series for x < a + 1, continued fraction
/// otherwise; Numerical Recipes §6.2).
inline double gamma_q(double a, double x) {
    if (x <= 0.0) return 1.0;
    const double log_prefix = a * std::log(x) - x - std::lgamma(a);
    if (x < a + 1.0) {
        double term = 1.0 / a, sum = term;
        for (int n = 1; n < 10000; ++n) {
            term *= x / (a + n);
            sum += term;
            if (std::abs(term) < std::abs(sum) * 1e-15) break;
        }
        return 1.0 - sum * std::exp(log_prefix);
    }
    const double tiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 10000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < 1e-15) break;
    }
    return std::exp(log_prefix) * h;
}

/// The outcome of a chi-square test.
struct ChiSquareResult {
    double statistic = 0.0;
    int dof = 0;
    double p_value = 1.0;
    double expected_total = 0.0;  ///< Σ expected counts (N × ∫ pdf over the binned region)
};

/// Pools cells with expected counts below `min_expected` (smallest first) and returns the
/// chi-square statistic, its degrees of freedom (cells − 1) and p-value.
inline ChiSquareResult chi_square(const std::vector<double>& observed,
                                  const std::vector<double>& expected, double min_expected = 5.0) {
    std::vector<std::size_t> order(observed.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return expected[a] < expected[b]; });
    ChiSquareResult r;
    double pool_obs = 0.0, pool_exp = 0.0;
    int cells = 0;
    for (std::size_t i : order) {
        r.expected_total += expected[i];
        if (expected[i] < min_expected) {
            pool_obs += observed[i];
            pool_exp += expected[i];
            continue;
        }
        const double d = observed[i] - expected[i];
        r.statistic += d * d / expected[i];
        ++cells;
    }
    if (pool_exp > 0.0) {
        // A pooled remainder below the minimum is merged into nothing further; pbrt adds it
        // as one cell when it reaches the minimum and drops it otherwise (with a warning).
        if (pool_exp >= min_expected) {
            const double d = pool_obs - pool_exp;
            r.statistic += d * d / pool_exp;
            ++cells;
        }
    } else if (pool_obs > 0.0) {
        r.statistic = 1e300;  // samples where the pdf is zero
    }
    r.dof = cells - 1;
    r.p_value = r.dof > 0 ? gamma_q(0.5 * r.dof, 0.5 * r.statistic) : 1.0;
    return r;
}

/// A binning of directions about +z: `theta_bins` × `phi_bins` cells over θ ∈ [0, θmax],
/// φ ∈ [0, 2π), plus one extra cell (index theta_bins·phi_bins) for "no sample" and for
/// directions outside θmax.
struct DirectionHistogram {
    int theta_bins = 10;
    int phi_bins = 20;
    double theta_max_rad = kPi / 2.0;

    int cells() const { return theta_bins * phi_bins + 1; }

    int cell_of(const std::optional<Vec3>& w) const {
        const int outside = theta_bins * phi_bins;
        if (!w) return outside;
        const double z = std::clamp(w->z, -1.0, 1.0);
        // θ from atan2 keeps resolution near the pole (sun-disk cones are 4.7 mrad wide).
        const double theta = std::atan2(std::hypot(w->x, w->y), z);
        if (theta >= theta_max_rad) return outside;
        double phi = std::atan2(w->y, w->x);
        if (phi < 0.0) phi += 2.0 * kPi;
        const int it =
            std::min(theta_bins - 1, static_cast<int>(theta / theta_max_rad * theta_bins));
        const int ip = std::min(phi_bins - 1, static_cast<int>(phi / (2.0 * kPi) * phi_bins));
        return it * phi_bins + ip;
    }

    /// N × ∫ pdf(ω) dω over each cell (Simpson with `sub` × `sub` panels per cell); the extra
    /// cell gets N − Σ so that a sampler that can fail is tested on its failure rate too.
    std::vector<double> expected(double n, const std::function<double(const Vec3&)>& pdf,
                                 int sub = 16) const {
        std::vector<double> e(static_cast<std::size_t>(cells()), 0.0);
        const double dt = theta_max_rad / theta_bins, dp = 2.0 * kPi / phi_bins;
        const int m = 2 * sub;  // Simpson needs an even number of intervals
        double total = 0.0;
        for (int it = 0; it < theta_bins; ++it) {
            for (int ip = 0; ip < phi_bins; ++ip) {
                double sum = 0.0;
                for (int a = 0; a <= m; ++a) {
                    const double wa = (a == 0 || a == m) ? 1.0 : (a % 2 ? 4.0 : 2.0);
                    const double theta = (it + static_cast<double>(a) / m) * dt;
                    const double st = std::sin(theta), ct = std::cos(theta);
                    for (int b = 0; b <= m; ++b) {
                        const double wb = (b == 0 || b == m) ? 1.0 : (b % 2 ? 4.0 : 2.0);
                        const double phi = (ip + static_cast<double>(b) / m) * dp;
                        const Vec3 w{st * std::cos(phi), st * std::sin(phi), ct};
                        sum += wa * wb * pdf(w) * st;
                    }
                }
                const double integral = sum * (dt / m / 3.0) * (dp / m / 3.0);
                e[static_cast<std::size_t>(it * phi_bins + ip)] = n * integral;
                total += n * integral;
            }
        }
        e.back() = std::max(0.0, n - total);
        return e;
    }
};

/// Draws `n` directions from `sample` (given two uniforms from a RandomStream keyed by
/// `seed` and `stream`), bins them and runs the chi-square test against `pdf`, integrated
/// with `sub` Simpson panels per cell side (peaked lobes near the horizon need more).
inline ChiSquareResult chi_square_direction_test(
    const DirectionHistogram& hist, int n,
    const std::function<std::optional<Vec3>(double, double)>& sample,
    const std::function<double(const Vec3&)>& pdf, std::uint64_t seed, std::uint64_t stream,
    int sub = 16) {
    RandomStream rng(seed, {stream});
    std::vector<double> observed(static_cast<std::size_t>(hist.cells()), 0.0);
    for (int i = 0; i < n; ++i) {
        const double u1 = rng.uniform();
        const double u2 = rng.uniform();
        observed[static_cast<std::size_t>(hist.cell_of(sample(u1, u2)))] += 1.0;
    }
    return chi_square(observed, hist.expected(n, pdf, sub));
}

/// The local unit direction at polar angle `theta_deg` from +z and azimuth `phi_deg` from +x.
inline Vec3 local_direction(double theta_deg, double phi_deg) {
    const double t = theta_deg * kPi / 180.0, p = phi_deg * kPi / 180.0;
    return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

/// ∫ g(ω) dω over the upper hemisphere by Simpson on 90 θ × 16 φ cells with `panels` × `panels`
/// panels each: the sum of DirectionHistogram's cells (its extra cell, max(0, 1 − Σ), is left
/// out, so an integral above 1 is not clipped).
inline double integrate_upper_hemisphere(const std::function<double(const Vec3&)>& g,
                                         int panels = 8) {
    DirectionHistogram h;
    h.theta_bins = 90;
    h.phi_bins = 16;
    const std::vector<double> cells = h.expected(1.0, g, panels);
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < cells.size(); ++i) sum += cells[i];
    return sum;
}

}  // namespace glint::radiometry::testing
