// SPDX-License-Identifier: Apache-2.0
// Hypersampling ("Hypersampling" in the DIRSIG5 BasicPlatform manual, docs/references.md,
// with ::IMPORTANT:: labels): the pixels of a capture whose field of view may contain an
// important instance.
#include <algorithm>
#include <array>
#include <cmath>

#include "glint/sensor/hypersampling.h"

namespace glint::sensor {
namespace {

/// Marks the pixels the box `b` may cover, seen from `pose`; false when part of the box is
/// behind the camera (the caller then marks every pixel).
bool mark_box(const scene::Bounds& b, const motion::Rigid& pose, const CameraModel& camera,
              double psf_reach_px, std::vector<std::uint8_t>& mask) {
    double min_c = INFINITY, max_c = -INFINITY, min_r = INFINITY, max_r = -INFINITY;
    double lens_blur_px = 0.0;  // the largest defocus blur radius over the corners
    const motion::Rigid to_instrument = motion::inverse(pose);
    for (int corner = 0; corner < 8; ++corner) {
        const motion::Vec3 p{(corner & 1) ? b.upper.x : b.lower.x,
                             (corner & 2) ? b.upper.y : b.lower.y,
                             (corner & 4) ? b.upper.z : b.lower.z};
        const motion::Vec3 d = motion::apply_point(to_instrument, p);
        lens_blur_px = std::max(lens_blur_px, 0.5 * camera.blur_diameter_px(-d.z));
        const std::optional<std::array<double, 2>> pixel = camera.project(motion::normalized(d));
        if (!pixel) return false;
        min_c = std::min(min_c, (*pixel)[0]);
        max_c = std::max(max_c, (*pixel)[0]);
        min_r = std::min(min_r, (*pixel)[1]);
        max_r = std::max(max_r, (*pixel)[1]);
    }
    // One pixel of margin (a pixel's samples reach its edges, and the box is a bound), plus
    // how far the PSF moves a sample.
    const double margin = 1.0 + std::ceil(psf_reach_px + lens_blur_px);
    const auto columns = static_cast<double>(camera.columns());
    const auto rows = static_cast<double>(camera.rows());
    const double c0 = std::max(0.0, std::floor(min_c) - margin);
    const double c1 = std::min(columns - 1.0, std::floor(max_c) + margin);
    const double r0 = std::max(0.0, std::floor(min_r) - margin);
    const double r1 = std::min(rows - 1.0, std::floor(max_r) + margin);
    for (double r = r0; r <= r1; ++r) {
        for (double c = c0; c <= c1; ++c) {
            mask[static_cast<std::size_t>(r) * camera.columns() + static_cast<std::size_t>(c)] = 1;
        }
    }
    return true;
}

}  // namespace

std::vector<std::uint8_t> hypersampled_pixels(const model::Scene& scene,
                                              const scene::GeometryScene& geometry,
                                              const CameraModel& camera,
                                              const motion::PoseService& poses,
                                              std::size_t instrument, const CaptureTiming& timing,
                                              double psf_reach_px) {
    std::vector<std::uint8_t> mask;
    const double last_s =
        timing.t1_s + timing.rolling_line_time_s * static_cast<double>(camera.rows() - 1);
    const std::array<motion::Rigid, 2> ends{poses.instrument_to_scene(instrument, timing.t0_s),
                                            poses.instrument_to_scene(instrument, last_s)};
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        if (!scene.instances[i].important) continue;
        const scene::Bounds box = geometry.instance_bounds(i);
        if (box.empty()) continue;
        if (mask.empty()) mask.assign(camera.columns() * camera.rows(), 0);
        for (const motion::Rigid& pose : ends) {
            if (!mark_box(box, pose, camera, psf_reach_px, mask)) {
                std::fill(mask.begin(), mask.end(), 1);
                break;
            }
        }
    }
    if (timing.tdi_stages > 1 && !mask.empty()) {
        // One problem per column: a column is important when any of its stages is.
        for (std::size_t row = 1; row < camera.rows(); ++row) {
            for (std::size_t column = 0; column < camera.columns(); ++column) {
                mask[column] |= mask[row * camera.columns() + column];
            }
        }
        mask.resize(camera.columns());
    }
    return mask;
}

}  // namespace glint::sensor
