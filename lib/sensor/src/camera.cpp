// SPDX-License-Identifier: Apache-2.0
// CameraModel: the focal-plane layout of a detector array (pitch, active element, offset,
// flips, scale_resolution), the pinhole projection and the Brown lens distortion, forward
// (project) and inverted by iteration (direction). Conventions in glint/sensor/camera.h.
#include "glint/sensor/camera.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::sensor {
namespace {

/// Convergence of the undistortion, in normalised (focal-length) units.
constexpr double kUndistortTolerance = 1e-12;
/// Bounds of the two solvers: fixed-point first, then Newton (polish, or rescue).
constexpr int kMaxFixedPointIterations = 100;
constexpr int kMaxNewtonIterations = 50;
constexpr int kMaxStepHalvings = 30;

bool positive_finite(double v) noexcept { return std::isfinite(v) && v > 0.0; }

/// A point in normalised image coordinates (x/f, y/f).
struct Normalised {
    double x = 0.0;
    double y = 0.0;
};

/// Brown's forward model: the distorted image of the undistorted point `p`.
Normalised distort(const model::Distortion& k, Normalised p) noexcept {
    const double r2 = p.x * p.x + p.y * p.y;
    const double radial = 1.0 + r2 * (k.k1 + r2 * (k.k2 + r2 * k.k3));
    return {p.x * radial + 2.0 * k.p1 * p.x * p.y + k.p2 * (r2 + 2.0 * p.x * p.x),
            p.y * radial + k.p1 * (r2 + 2.0 * p.y * p.y) + 2.0 * k.p2 * p.x * p.y};
}

/// Largest component of distort(p) − target.
double residual(const model::Distortion& k, Normalised p, Normalised target) noexcept {
    const Normalised d = distort(k, p);
    return std::max(std::abs(d.x - target.x), std::abs(d.y - target.y));
}

/// The Newton step towards distort(p) = target (to be added to p); nullopt when the
/// Jacobian is singular or the step not finite.
std::optional<Normalised> newton_step(const model::Distortion& k, Normalised p,
                                      Normalised target) noexcept {
    const double r2 = p.x * p.x + p.y * p.y;
    const double radial = 1.0 + r2 * (k.k1 + r2 * (k.k2 + r2 * k.k3));
    const double radial_dr2 = k.k1 + r2 * (2.0 * k.k2 + r2 * 3.0 * k.k3);
    const double j_xx = radial + 2.0 * p.x * p.x * radial_dr2 + 2.0 * k.p1 * p.y + 6.0 * k.p2 * p.x;
    const double j_xy = 2.0 * p.x * p.y * radial_dr2 + 2.0 * k.p1 * p.x + 2.0 * k.p2 * p.y;
    const double j_yx = j_xy;
    const double j_yy = radial + 2.0 * p.y * p.y * radial_dr2 + 6.0 * k.p1 * p.y + 2.0 * k.p2 * p.x;
    const double det = j_xx * j_yy - j_xy * j_yx;
    if (!std::isfinite(det) || det == 0.0) return std::nullopt;
    const Normalised d = distort(k, p);
    const double ex = d.x - target.x;
    const double ey = d.y - target.y;
    const Normalised step{-(j_yy * ex - j_xy * ey) / det, -(j_xx * ey - j_yx * ex) / det};
    if (!std::isfinite(step.x) || !std::isfinite(step.y)) return std::nullopt;
    return step;
}

/// The undistorted point whose distorted image is `target`: the fixed-point iteration
/// p ← (target − tangential(p)) / radial(p) until a step is at most kUndistortTolerance (at
/// most kMaxFixedPointIterations), then Newton steps while they reduce the residual (at most
/// kMaxNewtonIterations): usually one polishes the converged point to round-off; they take
/// over where the fixed point diverges (strong distortion far off axis). Returns the point
/// with the smallest residual found.
Normalised undistort(const model::Distortion& k, Normalised target) noexcept {
    Normalised p = target;
    for (int n = 0; n < kMaxFixedPointIterations; ++n) {
        const double r2 = p.x * p.x + p.y * p.y;
        const double radial = 1.0 + r2 * (k.k1 + r2 * (k.k2 + r2 * k.k3));
        if (!std::isfinite(radial) || radial <= 0.0) break;
        const double tx = 2.0 * k.p1 * p.x * p.y + k.p2 * (r2 + 2.0 * p.x * p.x);
        const double ty = k.p1 * (r2 + 2.0 * p.y * p.y) + 2.0 * k.p2 * p.x * p.y;
        const Normalised next{(target.x - tx) / radial, (target.y - ty) / radial};
        const double step = std::max(std::abs(next.x - p.x), std::abs(next.y - p.y));
        p = next;
        if (!(step > kUndistortTolerance)) break;
    }
    Normalised best = target;
    double best_residual = residual(k, target, target);
    if (const double r = residual(k, p, target); std::isfinite(r) && r < best_residual) {
        best = p;
        best_residual = r;
    }
    // Newton with backtracking: halve the step until it lowers the residual; stop at the
    // round-off floor, or when no fraction of the step helps.
    const double floor = 4.0 * std::numeric_limits<double>::epsilon() *
                         (1.0 + std::max(std::abs(target.x), std::abs(target.y)));
    for (int n = 0; n < kMaxNewtonIterations && best_residual > floor; ++n) {
        const std::optional<Normalised> step = newton_step(k, best, target);
        if (!step) break;
        bool improved = false;
        double scale = 1.0;
        for (int halving = 0; halving < kMaxStepHalvings && !improved; ++halving, scale *= 0.5) {
            const Normalised q{best.x + scale * step->x, best.y + scale * step->y};
            const double r = residual(k, q, target);
            if (r < best_residual) {
                best = q;
                best_residual = r;
                improved = true;
            }
        }
        if (!improved) break;
    }
    return best;
}

bool all_zero(const model::Distortion& d) noexcept {
    return d.k1 == 0.0 && d.k2 == 0.0 && d.k3 == 0.0 && d.p1 == 0.0 && d.p2 == 0.0;
}

/// A length for a message, in µm rounded to the picometre ("10 um", not "9.999999999999999e-06").
std::string micrometres(double m) { return format_shortest(std::round(m * 1e12) / 1e6) + " um"; }

/// Checks one axis of the array; `axis` is 'x' or 'y'.
void check_axis(char axis, std::size_t count, std::size_t scaled_count, double size_m,
                double spacing_m, double offset_m, const ErrorContext& where) {
    const std::string a(1, axis);
    if (count == 0) {
        throw input_error(a + "elementcount is 0, expected at least one element", where);
    }
    if (scaled_count == 0) {
        throw input_error("the scaled " + a + " pixel count is 0 (detector array of " +
                              std::to_string(count) + "), expected at least one pixel",
                          where);
    }
    if (!positive_finite(spacing_m)) {
        throw input_error(a + "elementspacing " + micrometres(spacing_m) +
                              " is not positive, expected a pitch > 0",
                          where);
    }
    if (!positive_finite(size_m)) {
        throw input_error(a + "elementsize " + micrometres(size_m) +
                              " is not positive, expected an active element size > 0",
                          where);
    }
    if (size_m > spacing_m) {
        throw input_error(a + "elementsize " + micrometres(size_m) + " is larger than " + a +
                              "elementspacing " + micrometres(spacing_m) +
                              ", expected an element no larger than its pitch",
                          where);
    }
    if (!std::isfinite(offset_m)) {
        throw input_error(a + "arrayoffset is not a finite number", where);
    }
}

}  // namespace

CameraModel::CameraModel(const model::InstrumentProperties& properties,
                         const model::DetectorArray& array, std::size_t columns, std::size_t rows)
    : m_columns(columns), m_rows(rows) {
    if (!properties.focal_length_m) {
        throw input_error("instrument has no focal length; a camera needs <focallength>",
                          properties.where);
    }
    if (!positive_finite(*properties.focal_length_m)) {
        throw input_error("focal length " + format_shortest(*properties.focal_length_m) +
                              " m is not positive, expected a focal length > 0",
                          properties.where);
    }
    m_focal_length_m = *properties.focal_length_m;
    if (properties.distortion) {
        const model::Distortion& d = *properties.distortion;
        for (const double c : {d.k1, d.k2, d.k3, d.p1, d.p2}) {
            if (!std::isfinite(c)) {
                throw input_error("distortion coefficient is not a finite number",
                                  properties.where);
            }
        }
        if (!all_zero(d)) m_distortion = d;
    }
    check_axis('x', array.x_count, columns, array.x_size_m, array.x_spacing_m, array.x_offset_m,
               array.where);
    check_axis('y', array.y_count, rows, array.y_size_m, array.y_spacing_m, array.y_offset_m,
               array.where);
    // scale_resolution: the same array extent divided into the scaled counts.
    const double x_scale = static_cast<double>(array.x_count) / static_cast<double>(columns);
    const double y_scale = static_cast<double>(array.y_count) / static_cast<double>(rows);
    m_pitch_m = {array.x_spacing_m * x_scale, array.y_spacing_m * y_scale};
    m_element_m = {array.x_size_m * x_scale, array.y_size_m * y_scale};
    m_offset_m = {array.x_offset_m, array.y_offset_m};
    m_x_flip = array.x_flip;
    m_y_flip = array.y_flip;
    if (properties.focus_distance_m && properties.aperture_diameter_m) {
        if (!positive_finite(*properties.focus_distance_m) ||
            !positive_finite(*properties.aperture_diameter_m)) {
            throw input_error("focus distance and aperture diameter must be finite numbers > 0",
                              properties.where);
        }
        m_lens = ThinLens{*properties.aperture_diameter_m, *properties.focus_distance_m};
    }
}

double CameraModel::blur_diameter_px(double depth_m) const noexcept {
    if (!m_lens || !(depth_m > 0.0)) return 0.0;
    return m_focal_length_m * m_lens->aperture_diameter_m *
           std::abs(depth_m - m_lens->focus_distance_m) /
           (depth_m * m_lens->focus_distance_m * m_pitch_m[0]);
}

std::array<double, 2> CameraModel::focal_plane_point(
    std::size_t column, std::size_t row, double u, double v,
    std::array<double, 2> offset_px) const noexcept {
    const double half_columns = 0.5 * static_cast<double>(m_columns);
    const double half_rows = 0.5 * static_cast<double>(m_rows);
    // Relative to the array centre, before the flips (exact zero at the centre of odd arrays).
    double x = (static_cast<double>(column) + 0.5 - half_columns) * m_pitch_m[0] +
               (u - 0.5) * m_element_m[0] + offset_px[0] * m_pitch_m[0];
    double y = -((static_cast<double>(row) + 0.5 - half_rows) * m_pitch_m[1] +
                 (v - 0.5) * m_element_m[1] + offset_px[1] * m_pitch_m[1]);
    if (m_x_flip) x = -x;
    if (m_y_flip) y = -y;
    return {x + m_offset_m[0], y + m_offset_m[1]};
}

Vec3 CameraModel::direction_unnormalized(
    const std::array<double, 2>& focal_plane_m) const noexcept {
    Normalised p{focal_plane_m[0] / m_focal_length_m, focal_plane_m[1] / m_focal_length_m};
    if (m_distortion) p = undistort(*m_distortion, p);
    return Vec3{p.x, p.y, -1.0};
}

Vec3 CameraModel::direction(const std::array<double, 2>& focal_plane_m) const noexcept {
    return motion::normalized(direction_unnormalized(focal_plane_m));
}

std::optional<std::array<double, 2>> CameraModel::project(const Vec3& d) const noexcept {
    if (!(d.z < 0.0)) return std::nullopt;
    Normalised p{d.x / -d.z, d.y / -d.z};
    if (m_distortion) p = distort(*m_distortion, p);
    double x = p.x * m_focal_length_m - m_offset_m[0];
    double y = p.y * m_focal_length_m - m_offset_m[1];
    if (m_x_flip) x = -x;
    if (m_y_flip) y = -y;
    return std::array<double, 2>{x / m_pitch_m[0] + 0.5 * static_cast<double>(m_columns),
                                 -y / m_pitch_m[1] + 0.5 * static_cast<double>(m_rows)};
}

}  // namespace glint::sensor
