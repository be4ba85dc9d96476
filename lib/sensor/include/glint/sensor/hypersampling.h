// SPDX-License-Identifier: Apache-2.0
// Hypersampling ("Hypersampling" in the DIRSIG5 BasicPlatform manual, docs/references.md):
// which pixels of a capture may see an instance marked ::IMPORTANT:: and so get the
// focal plane's hypersampled convergence.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "glint/model/scene.h"
#include "glint/motion/pose_service.h"
#include "glint/scene/geometry_scene.h"
#include "glint/sensor/camera.h"
#include "glint/sensor/pixel_ray_source.h"

namespace glint::sensor {

/// One entry per pixel (problem), 1 where the capture's field of view may contain an instance
/// marked ::IMPORTANT:: (its bounds over the window projected from the instrument's poses at
/// the window's start and end, one pixel of margin; every pixel when the box reaches behind
/// the camera); empty when no instance is important. For TDI (timing.tdi_stages > 1) one
/// entry per column: 1 when any stage of it is marked.
std::vector<std::uint8_t> hypersampled_pixels(const model::Scene& scene,
                                              const scene::GeometryScene& geometry,
                                              const CameraModel& camera,
                                              const motion::PoseService& poses,
                                              std::size_t instrument, const CaptureTiming& timing,
                                              double psf_reach_px = 0.0);

}  // namespace glint::sensor
