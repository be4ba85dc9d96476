// SPDX-License-Identifier: Apache-2.0
// The geometric camera model of a `generic` instrument's focal plane (the pixel ray source
// the renderer hands to the path tracer is in pixel_ray_source.h).
//
// Focal plane (metres, in the instrument frame's XY plane): column i (ENVI sample, 0-based,
// N columns, pitch p_x) and row j (ENVI line, M rows, pitch p_y) have their centre at
//     x = (i + ½ − N/2) p_x + x_offset,    y = −(j + ½ − M/2) p_y + y_offset
// so columns grow towards instrument +X and rows towards −Y: for an instrument with identity
// mounts on a vehicle flying +Y, the image's top line is forward and its left column the left
// wing, a north-up image of the ground for a northbound pass. The active element (size
// s_x × s_y ≤ pitch) is centred in its pitch cell; a point (u, v) ∈ [0, 1)² of the element is at
//     x + (u − ½) s_x,   y − (v − ½) s_y
// (u grows with the columns, v with the rows). `xflip` mirrors the array about its centre
// line x = x_offset: x − x_offset → −(x − x_offset), which takes column i's centre to column
// N − 1 − i's and mirrors u inside the element with it; `yflip` mirrors the rows about
// y = y_offset the same way. A flipped camera is therefore the exact mirror image of the
// unflipped one, and project() stays the inverse of the sampling.
// Pinhole projection with focal length f (the upright virtual image) and the instrument's
// <distortion> (Brown k1, k2, k3, p1, p2 on coordinates normalised by f, centred on the
// optical axis, i.e. the array offset included): the focal-plane point (x, y) is the
// *distorted* image (x_d, y_d) = (x/f, y/f) of the scene direction; direction() *undistorts*
// it to (x_u, y_u) — fixed-point iteration to 1e-12 (normalised), Newton steps when that has
// not converged within its bounded iterations — and looks along the unit vector of
// (x_u, y_u, −1) in the instrument frame (boresight −Z); project() applies the explicit
// forward model x_d = x_u (1 + k1 r² + k2 r⁴ + k3 r⁶) + 2 p1 x_u y_u + p2 (r² + 2 x_u²),
// y_d = y_u (1 + …) + p1 (r² + 2 y_u²) + 2 p2 x_u y_u, r² = x_u² + y_u². k1 > 0 is pincushion,
// k1 < 0 barrel (the DIRSIG5 BasicPlatform manual's "Lens Distortion", docs/references.md;
// docs/camera.md §3).
// scale_resolution keeps the field of view: N' = the schedule's scaled count, pitch and
// element size × N/N' (per axis); offsets and focal length are unchanged.
#pragma once

#include <array>
#include <cstddef>
#include <optional>

#include "glint/model/instrument.h"
#include "glint/motion/geometry.h"

namespace glint::sensor {

using motion::Vec3;

/// A finite focus (<focusdistance> with <aperturediameter>): a thin lens at the instrument
/// origin, in the instrument's XY plane.
struct ThinLens {
    double aperture_diameter_m = 0.0;
    double focus_distance_m = 0.0;  ///< along the boresight (−Z)
};

/// The camera of one focal plane.
class CameraModel {
public:
    /// `columns`, `rows`: the pixel counts after scale_resolution (schedule::ClockedFocalPlane
    /// x_count, y_count). Throws glint::Error (input, at the element: properties.where for the
    /// focal length and distortion, array.where for the rest) when the instrument has no
    /// focal length (or a non-positive one), the array or the scaled counts are zero, a pitch
    /// or element size is not positive, an element is larger than its pitch, or an offset or
    /// distortion coefficient is not finite.
    CameraModel(const model::InstrumentProperties& properties, const model::DetectorArray& array,
                std::size_t columns, std::size_t rows);

    std::size_t columns() const noexcept { return m_columns; }
    std::size_t rows() const noexcept { return m_rows; }
    double focal_length_m() const noexcept { return m_focal_length_m; }
    /// Pitch and active element size after scaling, m.
    std::array<double, 2> pitch_m() const noexcept { return m_pitch_m; }
    std::array<double, 2> element_size_m() const noexcept { return m_element_m; }

    /// Focal-plane point (m) of (u, v) ∈ [0, 1)² of the active element of (column, row),
    /// moved by `offset_px` (pixels along the columns and the lines: a PSF offset), flips
    /// applied (they mirror u, v and the offset with the pixels; see the top of this file), so
    /// project() of its direction is the pixel position plus the offset.
    std::array<double, 2> focal_plane_point(std::size_t column, std::size_t row, double u, double v,
                                            std::array<double, 2> offset_px = {}) const noexcept;
    /// Unit direction in the instrument frame that the focal-plane point looks along.
    Vec3 direction(const std::array<double, 2>& focal_plane_m) const noexcept;
    /// The same direction before normalization: (x, y, −1) with (x, y) the undistorted
    /// normalised image point (a caller that normalizes later saves a square root and three
    /// divisions).
    Vec3 direction_unnormalized(const std::array<double, 2>& focal_plane_m) const noexcept;
    /// The fractional pixel position (column, row; pixel centres at .5, edges at integers)
    /// where the instrument-frame direction `d` (any length) lands; nullopt when d does not
    /// point into the camera's hemisphere (d.z ≥ 0, or NaN). The position may lie outside the
    /// array. Inverse of direction() ∘ focal_plane_point (flips and distortion included):
    /// project(direction(focal_plane_point(i, j, u, v))) = (i + ½ + (u − ½) s_x/p_x,
    /// j + ½ + (v − ½) s_y/p_y).
    std::optional<std::array<double, 2>> project(const Vec3& d) const noexcept;

    /// The finite focus, when the instrument has one (docs/camera.md §9).
    const std::optional<ThinLens>& thin_lens() const noexcept { return m_lens; }
    /// Diameter (column pixels) of the blur of a point at `depth_m` along the boresight:
    /// f·D·|depth − focus| / (depth·focus·pitch_x); 0 without a finite focus.
    double blur_diameter_px(double depth_m) const noexcept;

private:
    std::size_t m_columns = 0;
    std::size_t m_rows = 0;
    double m_focal_length_m = 0.0;
    std::array<double, 2> m_pitch_m{};
    std::array<double, 2> m_element_m{};
    std::array<double, 2> m_offset_m{};
    bool m_x_flip = false;
    bool m_y_flip = false;
    std::optional<model::Distortion> m_distortion;
    std::optional<ThinLens> m_lens;
};

}  // namespace glint::sensor
