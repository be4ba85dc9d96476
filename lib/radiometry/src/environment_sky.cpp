// SPDX-License-Identifier: Apache-2.0
// The environment's sky (glint/radiometry/environment.h): the scattered sky's directional shape
// tabulated over zenith and azimuth from the sun and normalised to the diffuse irradiance, and
// its lookup by direction (docs/physics.md, "The sky in the renderer").
#include "environment_sky.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "glint/radiometry/environment.h"

namespace glint::radiometry {
namespace detail {
namespace {

/// The weights of the shape's nodes in ∫ f cos θ dΩ over the sky for f interpolated between
/// them as Environment::sky_lookup does, [zenith node][azimuth node]: exact in azimuth
/// (piecewise linear, both sides of the sun's plane), 0.01° midpoint steps in zenith.
std::vector<double> sky_shape_weights(const std::vector<double>& air_mass) {
    const auto& azimuths = Environment::kSkyAzimuthNodesDeg;
    const std::size_t na = azimuths.size();
    std::vector<double> w_azimuth(na, 0.0);
    for (std::size_t a = 0; a + 1 < na; ++a) {
        const double half = (azimuths[a + 1] - azimuths[a]) / kSkyRadToDeg;  // both sides: 2 × ½
        w_azimuth[a] += half;
        w_azimuth[a + 1] += half;
    }
    std::vector<double> w_zenith(air_mass.size(), 0.0);
    constexpr int kSteps = 9000;
    const double step = 0.5 * std::numbers::pi / kSteps;
    for (int i = 0; i < kSteps; ++i) {
        const double theta = (i + 0.5) * step;
        const double w = std::cos(theta) * std::sin(theta) * step;
        const AltitudeLevel at = locate_sky_zenith(air_mass, std::cos(theta));
        w_zenith[at.index] += (1.0 - at.fraction) * w;
        if (at.fraction > 0.0) w_zenith[at.index + 1] += at.fraction * w;
    }
    std::vector<double> weights(air_mass.size() * na);
    for (std::size_t z = 0; z < air_mass.size(); ++z) {
        for (std::size_t a = 0; a < na; ++a) weights[z * na + a] = w_zenith[z] * w_azimuth[a];
    }
    return weights;
}

}  // namespace

AltitudeLevel locate_sky_zenith(const std::vector<double>& air_mass, double cos_zenith) {
    const std::size_t nodes = air_mass.size();
    if (nodes < 2) return {0, 0.0};
    if (!(cos_zenith > 0.0)) return {nodes - 1, 0.0};
    const double zenith = std::acos(std::min(cos_zenith, 1.0)) * kSkyRadToDeg;
    const auto index =
        std::min(static_cast<std::size_t>(zenith / Environment::kSkyZenithStepDeg), nodes - 2);
    const double lo = air_mass[index];
    const double hi = air_mass[index + 1];
    const double m = glint::atmosphere::relative_air_mass(zenith);
    return {index, std::clamp((m - lo) / (hi - lo), 0.0, 1.0)};
}

std::shared_ptr<const std::vector<double>> sky_shape(
    const SpectralGrid& grid, const glint::atmosphere::AtmosphereModel& atmosphere,
    const glint::atmosphere::AtmosphereGeometry& geometry, const std::vector<double>& toa,
    const std::vector<double>& air_mass, unsigned threads) {
    const auto& nodes = Environment::kSkyAzimuthNodesDeg;
    const std::size_t na = nodes.size();
    const std::size_t nz = air_mass.size();
    const std::size_t bands = grid.size();
    std::vector<double> azimuths(na);
    for (std::size_t a = 0; a < na; ++a) {
        azimuths[a] = std::fmod(geometry.sun_azimuth_deg + nodes[a], 360.0);
    }
    const auto row = [&](std::size_t z) {
        const double zenith[] = {static_cast<double>(z) * Environment::kSkyZenithStepDeg};
        return atmosphere.scattered_sky_at_directions(grid, geometry, toa, zenith, azimuths);
    };
    std::vector<std::vector<std::vector<double>>> rows(nz);
    rows[0] = row(0);
    if (rows[0].empty()) return nullptr;
    // One zenith per task: each node's values depend on its direction alone.
    tbb::task_arena arena(threads == 0 ? tbb::task_arena::automatic : static_cast<int>(threads));
    arena.execute(
        [&] { tbb::parallel_for(std::size_t{1}, nz, [&](std::size_t z) { rows[z] = row(z); }); });
    auto shape = std::make_shared<std::vector<double>>(nz * na * bands);
    for (std::size_t z = 0; z < nz; ++z) {
        for (std::size_t a = 0; a < na; ++a) {
            std::copy(rows[z][a].begin(), rows[z][a].end(),
                      shape->begin() + static_cast<std::ptrdiff_t>((z * na + a) * bands));
        }
    }
    if (std::none_of(shape->begin(), shape->end(), [](double v) { return v > 0.0; })) {
        return nullptr;
    }
    const std::vector<double> weights = sky_shape_weights(air_mass);
    for (std::size_t b = 0; b < bands; ++b) {
        double integral = 0.0;
        for (std::size_t k = 0; k < nz * na; ++k) integral += weights[k] * (*shape)[k * bands + b];
        const double scale = integral > 0.0 ? std::numbers::pi / integral : 0.0;
        for (std::size_t k = 0; k < nz * na; ++k) {
            double& v = (*shape)[k * bands + b];
            v = scale > 0.0 ? v * scale : 1.0;
        }
    }
    return shape;
}

}  // namespace detail

AltitudeLevel Environment::sky_node(double cos_zenith) const noexcept {
    return detail::locate_sky_zenith(m_sky_air_mass, cos_zenith);
}

Environment::SkyLookup Environment::sky_lookup(const Vec3& wi, double time_s,
                                               const AltitudeLevel& at) const noexcept {
    SkyLookup l;
    const AltitudeLevel node = sky_node(wi.z);
    const double f = at.fraction;
    const double g = node.fraction;
    const std::size_t level_hi = f > 0.0 ? at.index + 1 : at.index;
    const std::size_t node_hi = g > 0.0 ? node.index + 1 : node.index;
    const auto row = [&](std::size_t level, std::size_t n) {
        return m_sky.data() + (level * m_sky_nodes + n) * m_bands;
    };
    l.rows = {row(at.index, node.index), row(at.index, node_hi), row(level_hi, node.index),
              row(level_hi, node_hi)};
    l.row_weights = {(1.0 - f) * (1.0 - g), (1.0 - f) * g, f * (1.0 - g), f * g};
    if (!m_sky_shape) return l;
    l.diffuse = {m_sky_diffuse.data() + at.index * m_bands,
                 m_sky_diffuse.data() + level_hi * m_bands};
    l.diffuse_weights = {1.0 - f, f};
    // The azimuth from the sun's, folded into [0°, 180°] (the sky is symmetric about the
    // sun's vertical plane); 0 where either direction is vertical.
    const Vec3 sun = sun_direction(time_s);
    const double h = std::hypot(wi.x, wi.y) * std::hypot(sun.x, sun.y);
    const double cos_relative =
        h > 0.0 ? std::clamp((wi.x * sun.x + wi.y * sun.y) / h, -1.0, 1.0) : 1.0;
    const double relative_deg = std::acos(cos_relative) * detail::kSkyRadToDeg;
    const auto& nodes = kSkyAzimuthNodesDeg;
    const auto upper = std::upper_bound(nodes.begin() + 1, nodes.end() - 1, relative_deg);
    const auto a0 = static_cast<std::size_t>(upper - nodes.begin()) - 1;
    const double fa =
        std::clamp((relative_deg - nodes[a0]) / (nodes[a0 + 1] - nodes[a0]), 0.0, 1.0);
    const std::size_t na = nodes.size();
    const double* shape = m_sky_shape->data();
    const auto cell = [&](std::size_t n, std::size_t a) { return shape + (n * na + a) * m_bands; };
    l.shape = {cell(node.index, a0), cell(node.index, a0 + 1), cell(node_hi, a0),
               cell(node_hi, a0 + 1)};
    l.shape_weights = {(1.0 - g) * (1.0 - fa), (1.0 - g) * fa, g * (1.0 - fa), g * fa};
    return l;
}

std::vector<double> Environment::sky_radiance(const Vec3& wi, double time_s, double z_m) const {
    const SkyLookup l = sky_lookup(wi, time_s, level_at(z_m));
    std::vector<double> out(m_bands);
    for (std::size_t b = 0; b < m_bands; ++b) out[b] = l.at(b);
    return out;
}

}  // namespace glint::radiometry
