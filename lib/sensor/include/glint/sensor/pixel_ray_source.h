// SPDX-License-Identifier: Apache-2.0
// The pixel ray source the renderer hands to the path tracer: the sample rays of one capture
// of a camera (CameraModel), over the element (or an active-area mask's importance draw), the
// integration window (rolling readout and TDI stages included), a PSF and a thin lens, from
// the instrument's pose at each sample's time. docs/camera.md.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include "glint/motion/pose_service.h"
#include "glint/radiometry/problem.h"
#include "glint/sensor/active_area.h"
#include "glint/sensor/camera.h"
#include "glint/sensor/psf.h"

namespace glint::sensor {

/// When in a capture each pixel integrates.
struct CaptureTiming {
    double t0_s = 0.0;  ///< window start (the clock tick)
    double t1_s = 0.0;  ///< window end (t0 + integration time)
    /// Rolling readout: row j's window is shifted by j × line time; 0 = global shutter.
    double rolling_line_time_s = 0.0;
    /// TDI stages (the camera's rows) when > 1: one problem per column, and [t0, t1] is the
    /// whole window of all stages (see PixelRaySource).
    std::size_t tdi_stages = 1;
};

/// The sample rays of one capture: problem p is pixel (p % columns, p / columns) in output
/// order (flips are the camera's business); sample n draws, in this order, u, v (element
/// area), then τ (window), then, with a PSF, two uniforms for its offset (PsfSampler), then,
/// with a thin lens (CameraModel::thin_lens), two uniforms for the aperture point, each
/// from rng.uniform(); its time is t0 + row × line time + τ
/// (t1 − t0) (row = the output line), its origin the instrument's origin and its direction the
/// camera direction turned into scene ENU, both from the pose service at that time. Weight 1.
/// TDI (timing.tdi_stages = N > 1, the camera's rows): problem p is column p of the one
/// output line; τ spreads the sample over the whole window, and its stage k = ⌊τ N⌋ is the
/// row it lands on: stage k integrates on row k during the k-th N-th of [t0, t1], so a scene
/// point whose image moves one row per stage time (towards higher rows, as the ground does
/// for a camera flying towards instrument +Y) is seen by every stage of one column. The
/// paths of a pixel are thus spread evenly over its stages, and the mean over them is the
/// mean radiance over the stages. generate() throws glint::Error (internal) for a problem
/// ≥ columns × rows (columns for TDI), and what the pose service throws.
class PixelRaySource final : public radiometry::RaySource {
public:
    /// Keeps references: camera and poses must outlive it. Throws glint::Error (internal)
    /// for an instrument index out of range, a non-finite window or one with t1 < t0, a
    /// negative or non-finite line time, or TDI stages other than 1 or the camera's rows
    /// (or with a rolling line time).
    /// `psf` and `mask` (each may be null: none) must outlive it too. With a mask, u and v
    /// come from its importance draw (the same two uniforms).
    PixelRaySource(const CameraModel& camera, const motion::PoseService& poses,
                   std::size_t instrument, CaptureTiming timing, const PsfSampler* psf = nullptr,
                   const ActiveArea* mask = nullptr);
    radiometry::SampleRay generate(std::uint64_t problem, std::uint64_t sample,
                                   RandomStream& rng) const override;

private:
    const CameraModel& m_camera;
    const motion::PoseService& m_poses;
    std::size_t m_instrument;
    CaptureTiming m_timing;
    const PsfSampler* m_psf;
    const ActiveArea* m_mask;
    /// The pose of a window of zero length without rolling readout: every sample's time is
    /// t0, so it is computed once.
    std::optional<motion::Rigid> m_fixed_pose;
};

}  // namespace glint::sensor
