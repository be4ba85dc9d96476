// SPDX-License-Identifier: Apache-2.0
// Point sources seen by the camera (docs/physics.md, "Point sources seen by the camera"): a
// delta source's irradiance at the aperture spread over the solid angle of the element that
// sees it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "glint/motion/pose_service.h"
#include "glint/radiometry/environment.h"
#include "glint/radiometry/point_lights.h"
#include "glint/scene/geometry_scene.h"
#include "glint/sensor/active_area.h"
#include "glint/sensor/camera.h"
#include "glint/sensor/pixel_ray_source.h"
#include "glint/sensor/psf.h"

namespace glint::sensor {

/// What the pixels of one capture record straight from the point sources in their view.
struct SeenPointSources {
    /// Per source: the irradiance it puts on the aperture, I(λ) T_v(λ) / r², W/(cm² µm), per
    /// band of the grid.
    std::vector<std::vector<double>> irradiance;
    /// One pixel seeing one source: its radiance gains per_sr × irradiance[source].
    struct Entry {
        std::uint64_t problem = 0;
        std::uint32_t source = 0;
        double per_sr = 0.0;  ///< the share of the source's draws it holds / its solid angle
    };
    std::vector<Entry> entries;  ///< by problem, then source
    /// Adds to `radiance` (bands first_band … of the grid) what problem `problem` records;
    /// returns whether it records anything.
    bool add_to(std::uint64_t problem, std::size_t first_band, std::span<double> radiance) const;
};

/// The point sources `lights` (at their mid-window positions) as the pixels of a capture see
/// them: for each of 16 times spread over the window (a rolling row's own times; for TDI,
/// the stage a time falls in), a source not hidden from the instrument's origin (by a
/// surface more than 1 mm before it) projects to a point of the focal plane; the PSF's and a
/// thin lens's blur spread it over 1,024 fixed draws, and each draw that lands in a pixel's
/// active element (weighted by the active-area mask) gives that pixel its share over the
/// element's solid angle. The atmosphere between is the sensor path's transmittance from the
/// source's height.
SeenPointSources seen_point_sources(const CameraModel& camera, const motion::PoseService& poses,
                                    std::size_t instrument, const CaptureTiming& timing,
                                    const PsfSampler* psf, const ActiveArea* mask,
                                    const radiometry::PointLights& lights,
                                    const scene::GeometryScene& geometry,
                                    const radiometry::Environment& environment);

}  // namespace glint::sensor
