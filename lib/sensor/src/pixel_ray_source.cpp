// SPDX-License-Identifier: Apache-2.0
// PixelRaySource: the sample rays of one capture of a focal plane. Each sample draws a point
// of the pixel's active element and a time in the pixel's integration window (uniformly, as
// the BasicPlatform manual's "Spatial and Temporal Sampling" describes), then, with a PSF, an
// offset from it (the manual's two-step sampling), then asks the pose service where the
// instrument is and how it is turned at that time.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "glint/core/error.h"
#include "glint/sensor/camera.h"
#include "glint/sensor/pixel_ray_source.h"

namespace glint::sensor {

PixelRaySource::PixelRaySource(const CameraModel& camera, const motion::PoseService& poses,
                               std::size_t instrument, CaptureTiming timing, const PsfSampler* psf,
                               const ActiveArea* mask)
    : m_camera(camera),
      m_poses(poses),
      m_instrument(instrument),
      m_timing(timing),
      m_psf(psf),
      m_mask(mask) {
    if (instrument >= poses.instrument_count()) {
        throw internal_error("pixel ray source: instrument " + std::to_string(instrument) +
                             " out of range (the platform has " +
                             std::to_string(poses.instrument_count()) + ")");
    }
    if (!std::isfinite(timing.t0_s) || !std::isfinite(timing.t1_s) || timing.t1_s < timing.t0_s) {
        throw internal_error(
            "pixel ray source: integration window is not a finite [t0, t1] "
            "with t1 >= t0");
    }
    if (!std::isfinite(timing.rolling_line_time_s) || timing.rolling_line_time_s < 0.0) {
        throw internal_error("pixel ray source: rolling line time must be finite and >= 0");
    }
    if (timing.tdi_stages == 0 || (timing.tdi_stages > 1 && (timing.tdi_stages != camera.rows() ||
                                                             timing.rolling_line_time_s != 0.0))) {
        throw internal_error("pixel ray source: " + std::to_string(timing.tdi_stages) +
                             " TDI stages for a camera of " + std::to_string(camera.rows()) +
                             " rows (stages must be 1, or the rows without rolling readout)");
    }
    if (timing.t1_s == timing.t0_s && timing.rolling_line_time_s == 0.0) {
        m_fixed_pose = poses.instrument_to_scene(instrument, timing.t0_s);
    }
}

radiometry::SampleRay PixelRaySource::generate(std::uint64_t problem, std::uint64_t /*sample*/,
                                               RandomStream& rng) const {
    const std::uint64_t columns = m_camera.columns();
    const bool tdi = m_timing.tdi_stages > 1;
    const std::uint64_t rows = tdi ? 1 : m_camera.rows();
    if (problem / columns >= rows) {
        throw internal_error("pixel ray source: problem " + std::to_string(problem) +
                             " out of range (" + std::to_string(columns) + " x " +
                             std::to_string(rows) + " pixels)");
    }
    const std::uint64_t column = problem % columns;
    // The documented draw order: u, v, τ, then the PSF's two.
    double u = rng.uniform();
    double v = rng.uniform();
    if (m_mask != nullptr) {
        const std::array<double, 2> point = m_mask->point(u, v);
        u = point[0];
        v = point[1];
    }
    const double tau = rng.uniform();
    std::array<double, 2> offset_px{};
    if (m_psf != nullptr) {
        const double r1 = rng.uniform();
        const double r2 = rng.uniform();
        offset_px = m_psf->offset_px(r1, r2);
    }
    const auto stages = static_cast<double>(m_timing.tdi_stages);
    const std::uint64_t row =
        tdi ? std::min<std::uint64_t>(static_cast<std::uint64_t>(tau * stages),
                                      m_timing.tdi_stages - 1)
            : problem / columns;
    const double t_s = m_timing.t0_s + static_cast<double>(row) * m_timing.rolling_line_time_s +
                       tau * (m_timing.t1_s - m_timing.t0_s);

    // Not unit length: the ray's direction is normalized once, in the scene frame (the thin
    // lens's focus point below does not depend on the length).
    Vec3 d_instrument = m_camera.direction_unnormalized(m_camera.focal_plane_point(
        static_cast<std::size_t>(column), static_cast<std::size_t>(row), u, v, offset_px));
    Vec3 origin_instrument{};
    if (const std::optional<ThinLens>& lens = m_camera.thin_lens()) {
        // Thin lens: the chief ray's point on the plane of focus, seen from a point of the
        // aperture disc (uniform: radius ∝ √r).
        const double r_a = rng.uniform();
        const double r_b = rng.uniform();
        const double radius = 0.5 * lens->aperture_diameter_m * std::sqrt(r_a);
        const double angle = 2.0 * std::numbers::pi * r_b;
        origin_instrument = Vec3{radius * std::cos(angle), radius * std::sin(angle), 0.0};
        const Vec3 focus = d_instrument * (lens->focus_distance_m / -d_instrument.z);
        d_instrument = focus - origin_instrument;
    }
    const motion::Rigid pose =
        m_fixed_pose ? *m_fixed_pose : m_poses.instrument_to_scene(m_instrument, t_s);
    radiometry::SampleRay ray;
    ray.origin_m = motion::apply_point(pose, origin_instrument);
    ray.direction = motion::normalized(motion::apply_direction(pose, d_instrument));
    ray.time_s = t_s;
    ray.weight = 1.0;
    return ray;
}

}  // namespace glint::sensor
