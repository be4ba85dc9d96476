// SPDX-License-Identifier: Apache-2.0
// Mount kinematics and attachment placements: the time-dependent rigid transform of each link
// of a `.platform` attachment tree (glint/model/platform.h), relative to its parent.
//
// Every transform maps the child frame into the parent frame (glint/motion/rigid.h). An
// instrument at the end of a path attachment_0 > mount_0 > attachment_1 > … > attachment_n
// sits on the vehicle at
//     instrument_to_vehicle(t) = A_0 · M_0(t) · A_1 · M_1(t) · … · A_n
// (outermost first; A_i = affine_transform(attachment_i), M_i = mount_transform(mount_i, t)).
// Angles follow glint/motion/euler.h (active, extrinsic, `rotationorder` = applied order);
// the instrument boresight is −Z of the instrument frame (kInstrumentBoresight in frames.h).
//
// Parameters read from the model (units as glint::model stores them; docs/formats.md has the
// XML):
//
// clang-format off
// | mount type | fields | unit | kinematics |
// |---|---|---|---|
// | static (lemniscate, line, scripted: held static) | rotation_rad, rotation_order | rad | R = euler(rotation_rad, order), no translation |
// | commanded | entries (time_s, rotation_rad, translation_m), rotation_order | s, rad, m | slerp of the entry rotations, linear translation; first/last entry held outside the table |
// | tabulated | as commanded, period_s | s | the table repeated every P s (entry times + k·P; the gap last → first + P interpolated too); no period (last time ≤ 0): as commanded |
// | whisk | whisk.axis, min/max_angle_rad, rate_hz, phase_rad, sinusoidal | rad, Hz | θ(t) about Y (acrosstrack) or X (alongtrack); see whisk_angle_rad |
// | tracking | tracking.point_m or name, offset_m | m (scene ENU) | −Z turned towards the target; see tracking_rotation |
//
// | affinetransform | fields | unit | transform |
// |---|---|---|---|
// | translation + rotation | translation_m, rotation_rad, rotation_order | m, rad | R = euler(rotation_rad, order), t = translation_m |
// | matrix | 16 numbers row-major, last row 0 0 0 1 | m | the 3×3 part must be a proper rotation (orthonormal to 1e-6, det +1) |
// clang-format on
#pragma once

#include <optional>
#include <string_view>

#include "glint/model/platform.h"
#include "glint/motion/geometry.h"
#include "glint/motion/rigid.h"

namespace glint::motion {

/// Resolves named scene targets for tracking mounts (SceneTargets, scene_instances.h);
/// implementations must be thread-safe and should not allocate.
class TargetResolver {
public:
    virtual ~TargetResolver() = default;
    /// The position (scene ENU, m) of the target `name` at `t_s`, or nullopt when the scene has
    /// no such target.
    virtual std::optional<Vec3> target_position_m(std::string_view name, double t_s) const = 0;
};

/// What a mount may need besides its own parameters. Only tracking mounts read it.
struct MountContext {
    /// The mount's parent frame (the attachment it sits on, placement included) → scene ENU
    /// at the same time t. Required by tracking mounts.
    std::optional<Rigid> parent_to_scene;
    /// Named targets; null when no scene is loaded (a named tracking target is then an error).
    const TargetResolver* targets = nullptr;
};

/// Tolerance of the rigidity check of an affine transform matrix (orthonormality of the 3×3
/// part, |det − 1|, and the last row 0 0 0 1).
inline constexpr double kRigidMatrixTolerance = 1e-6;

/// The placement of an `<affinetransform>`: translation + Euler rotation, or its 4×4 matrix.
/// Throws glint::Error (input, at transform.where) for an unknown rotation order or a matrix
/// that is not rigid (last row not 0 0 0 1, 3×3 part not orthonormal, a reflection, or a
/// non-finite value).
Rigid affine_transform(const model::AffineTransform& transform);

/// Checks once what mount_transform would otherwise fail on: rotation order, an empty or
/// unordered entry table, a missing whisk scan or non-positive rate, min > max, a missing
/// tracking target, non-finite values. Throws glint::Error (input, at mount.where or the
/// entry). Does not look at the mount's attachments.
void validate_mount(const model::Mount& mount);

/// Whether the mount's transform changes with time (commanded, tabulated, whisk, tracking).
bool mount_is_time_varying(const model::Mount& mount) noexcept;

/// The scan angle of a whisk mount at `t_s` (rad), c = (min + max)/2, a = (max − min)/2,
/// φ = phase_rad, f = rate_hz:
///   sinusoidal: θ = c + a · sin(2π f t + φ)  (θ = max at a quarter period when φ = 0);
///   linear (sawtooth): θ = c + a · (2 · frac(f t + φ/2π + 1/2) − 1), a linear sweep from min
///   to max over one period, then a fly-back; like the sinusoid it crosses c rising at cycle
///   phase 0 (so at t = 0 when φ = 0), and flies back at cycle phase π.
double whisk_angle_rad(const model::WhiskScan& scan, double t_s) noexcept;

/// The rotation (mount frame → parent frame) that turns the boresight −Z towards
/// `direction` (parent frame, need not be unit length). The roll about the boresight is fixed
/// by keeping the mount's +Y in the plane of the boresight and the parent's +Y (forward), on
/// the forward side; when the boresight is along ±Y the parent's +Z takes that role. Identity
/// for a zero direction.
Quaternion tracking_rotation(const Vec3& direction) noexcept;

/// The target point (scene ENU, m) of a tracking mount at `t_s`: the fixed point, or the named
/// target from `targets`, plus offset_m. Throws glint::Error (input, at mount.where) for a
/// named target without a resolver ("tracking a named target ... needs the scene") or a
/// name the resolver does not know.
Vec3 tracking_target_m(const model::Mount& mount, double t_s, const TargetResolver* targets);

/// The transform of `mount` (mount frame → parent attachment frame) at `t_s` (seconds after
/// the tasks reference time); see the table at the top of this file. Throws glint::Error
/// (input) for the problems validate_mount reports, and (internal) for a tracking mount
/// without context.parent_to_scene. Thread-safe; allocates nothing except to throw.
Rigid mount_transform(const model::Mount& mount, double t_s, const MountContext& context = {});

}  // namespace glint::motion
