// SPDX-License-Identifier: Apache-2.0
// Time-resolved laser returns (glint/radiometry/lidar.h).
#include "glint/radiometry/lidar.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/radiometry/clear_sheets.h"
#include "glint/radiometry/mixture_draw.h"
#include "glint/radiometry/sampling.h"
#include "glint/radiometry/shading_normal.h"

namespace glint::radiometry {
namespace {

/// σ of a Gaussian per unit FWHM: 1 / (2 √(2 ln 2)).
constexpr double kSigmaPerFwhm = 0.42466090014400953;
/// A Gaussian pulse's extent, σ either side (C < 1e-9 beyond it).
constexpr double kGaussianReachSigma = 6.0;

}  // namespace

PulseShape PulseShape::gaussian(double fwhm_s) {
    if (!(fwhm_s > 0.0) || !std::isfinite(fwhm_s)) {
        throw input_error("pulse duration " + format_shortest(fwhm_s) +
                          " s: expected a positive FWHM");
    }
    PulseShape shape;
    shape.m_sigma_s = fwhm_s * kSigmaPerFwhm;
    shape.m_begin_s = -kGaussianReachSigma * shape.m_sigma_s;
    shape.m_end_s = kGaussianReachSigma * shape.m_sigma_s;
    return shape;
}

PulseShape PulseShape::tabulated(std::vector<double> time_s, std::vector<double> power) {
    if (time_s.size() != power.size() || time_s.size() < 2) {
        throw input_error("a tabulated pulse shape needs at least 2 (time, power) rows, got " +
                          std::to_string(std::min(time_s.size(), power.size())));
    }
    for (std::size_t i = 0; i < time_s.size(); ++i) {
        if (!std::isfinite(time_s[i]) || !std::isfinite(power[i]) || power[i] < 0.0) {
            throw input_error("pulse shape row " + std::to_string(i + 1) +
                              ": expected a finite time and a power >= 0");
        }
        if (i > 0 && !(time_s[i] > time_s[i - 1])) {
            throw input_error("pulse shape row " + std::to_string(i + 1) + ": time " +
                              format_shortest(time_s[i]) + " s does not increase");
        }
    }
    PulseShape shape;
    shape.m_cumulative.assign(time_s.size(), 0.0);
    for (std::size_t i = 1; i < time_s.size(); ++i) {
        shape.m_cumulative[i] = shape.m_cumulative[i - 1] +
                                0.5 * (power[i] + power[i - 1]) * (time_s[i] - time_s[i - 1]);
    }
    const double energy = shape.m_cumulative.back();
    if (!(energy > 0.0)) throw input_error("the tabulated pulse shape holds no energy");
    for (double& p : power) p /= energy;
    for (double& c : shape.m_cumulative) c /= energy;
    shape.m_begin_s = time_s.front();
    shape.m_end_s = time_s.back();
    shape.m_time_s = std::move(time_s);
    shape.m_power = std::move(power);
    return shape;
}

double PulseShape::cumulative(double t_s) const noexcept {
    if (m_sigma_s > 0.0) {
        return 0.5 * std::erfc(-t_s / (m_sigma_s * std::numbers::sqrt2));
    }
    if (t_s <= m_begin_s) return 0.0;
    if (t_s >= m_end_s) return 1.0;
    const auto upper = std::upper_bound(m_time_s.begin(), m_time_s.end(), t_s);
    const std::size_t i = static_cast<std::size_t>(upper - m_time_s.begin()) - 1;
    const double dt = t_s - m_time_s[i];
    const double slope = (m_power[i + 1] - m_power[i]) / (m_time_s[i + 1] - m_time_s[i]);
    return m_cumulative[i] + m_power[i] * dt + 0.5 * slope * dt * dt;
}

void deposit(const PulseShape& shape, const TimeGate& gate, double delay_s, double value,
             std::span<double> histogram) noexcept {
    if (gate.samples == 0 || !(gate.sample_width_s > 0.0) || value == 0.0) return;
    const double first = (delay_s + shape.begin_s() - gate.start_s) / gate.sample_width_s;
    const double last = (delay_s + shape.end_s() - gate.start_s) / gate.sample_width_s;
    if (!(last >= 0.0) || !(first < static_cast<double>(gate.samples))) return;
    const std::size_t j0 = first <= 0.0 ? 0 : static_cast<std::size_t>(first);
    const std::size_t j1 =
        std::min(gate.samples - 1, static_cast<std::size_t>(std::max(0.0, std::floor(last))));
    double below =
        shape.cumulative(gate.start_s + static_cast<double>(j0) * gate.sample_width_s - delay_s);
    for (std::size_t j = j0; j <= j1; ++j) {
        const double above = shape.cumulative(
            gate.start_s + static_cast<double>(j + 1) * gate.sample_width_s - delay_s);
        histogram[j] += value * (above - below);
        below = above;
    }
}

double LaserPulse::intensity_j_per_sr(const Vec3& d) const noexcept {
    const double w = 0.5 * divergence_rad;
    const double alpha = std::atan2(norm(cross(axis, d)), dot(axis, d));
    return energy_j * 2.0 / (std::numbers::pi * w * w) * std::exp(-2.0 * alpha * alpha / (w * w));
}

LidarTracer::LidarTracer(const scene::GeometryScene& scene, const MaterialTable& materials,
                         TracerSettings settings, const PulseShape& shape, TimeGate gate)
    : m_scene(scene), m_materials(materials), m_settings(settings), m_shape(shape), m_gate(gate) {
    if (materials.size() > 0 && materials.bands() != 1) {
        throw input_error("the lidar's materials have " + std::to_string(materials.bands()) +
                          " bands, expected 1 (the laser line)");
    }
    if (settings.max_bounces > kMaxBouncesLimit) {
        throw usage_error("max bounces " + std::to_string(settings.max_bounces) +
                          " exceeds the limit of " + std::to_string(kMaxBouncesLimit));
    }
    if (gate.samples == 0 || !(gate.sample_width_s > 0.0)) {
        throw usage_error("a lidar gate needs time samples of positive width");
    }
}

void LidarTracer::trace(const SampleRay& ray, const LaserPulse& laser, RandomStream& rng,
                        std::span<double> histogram, std::uint64_t& rays) const {
    const double time = ray.time_s;
    std::optional<scene::RayHit> hit = m_scene.intersect(ray.origin_m, ray.direction, time);
    ++rays;
    double beta = ray.weight;
    double travelled_m = 0.0;
    Vec3 direction = ray.direction;
    for (unsigned bounce = 0; hit; ++bounce) {
        draw_mixture_material(m_scene, *hit, rng);
        const std::size_t m = hit->material;
        if (!m_materials.scatters(m)) break;
        // The black back face of a single-sided material.
        if (!m_materials.double_sided(m) && dot(hit->normal, direction) > 0.0) break;
        travelled_m += hit->distance_m;
        const Vec3 wo = -direction;
        const bool back_face = dot(hit->normal, wo) < 0.0;
        const Vec3 geometric = back_face ? -hit->normal : hit->normal;
        // A bump map's tilted normal: the BSDF's frame and cosines (shading_normal.h).
        const Vec3 normal = shading_normal(*hit, geometric, back_face);
        const Bsdf& bsdf = m_materials.bsdf(m);
        const Frame frame = shading_frame(bsdf, normal);
        const Vec3 wo_local = frame.to_local(wo);
        const double rho = m_materials.reflectance(m)[0];
        const double tau = m_materials.transmittance(m)[0];
        const bool reflects = m_materials.reflects(m);
        const bool transmits = m_materials.transmits(m);
        // The laser by next-event estimation: one shadow ray.
        const Vec3 to_laser = laser.position_m - hit->position_m;
        const double r_m = norm(to_laser);
        if (r_m > 0.0 && wo_local.z > 0.0 && same_side(geometric, normal, to_laser)) {
            const Vec3 wi = (1.0 / r_m) * to_laser;
            const double cos_i = dot(normal, wi);
            // In front: reflected (ρ · shape); behind a thin sheet: transmitted (τ/π).
            if (cos_i > 0.0 ? reflects : (cos_i < 0.0 && transmits && !bsdf.straight())) {
                const Vec3 origin = m_scene.spawn_origin(*hit, wi);
                ++rays;
                const double reach_m = norm(laser.position_m - origin);
                // Clear sheets between the point and the transmitter pass the pulse attenuated
                // by their τ at the laser's band (the first of the grid).
                double through = 1.0;
                bool clear = !m_scene.occluded(origin, wi, time, 0.0, reach_m);
                if (!clear && m_materials.any_straight()) {
                    std::vector<double> sheets(m_materials.bands(), 1.0);
                    clear =
                        pass_clear_sheets(m_scene, m_materials, origin, wi, time, reach_m, sheets);
                    through = sheets[0];
                }
                if (clear) {
                    // I |cos θ| / r², m² → cm² (10⁴), times the BRDF or BTDF.
                    const double fluence = laser.intensity_j_per_sr(-wi) * std::abs(cos_i) /
                                           (r_m * r_m * 1e4) * through;
                    const double value =
                        cos_i > 0.0
                            ? beta * rho * bsdf.reflection(wo_local, frame.to_local(wi)) * fluence
                            : beta * (tau / kPi) * fluence;
                    deposit(m_shape, m_gate, (travelled_m + r_m) / kSpeedOfLightMPerS, value,
                            histogram);
                }
            }
        }
        if (bounce >= m_settings.max_bounces) break;
        // As the path tracer: through the sheet with probability P_t, else reflected; an
        // opaque material draws no number for the choice.
        const double p_transmit = bsdf.transmission_probability();
        const double u_side = p_transmit > 0.0 ? rng.uniform() : 1.0;
        const double u_lobe = rng.uniform();
        const double u1 = rng.uniform();
        const double u2 = rng.uniform();
        const auto sample = bsdf.sample(wo_local, u_side, u_lobe, u1, u2);
        if (!sample || !(sample->weight > 0.0)) break;
        const Vec3 next = sample->wi;
        beta *= (sample->side == ScatterSide::transmitted ? tau : rho) * sample->weight;
        if (!(beta > 0.0)) break;
        if (bounce + 1 >= m_settings.roulette_start_bounce) {
            const double survive = std::min(1.0, beta / ray.weight);
            if (rng.uniform() >= survive) break;
            beta /= survive;
        }
        const Vec3 wi = normalized(frame.to_world(next));
        if (!same_side(geometric, normal, wi)) break;  // into the bumps' facet
        hit = m_scene.intersect(m_scene.spawn_origin(*hit, wi), wi, time);
        ++rays;
        direction = wi;
    }
}

Returns solve_returns(const LidarTracer& tracer, const LaserPulse& laser, const ReturnBatch& batch,
                      const Context& context) {
    if (batch.source == nullptr) throw usage_error("a lidar batch needs a ray source");
    if (batch.samples == 0) throw usage_error("a lidar batch needs at least 1 sample per pixel");
    const std::size_t bins = tracer.gate().samples;
    Returns out;
    out.samples_per_problem = bins;
    out.energy_j_per_cm2_sr.assign(batch.count * bins, 0.0);
    struct Workspace {
        std::uint64_t rays = 0;
    };
    const int threads =
        context.threads == 0 ? tbb::task_arena::automatic : static_cast<int>(context.threads);
    tbb::task_arena arena(threads);
    tbb::enumerable_thread_specific<Workspace> workspaces([&] { return Workspace{0}; });
    arena.execute([&] {
        tbb::parallel_for(
            tbb::blocked_range<std::uint64_t>(0, batch.count, 4),
            [&](const tbb::blocked_range<std::uint64_t>& range) {
                Workspace& ws = workspaces.local();
                for (std::uint64_t p = range.begin(); p != range.end(); ++p) {
                    if (context.cancel.cancelled()) return;
                    const std::span<double> mean(out.energy_j_per_cm2_sr.data() + p * bins, bins);
                    double weight_sum = 0.0;
                    for (std::uint64_t n = 0; n < batch.samples; ++n) {
                        RandomStream rng = sample_stream(batch.key, p, n);
                        const SampleRay ray = batch.source->generate(p, n, rng);
                        if (!(ray.weight > 0.0) || !std::isfinite(ray.weight)) {
                            throw input_error("sample " + std::to_string(n) + " of pixel " +
                                              std::to_string(p) + " has weight " +
                                              format_shortest(ray.weight) + ", expected > 0");
                        }
                        tracer.trace(ray, laser, rng, mean, ws.rays);
                        weight_sum += ray.weight;
                    }
                    for (double& v : mean) v /= weight_sum;
                }
            });
    });
    context.cancel.throw_if_cancelled();
    for (const Workspace& ws : workspaces) out.rays += ws.rays;
    return out;
}

}  // namespace glint::radiometry
