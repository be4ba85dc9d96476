// SPDX-License-Identifier: Apache-2.0
// Successive orders of scattering (glint/atmosphere/scattering_orders.h).
//
// Optical depth τ grows downward from the top; μ > 0 is upward travel. For azimuth mode m the
// radiance is Σ_m I^m(τ, μ) cos(mφ) with φ measured from the beam's direction of travel, and
// the source of the diffuse field
//   J^m(τ, μ) = (ω/2) Σ_j w_j P^m(μ, μ_j) I^m(τ, μ_j)
// over the 2N directions, P^m(μ, μ') = Σ_l (2l + 1) χ_l Λ_l^m(μ) Λ_l^m(μ') with the
// normalized associated Legendre functions Λ_l^m = √((l−m)!/(l+m)!) P_l^m. The direct beam
// (irradiance 1 normal to it) adds (ω/4π)(2 − δ_m0) P^m(μ, −μ₀) e^(−τ/μ₀), integrated
// exactly through each sublayer; the diffuse sources are linear within a sublayer.
#include "glint/atmosphere/scattering_orders.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "atmosphere_detail.h"
#include "glint/core/error.h"

namespace glint::atmosphere {
namespace {

/// The most sublayers a problem is split into (the 0.02 default depth up to a total optical
/// depth of 41).
constexpr std::size_t kMaxSublayers = 2048;

using detail::kPi;

/// Σ_m terms[m] cos(mφ).
}  // namespace

double sum_modes(std::span<const double> terms, double phi) {
    if (!std::isfinite(phi)) throw input_error("non-finite azimuth");
    double sum = 0.0;
    for (std::size_t m = 0; m < terms.size(); ++m) {
        sum += terms[m] * std::cos(static_cast<double>(m) * phi);
    }
    return sum;
}

void gauss_legendre_unit(int n, std::vector<double>& nodes, std::vector<double>& weights) {
    nodes.assign(static_cast<std::size_t>(n), 0.0);
    weights.assign(static_cast<std::size_t>(n), 0.0);
    for (int i = 0; i < n; ++i) {
        double x = std::cos(kPi * (i + 0.75) / (n + 0.5));
        double derivative = 1.0;
        for (int iteration = 0; iteration < 100; ++iteration) {
            double p0 = 1.0;
            double p1 = x;
            for (int k = 2; k <= n; ++k) {
                const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            derivative = n * (x * p1 - p0) / (x * x - 1.0);
            const double step = p1 / derivative;
            x -= step;
            if (std::abs(step) < 1e-15) break;
        }
        const double w = 2.0 / ((1.0 - x * x) * derivative * derivative);
        nodes[static_cast<std::size_t>(i)] = 0.5 * (x + 1.0);
        weights[static_cast<std::size_t>(i)] = 0.5 * w;
    }
}

namespace {

/// Λ_l^m(μ) for l = m … lmax (index l − m); sign conventions cancel in the products used.
std::vector<double> normalized_legendre(int m, int lmax, double mu) {
    std::vector<double> out;
    if (lmax < m) return out;
    out.reserve(static_cast<std::size_t>(lmax - m + 1));
    const double s = std::sqrt(std::max(0.0, 1.0 - mu * mu));
    double pmm = 1.0;
    for (int k = 1; k <= m; ++k) pmm *= std::sqrt((2.0 * k - 1.0) / (2.0 * k)) * s;
    out.push_back(pmm);
    if (lmax == m) return out;
    double previous = pmm;
    double current = mu * std::sqrt(2.0 * m + 1.0) * pmm;
    out.push_back(current);
    for (int l = m + 2; l <= lmax; ++l) {
        const double next = ((2.0 * l - 1.0) * mu * current -
                             std::sqrt((l - 1.0) * (l - 1.0) - double(m) * m) * previous) /
                            std::sqrt(double(l) * l - double(m) * m);
        out.push_back(next);
        previous = current;
        current = next;
    }
    return out;
}

/// P^m(μ, μ') of a layer's moments.
double phase_mode(const std::vector<double>& moments, int m, const std::vector<double>& a,
                  const std::vector<double>& b) {
    double sum = 0.0;
    for (std::size_t k = 0; k < a.size() && k < b.size(); ++k) {
        const std::size_t l = static_cast<std::size_t>(m) + k;
        if (l >= moments.size()) break;
        sum += (2.0 * static_cast<double>(l) + 1.0) * moments[l] * a[k] * b[k];
    }
    return sum;
}

/// ∫_0^Δ J(t) e^{−(Δ−t)/μ} dt/μ for J linear from `entry` to `exit`: the weights of the two.
void linear_weights(double x, double& entry, double& exit, double& attenuation) {
    attenuation = std::exp(-x);
    const double mean = x > 0.0 ? -std::expm1(-x) / x : 1.0;  // (1 − e^{−x})/x
    entry = mean - attenuation;
    exit = 1.0 - mean;
}

/// expm1(y)/y, 1 at y = 0.
double exprel(double y) { return std::abs(y) < 1e-12 ? 1.0 + 0.5 * y : std::expm1(y) / y; }

}  // namespace

ScatteringSolution solve_scattering_orders(const ScatteringProblem& problem) {
    const auto bad = [](double v) { return !std::isfinite(v); };
    if (problem.layers.empty()) throw input_error("scattering problem without layers");
    if (bad(problem.sun_cos_zenith) || problem.sun_cos_zenith <= 0.0 ||
        problem.sun_cos_zenith > 1.0) {
        throw input_error("scattering problem: sun cos zenith must lie in (0, 1]");
    }
    if (bad(problem.ground_albedo) || problem.ground_albedo < 0.0 || problem.ground_albedo > 1.0) {
        throw input_error("scattering problem: ground albedo must lie in [0, 1]");
    }
    if (bad(problem.beam_irradiance) || problem.beam_irradiance < 0.0 ||
        bad(problem.ground_planck) || problem.ground_planck < 0.0 ||
        bad(problem.top_isotropic_radiance) || problem.top_isotropic_radiance < 0.0) {
        throw input_error(
            "scattering problem: the beam, the ground's Planck radiance and the top's radiance "
            "must be finite and >= 0");
    }
    if (!problem.level_planck.empty()) {
        if (problem.level_planck.size() != problem.layers.size() + 1) {
            throw input_error("scattering problem: " + std::to_string(problem.level_planck.size()) +
                              " level Planck radiances for " +
                              std::to_string(problem.layers.size() + 1) + " levels");
        }
        for (double b : problem.level_planck) {
            if (bad(b) || b < 0.0) {
                throw input_error("scattering problem: level Planck radiances must be >= 0");
            }
        }
    }
    if (problem.streams < 2 || problem.azimuth_modes < 1 || !(problem.max_sublayer_depth > 0.0)) {
        throw input_error(
            "scattering problem: streams >= 2, azimuth modes >= 1 and a sublayer "
            "depth > 0 are required");
    }
    for (const ScatteringLayer& layer : problem.layers) {
        if (bad(layer.optical_depth) || layer.optical_depth < 0.0 ||
            bad(layer.single_scatter_albedo) || layer.single_scatter_albedo < 0.0 ||
            layer.single_scatter_albedo > 1.0 || layer.moments.empty() ||
            layer.moments.front() != 1.0) {
            throw input_error(
                "scattering layer needs an optical depth >= 0, a single-scatter "
                "albedo in [0, 1] and moments starting with 1");
        }
    }

    ScatteringSolution s;
    s.m_problem = problem;
    const int n = problem.streams;
    const std::size_t nd = static_cast<std::size_t>(2 * n);
    gauss_legendre_unit(n, s.m_mu, s.m_weight);
    // Sublayers of at most max_sublayer_depth, and at most kMaxSublayers in all: a thicker
    // atmosphere (fog, or an aerosol depth of 10^6 in a file) gets thicker sublayers, so its
    // memory and time stay bounded; the light through it is nil anyway.
    double total_depth = 0.0;
    for (const ScatteringLayer& layer : problem.layers) total_depth += layer.optical_depth;
    if (!std::isfinite(total_depth)) {
        throw input_error("scattering problem: the layers' optical depths add up to infinity");
    }
    const double sublayer_depth =
        std::max(problem.max_sublayer_depth, total_depth / static_cast<double>(kMaxSublayers));
    s.m_tau.push_back(0.0);
    s.m_level_boundary.push_back(0);
    for (std::size_t k = 0; k < problem.layers.size(); ++k) {
        const double depth = problem.layers[k].optical_depth;
        // At most kMaxSublayers + 1 per layer (rounding up), so the conversion is defined.
        const int parts =
            std::max(1, static_cast<int>(std::min(std::ceil(depth / sublayer_depth),
                                                  static_cast<double>(kMaxSublayers) + 1.0)));
        const double top = s.m_tau.back();
        for (int p = 1; p <= parts; ++p) {
            s.m_tau.push_back(top + depth * p / parts);
            s.m_layer_of.push_back(k);
        }
        s.m_level_boundary.push_back(s.m_tau.size() - 1);
    }
    const std::size_t sublayers = s.m_layer_of.size();
    const std::size_t boundaries = s.m_tau.size();
    // The layers' emission (1 − ω) B(τ) at the top and bottom of every sublayer, B linear in τ
    // within its layer (none without level Planck radiances).
    std::vector<double> emission_top(sublayers, 0.0), emission_bottom(sublayers, 0.0);
    if (!problem.level_planck.empty()) {
        for (std::size_t q = 0; q < sublayers; ++q) {
            const std::size_t k = s.m_layer_of[q];
            const double layer_top = s.m_tau[s.m_level_boundary[k]];
            const double depth = problem.layers[k].optical_depth;
            const double b0 = problem.level_planck[k];
            const double b1 = problem.level_planck[k + 1];
            const auto planck = [&](double tau) {
                return depth > 0.0 ? b0 + (b1 - b0) * (tau - layer_top) / depth : b0;
            };
            const double absorbing = 1.0 - problem.layers[k].single_scatter_albedo;
            emission_top[q] = absorbing * planck(s.m_tau[q]);
            emission_bottom[q] = absorbing * planck(s.m_tau[q + 1]);
        }
    }
    const double beam_scale = problem.beam_irradiance;
    const double mu0 = problem.sun_cos_zenith;
    const int lmax = 2 * n - 1;

    // Signed directions: 0..n−1 up (+μᵢ), n..2n−1 down (−μᵢ).
    std::vector<double> mu_signed(nd);
    for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
        mu_signed[i] = s.m_mu[i];
        mu_signed[i + static_cast<std::size_t>(n)] = -s.m_mu[i];
    }

    for (int m = 0; m < problem.azimuth_modes; ++m) {
        // Per layer: the diffuse source matrix K[a][b] = (ω/2) w_b P^m(μ_a, μ_b) and the
        // beam's source c_a = (ω/4π)(2 − δ_m0) P^m(μ_a, −μ₀).
        std::vector<std::vector<double>> lambda(nd);
        for (std::size_t a = 0; a < nd; ++a) lambda[a] = normalized_legendre(m, lmax, mu_signed[a]);
        const std::vector<double> lambda_sun = normalized_legendre(m, lmax, -mu0);
        const std::size_t layers = problem.layers.size();
        std::vector<std::vector<double>> kernel(layers, std::vector<double>(nd * nd, 0.0));
        std::vector<std::vector<double>> beam(layers, std::vector<double>(nd, 0.0));
        for (std::size_t k = 0; k < layers; ++k) {
            const ScatteringLayer& layer = problem.layers[k];
            const double omega = layer.single_scatter_albedo;
            for (std::size_t a = 0; a < nd; ++a) {
                for (std::size_t b = 0; b < nd; ++b) {
                    kernel[k][a * nd + b] = 0.5 * omega *
                                            s.m_weight[b % static_cast<std::size_t>(n)] *
                                            phase_mode(layer.moments, m, lambda[a], lambda[b]);
                }
                beam[k][a] = omega / (4.0 * kPi) * (m == 0 ? 1.0 : 2.0) *
                             phase_mode(layer.moments, m, lambda[a], lambda_sun);
            }
        }

        // One order: sources J (per sublayer, at its top and bottom) → field.
        std::vector<double> order(boundaries * nd, 0.0);  // field of the current order
        std::vector<double> total(boundaries * nd, 0.0);
        const auto at = [&](std::vector<double>& f, std::size_t boundary,
                            std::size_t dir) -> double& { return f[boundary * nd + dir]; };
        // Order 1: the direct beam scattered once, and (m = 0) the ground's reflection of it;
        // with thermal sources (m = 0), the radiance entering at the top, the layers' and
        // the ground's emission.
        {
            const bool thermal = m == 0;
            for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
                const double mu = s.m_mu[i];
                const std::size_t down = i + static_cast<std::size_t>(n);
                at(order, 0, down) = thermal ? problem.top_isotropic_radiance : 0.0;
                for (std::size_t q = 0; q < sublayers; ++q) {
                    const double t = s.m_tau[q];
                    const double d = s.m_tau[q + 1] - t;
                    const double e = std::exp(-d / mu);
                    // e^{−d/μ} exprel(y), y = d(1/μ − 1/μ₀); in a sublayer so thick that the
                    // product is 0 × ∞, its equal e^{−d/μ₀} exprel(−y), whose factors are finite.
                    const double y = d * (1.0 / mu - 1.0 / mu0);
                    double through = e * exprel(y);
                    if (!std::isfinite(through)) through = std::exp(-d / mu0) * exprel(-y);
                    const double integral = std::exp(-t / mu0) * (d / mu) * through;
                    at(order, q + 1, down) = at(order, q, down) * e +
                                             beam_scale * beam[s.m_layer_of[q]][down] * integral;
                    if (thermal) {
                        double entry = 0.0, exit = 0.0, attenuation = 0.0;
                        linear_weights(d / mu, entry, exit, attenuation);
                        at(order, q + 1, down) +=
                            entry * emission_top[q] + exit * emission_bottom[q];
                    }
                }
                at(order, sublayers, i) =
                    m == 0 ? beam_scale * problem.ground_albedo / kPi * mu0 *
                                     std::exp(-s.m_tau.back() / mu0) +
                                 (1.0 - problem.ground_albedo) * problem.ground_planck
                           : 0.0;
                for (std::size_t q = sublayers; q-- > 0;) {
                    const double t = s.m_tau[q];
                    const double d = s.m_tau[q + 1] - t;
                    const double e = std::exp(-d / mu);
                    const double integral = std::exp(-t / mu0) *
                                            (-std::expm1(-d * (1.0 / mu0 + 1.0 / mu))) * mu0 /
                                            (mu0 + mu);
                    at(order, q, i) =
                        at(order, q + 1, i) * e + beam_scale * beam[s.m_layer_of[q]][i] * integral;
                    if (thermal) {
                        double entry = 0.0, exit = 0.0, attenuation = 0.0;
                        linear_weights(d / mu, entry, exit, attenuation);
                        at(order, q, i) += entry * emission_bottom[q] + exit * emission_top[q];
                    }
                }
            }
        }
        std::vector<double> source_top(sublayers * nd), source_bottom(sublayers * nd);
        double previous_size = 0.0;
        int orders = 1;
        for (;;) {
            double size = 0.0;
            double field = 0.0;
            for (std::size_t j = 0; j < order.size(); ++j) {
                total[j] += order[j];
                size = std::max(size, std::abs(order[j]));
                field = std::max(field, std::abs(total[j]));
            }
            if (field == 0.0 || size <= 1e-300) break;
            if (orders >= 3 && previous_size > 0.0) {
                const double ratio = size / previous_size;
                if (ratio < 1.0) {
                    const double rest = ratio / (1.0 - ratio);
                    if (size * rest <= problem.tolerance * field) {
                        // The geometric rest of the series, shaped like the last order.
                        for (std::size_t j = 0; j < order.size(); ++j) total[j] += order[j] * rest;
                        break;
                    }
                }
            }
            if (orders >= problem.max_orders) break;
            previous_size = size;
            // Sources of the next order from this order's field.
            for (std::size_t q = 0; q < sublayers; ++q) {
                const std::vector<double>& kq = kernel[s.m_layer_of[q]];
                for (std::size_t a = 0; a < nd; ++a) {
                    double top = 0.0;
                    double bottom = 0.0;
                    const double* row = &kq[a * nd];
                    const double* f_top = &order[q * nd];
                    const double* f_bottom = &order[(q + 1) * nd];
                    for (std::size_t b = 0; b < nd; ++b) {
                        top += row[b] * f_top[b];
                        bottom += row[b] * f_bottom[b];
                    }
                    source_top[q * nd + a] = top;
                    source_bottom[q * nd + a] = bottom;
                }
            }
            // The ground's reflection of this order's downward flux (m = 0).
            double ground = 0.0;
            if (m == 0) {
                for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
                    ground += 2.0 * s.m_weight[i] * s.m_mu[i] *
                              order[sublayers * nd + i + static_cast<std::size_t>(n)];
                }
                ground *= problem.ground_albedo;
            }
            std::vector<double> next(boundaries * nd, 0.0);
            for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
                const double mu = s.m_mu[i];
                const std::size_t down = i + static_cast<std::size_t>(n);
                for (std::size_t q = 0; q < sublayers; ++q) {
                    double entry = 0.0, exit = 0.0, e = 0.0;
                    linear_weights((s.m_tau[q + 1] - s.m_tau[q]) / mu, entry, exit, e);
                    at(next, q + 1, down) = at(next, q, down) * e +
                                            entry * source_top[q * nd + down] +
                                            exit * source_bottom[q * nd + down];
                }
                at(next, sublayers, i) = ground;
                for (std::size_t q = sublayers; q-- > 0;) {
                    double entry = 0.0, exit = 0.0, e = 0.0;
                    linear_weights((s.m_tau[q + 1] - s.m_tau[q]) / mu, entry, exit, e);
                    at(next, q, i) = at(next, q + 1, i) * e + entry * source_bottom[q * nd + i] +
                                     exit * source_top[q * nd + i];
                }
            }
            order.swap(next);
            ++orders;
        }
        s.m_field.push_back(std::move(total));
        s.m_orders.push_back(orders);
    }
    return s;
}

double ScatteringSolution::optical_depth(std::size_t level) const noexcept {
    return m_tau[m_level_boundary[level]];
}

double ScatteringSolution::direct_flux(std::size_t level) const noexcept {
    const double mu0 = m_problem.sun_cos_zenith;
    return m_problem.beam_irradiance * mu0 * std::exp(-optical_depth(level) / mu0);
}

double ScatteringSolution::diffuse_down_flux(std::size_t level) const noexcept {
    const std::size_t n = m_mu.size();
    const std::size_t b = m_level_boundary[level];
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i)
        sum += m_weight[i] * m_mu[i] * m_field[0][b * 2 * n + n + i];
    return 2.0 * kPi * sum;
}

double ScatteringSolution::diffuse_up_flux(std::size_t level) const noexcept {
    const std::size_t n = m_mu.size();
    const std::size_t b = m_level_boundary[level];
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) sum += m_weight[i] * m_mu[i] * m_field[0][b * 2 * n + i];
    return 2.0 * kPi * sum;
}

double ScatteringSolution::multiple_scatter_up_radiance(std::size_t level, double mu,
                                                        double relative_azimuth_rad) const {
    return sum_modes(up_modes(level, mu, true), relative_azimuth_rad);
}

std::vector<double> ScatteringSolution::multiple_scatter_up_modes(std::size_t level,
                                                                  double mu) const {
    return up_modes(level, mu, true);
}

double ScatteringSolution::multiple_scatter_down_radiance(std::size_t level, double mu,
                                                          double relative_azimuth_rad) const {
    return sum_modes(down_modes(level, mu), relative_azimuth_rad);
}

std::vector<double> ScatteringSolution::multiple_scatter_down_modes(std::size_t level,
                                                                    double mu) const {
    return down_modes(level, mu);
}

double ScatteringSolution::single_scatter_up_radiance(std::size_t level, double mu,
                                                      double relative_azimuth_rad) const {
    return sum_modes(up_modes(level, mu, false), relative_azimuth_rad);
}

std::vector<double> ScatteringSolution::up_modes(std::size_t level, double mu, bool diffuse) const {
    if (!(mu > 0.0) || mu > 1.0) {
        throw input_error("upward radiance needs a direction cosine in (0, 1]");
    }
    const std::size_t n = m_mu.size();
    const std::size_t nd = 2 * n;
    const int lmax = static_cast<int>(nd) - 1;
    const double mu0 = m_problem.sun_cos_zenith;
    const std::size_t stop = m_level_boundary.at(level);
    const std::size_t sublayers = m_layer_of.size();
    std::vector<double> terms(m_field.size(), 0.0);
    for (std::size_t m = 0; m < m_field.size(); ++m) {
        const int mi = static_cast<int>(m);
        const std::vector<double> lambda_view = normalized_legendre(mi, lmax, mu);
        std::vector<std::vector<double>> lambda(nd);
        for (std::size_t b = 0; b < nd; ++b) {
            lambda[b] = normalized_legendre(mi, lmax, b < n ? m_mu[b] : -m_mu[b - n]);
        }
        const std::vector<double> lambda_sun = normalized_legendre(mi, lmax, -mu0);
        // Per layer: the view row of the kernel (diffuse) or the beam coefficient.
        const std::size_t layers = m_problem.layers.size();
        std::vector<std::vector<double>> row(layers, std::vector<double>(nd, 0.0));
        std::vector<double> beam(layers, 0.0);
        for (std::size_t k = 0; k < layers; ++k) {
            const ScatteringLayer& layer = m_problem.layers[k];
            const double omega = layer.single_scatter_albedo;
            for (std::size_t b = 0; b < nd; ++b) {
                row[k][b] = 0.5 * omega * m_weight[b % n] *
                            phase_mode(layer.moments, mi, lambda_view, lambda[b]);
            }
            beam[k] = m_problem.beam_irradiance * omega / (4.0 * kPi) * (m == 0 ? 1.0 : 2.0) *
                      phase_mode(layer.moments, mi, lambda_view, lambda_sun);
        }
        const std::vector<double>& field = m_field[m];
        const auto source = [&](std::size_t k, std::size_t boundary) {
            double sum = 0.0;
            for (std::size_t b = 0; b < nd; ++b) sum += row[k][b] * field[boundary * nd + b];
            return sum;
        };
        double value = 0.0;  // starts at the ground with nothing (path radiance only)
        for (std::size_t q = sublayers; q-- > stop;) {
            const std::size_t k = m_layer_of[q];
            const double d = m_tau[q + 1] - m_tau[q];
            if (diffuse) {
                double entry = 0.0, exit = 0.0, e = 0.0;
                linear_weights(d / mu, entry, exit, e);
                value = value * e + entry * source(k, q + 1) + exit * source(k, q);
            } else {
                const double e = std::exp(-d / mu);
                const double integral = std::exp(-m_tau[q] / mu0) *
                                        (-std::expm1(-d * (1.0 / mu0 + 1.0 / mu))) * mu0 /
                                        (mu0 + mu);
                value = value * e + beam[k] * integral;
            }
        }
        terms[m] = value;
    }
    return terms;
}

std::vector<double> ScatteringSolution::down_modes(std::size_t level, double mu) const {
    if (!(mu > 0.0) || mu > 1.0) {
        throw input_error("downward radiance needs a direction cosine in (0, 1]");
    }
    const std::size_t n = m_mu.size();
    const std::size_t nd = 2 * n;
    const int lmax = static_cast<int>(nd) - 1;
    const std::size_t stop = m_level_boundary.at(level);
    std::vector<double> terms(m_field.size(), 0.0);
    for (std::size_t m = 0; m < m_field.size(); ++m) {
        const int mi = static_cast<int>(m);
        // Travelling downward: the direction −μ.
        const std::vector<double> lambda_view = normalized_legendre(mi, lmax, -mu);
        const std::size_t layers = m_problem.layers.size();
        std::vector<std::vector<double>> row(layers, std::vector<double>(nd, 0.0));
        for (std::size_t b = 0; b < nd; ++b) {
            const std::vector<double> lambda =
                normalized_legendre(mi, lmax, b < n ? m_mu[b] : -m_mu[b - n]);
            for (std::size_t k = 0; k < layers; ++k) {
                const ScatteringLayer& layer = m_problem.layers[k];
                row[k][b] = 0.5 * layer.single_scatter_albedo * m_weight[b % n] *
                            phase_mode(layer.moments, mi, lambda_view, lambda);
            }
        }
        const std::vector<double>& field = m_field[m];
        const auto source = [&](std::size_t k, std::size_t boundary) {
            double sum = 0.0;
            for (std::size_t b = 0; b < nd; ++b) sum += row[k][b] * field[boundary * nd + b];
            return sum;
        };
        double value = 0.0;  // nothing scattered above the top
        for (std::size_t q = 0; q < stop; ++q) {
            const std::size_t k = m_layer_of[q];
            double entry = 0.0, exit = 0.0, e = 0.0;
            linear_weights((m_tau[q + 1] - m_tau[q]) / mu, entry, exit, e);
            value = value * e + entry * source(k, q) + exit * source(k, q + 1);
        }
        terms[m] = value;
    }
    return terms;
}

}  // namespace glint::atmosphere
