// SPDX-License-Identifier: Apache-2.0
// Point sources seen by the camera (glint/sensor/point_sources_seen.h): a source is a point,
// so no sample ray ever hits it; the pixel whose footprint holds it records its irradiance at
// the aperture over the footprint's solid angle, E/Ω. This is the Monte-Carlo pixel's
// expectation for a delta source: a pixel's sample directions have density 1/Ω over its
// element (times the mask's relative sensitivity), so the mean of L = E δ(ω − ω_s) over them
// is E/Ω where ω_s is seen. The PSF, a thin lens's blur and the motion over the window are
// integrated with fixed draws (Halton points and evenly spaced times), so the result is the
// same on every run and shard. docs/physics.md, "Point sources seen by the camera".
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include "glint/motion/rigid.h"
#include "glint/sensor/point_sources_seen.h"

namespace glint::sensor {
namespace {

/// Times over a window, draws over the PSF and blur, and the clearance before a source.
constexpr std::size_t kTimeDraws = 16;
constexpr std::size_t kSpreadDraws = 1024;
constexpr double kClearance_m = 1e-3;

/// The radical inverse of `index` in base `base` (a Halton coordinate in [0, 1)).
double halton(std::size_t index, std::size_t base) noexcept {
    double result = 0.0;
    double f = 1.0;
    for (std::size_t i = index + 1; i > 0; i /= base) {
        f /= static_cast<double>(base);
        result += f * static_cast<double>(i % base);
    }
    return result;
}

/// The solid angle of the active element of (column, row), sr: its four corners' directions,
/// two flat triangles (the element spans well under a degree, where they are the sphere to
/// better than 1e-6).
double element_solid_angle_sr(const CameraModel& camera, std::size_t column, std::size_t row) {
    const auto corner = [&](double u, double v) {
        return motion::normalized(camera.direction(camera.focal_plane_point(column, row, u, v)));
    };
    const Vec3 a = corner(0.0, 0.0);
    const Vec3 b = corner(1.0, 0.0);
    const Vec3 c = corner(1.0, 1.0);
    const Vec3 d = corner(0.0, 1.0);
    return 0.5 * (motion::norm(motion::cross(b - a, c - a)) +
                  motion::norm(motion::cross(c - a, d - a)));
}

/// The pixel-space spreads of one draw: the PSF's offset and a thin lens's blur direction
/// (a point of the unit disc, scaled per source by its blur radius).
struct Spread {
    std::array<double, 2> psf_px{};
    std::array<double, 2> disc{};
};

std::vector<Spread> spreads(const PsfSampler* psf, bool lens) {
    if (psf == nullptr && !lens) return {Spread{}};
    std::vector<Spread> out(kSpreadDraws);
    for (std::size_t m = 0; m < kSpreadDraws; ++m) {
        if (psf != nullptr) out[m].psf_px = psf->offset_px(halton(m, 2), halton(m, 3));
        if (lens) {
            const double radius = std::sqrt(halton(m, 5));
            const double angle = 2.0 * std::numbers::pi * halton(m, 7);
            out[m].disc = {radius * std::cos(angle), radius * std::sin(angle)};
        }
    }
    return out;
}

}  // namespace

bool SeenPointSources::add_to(std::uint64_t problem, std::size_t first_band,
                              std::span<double> radiance) const {
    const auto from = std::lower_bound(
        entries.begin(), entries.end(), problem,
        [](const Entry& e, std::uint64_t p) { return e.problem < p; });
    bool any = false;
    for (auto it = from; it != entries.end() && it->problem == problem; ++it) {
        const std::vector<double>& e = irradiance[it->source];
        for (std::size_t j = 0; j < radiance.size(); ++j) {
            radiance[j] += it->per_sr * e[first_band + j];
        }
        any = true;
    }
    return any;
}

SeenPointSources seen_point_sources(const CameraModel& camera, const motion::PoseService& poses,
                                    std::size_t instrument, const CaptureTiming& timing,
                                    const PsfSampler* psf, const ActiveArea* mask,
                                    const radiometry::PointLights& lights,
                                    const scene::GeometryScene& geometry,
                                    const radiometry::Environment& environment) {
    SeenPointSources out;
    if (lights.empty()) return out;
    const bool tdi = timing.tdi_stages > 1;
    const bool moving = timing.t1_s > timing.t0_s || timing.rolling_line_time_s > 0.0;
    const std::size_t times =
        !moving ? 1 : (tdi ? std::max(kTimeDraws, 4 * timing.tdi_stages) : kTimeDraws);
    const std::vector<Spread> draws = spreads(psf, camera.thin_lens().has_value());
    const double per_draw = 1.0 / static_cast<double>(times * draws.size());
    const auto columns = static_cast<double>(camera.columns());
    const auto rows = static_cast<double>(camera.rows());
    const std::array<double, 2> pitch = camera.pitch_m();
    const std::array<double, 2> element = camera.element_size_m();
    const double mean_sensitivity = mask != nullptr ? mask->mean_sensitivity() : 1.0;
    const double mid_s = 0.5 * (timing.t0_s + timing.t1_s);

    std::map<std::pair<std::uint64_t, std::uint32_t>, double> shares;
    std::map<std::pair<std::size_t, std::size_t>, double> solid_angles;
    out.irradiance.resize(lights.size());
    for (std::size_t s = 0; s < lights.size(); ++s) {
        const Vec3& at = lights.position_m(s);
        bool seen = false;
        for (std::size_t k = 0; k < times; ++k) {
            const double tau = (static_cast<double>(k) + 0.5) / static_cast<double>(times);
            double t_s = timing.t0_s + tau * (timing.t1_s - timing.t0_s);
            // A rolling row integrates later by its row's line time: find the row, then
            // look again at its time (twice: the source may move across a row edge).
            motion::Rigid pose = poses.instrument_to_scene(instrument, t_s);
            std::optional<std::array<double, 2>> position = camera.project(
                motion::apply_direction(motion::inverse(pose), at - pose.translation_m));
            for (int pass = 0; pass < 2 && position && timing.rolling_line_time_s > 0.0; ++pass) {
                const double row = std::clamp(std::floor((*position)[1]), 0.0, rows - 1.0);
                const double row_time_s = t_s + row * timing.rolling_line_time_s;
                pose = poses.instrument_to_scene(instrument, row_time_s);
                position = camera.project(
                    motion::apply_direction(motion::inverse(pose), at - pose.translation_m));
                if (pass == 1) t_s = row_time_s;
            }
            if (!position) continue;
            const Vec3 to_source = at - pose.translation_m;
            const double range_m = motion::norm(to_source);
            if (!(range_m > kClearance_m)) continue;
            const Vec3 direction = to_source / range_m;
            if (geometry.occluded(pose.translation_m, direction, t_s, 0.0,
                                  range_m - kClearance_m)) {
                continue;
            }
            // A thin lens blurs the source into a disc (radius in column pixels; rows scaled
            // by the pitch ratio).
            const Vec3 in_instrument =
                motion::apply_direction(motion::inverse(pose), direction);
            const double blur_radius_px = 0.5 * camera.blur_diameter_px(-in_instrument.z);
            const std::size_t stage =
                tdi ? std::min(static_cast<std::size_t>(tau * static_cast<double>(timing.tdi_stages)),
                               timing.tdi_stages - 1)
                    : 0;
            for (const Spread& draw : draws) {
                // A sample of pixel (i, j) with PSF offset o looks at its element point + o:
                // it sees the source where the element point is the source's position − o.
                const double x = (*position)[0] - draw.psf_px[0] + blur_radius_px * draw.disc[0];
                const double y = (*position)[1] - draw.psf_px[1] +
                                 blur_radius_px * draw.disc[1] * pitch[0] / pitch[1];
                if (!(x >= 0.0 && x < columns && y >= 0.0 && y < rows)) continue;
                const auto column = static_cast<std::size_t>(x);
                const auto row = static_cast<std::size_t>(y);
                // The element point (u, v): inside the active element, or in the gap around it.
                const double u = (x - static_cast<double>(column) - 0.5) * pitch[0] / element[0] + 0.5;
                const double v = (y - static_cast<double>(row) - 0.5) * pitch[1] / element[1] + 0.5;
                if (!(u >= 0.0 && u < 1.0 && v >= 0.0 && v < 1.0)) continue;
                if (tdi && row != stage) continue;  // another stage integrates then
                // The mask: samples fall on (u, v) with density s/s̄, and the pixel is then
                // scaled by s̄ (store_channels): s/s̄ here.
                const double weight =
                    mask != nullptr ? mask->sensitivity(u, v) / mean_sensitivity : 1.0;
                if (!(weight > 0.0)) continue;
                double& omega = solid_angles[{column, row}];
                if (omega == 0.0) omega = element_solid_angle_sr(camera, column, row);
                const std::uint64_t problem =
                    tdi ? column : static_cast<std::uint64_t>(row) * camera.columns() + column;
                shares[{problem, static_cast<std::uint32_t>(s)}] += weight * per_draw / omega;
                seen = true;
            }
        }
        if (!seen) continue;
        // The irradiance at the aperture at mid-window: I T / r² (m² → cm²: 10⁻⁴), T the
        // sensor path's transmittance from the source's height.
        const motion::Rigid pose = poses.instrument_to_scene(instrument, mid_s);
        const Vec3 to_sensor = pose.translation_m - at;
        const double r2_m2 = motion::dot(to_sensor, to_sensor);
        const std::size_t bands = lights.bands();
        std::vector<double> transmittance(bands, 1.0);
        std::vector<double> path(bands, 0.0);
        environment.sensor_path(motion::normalized(to_sensor), mid_s, at.z, transmittance, path);
        std::vector<double>& e = out.irradiance[s];
        e.resize(bands);
        const std::span<const double> intensity = lights.intensity_w_per_sr_um(s);
        for (std::size_t b = 0; b < bands; ++b) {
            e[b] = intensity[b] * transmittance[b] / (r2_m2 * 1e4);
        }
    }
    for (const auto& [key, per_sr] : shares) {
        out.entries.push_back({key.first, key.second, per_sr});
    }
    return out;
}

}  // namespace glint::sensor
