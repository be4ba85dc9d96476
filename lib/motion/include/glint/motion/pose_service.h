// SPDX-License-Identifier: Apache-2.0
// The pose service: where every instrument of one BasicPlatform is, and where it looks, at any
// time — the one answer the capture schedule and the renderer both use.
//
// For instrument k on the path attachment_0 > mount_0 > … > attachment_n (glint/motion/
// mount.h), at time t (seconds after the tasks reference):
//     instrument_to_scene(k, t) = V(t) · P(t) · A_0 · M_0(t) · J_0(t) · A_1 · … · A_n
// where V is the vehicle pose (trajectory, vehicle → scene ENU), P the platform jitter
// (rotation euler(orientation jitter, motion rotation order) about the vehicle axes; the
// location jitter is added to V's position in scene ENU), A_i the attachment placements, M_i
// the mount transforms and J_i the mount jitter (rotation euler(x, y, z deviates, the mount's
// rotation order) in the mount frame: it perturbs the mount's own pointing). A point p of the
// instrument frame is at apply_point(instrument_to_scene, p) in the scene; the boresight is
// apply_direction(instrument_to_scene, kInstrumentBoresight) (instrument −Z).
//
// Jitter streams (glint/motion/jitter.h): platform jitter uses stream ids {plugin_index},
// the jitter of mount m (depth-first document order over every mount of the platform,
// 0-based) {plugin_index, m}; PSD series are synthesised over the options' jitter span and
// repeat outside it. Same seed, same inputs → the same poses on any thread.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "glint/core/diagnostics.h"
#include "glint/core/log.h"
#include "glint/model/jitter.h"
#include "glint/model/platform.h"
#include "glint/model/simulation.h"
#include "glint/model/simulation_inputs.h"
#include "glint/model/tasks.h"
#include "glint/motion/euler.h"
#include "glint/motion/frames.h"
#include "glint/motion/jitter.h"
#include "glint/motion/mount.h"
#include "glint/motion/rigid.h"
#include "glint/motion/trajectory.h"

namespace glint::motion {

/// How a PoseService draws jitter and resolves tracking targets.
struct PoseServiceOptions {
    std::uint64_t seed = 1;          ///< the run's --seed
    std::uint64_t plugin_index = 0;  ///< the BasicPlatform's index in plugin_list (stream id)
    TimeSpan jitter_span{};          ///< times PSD jitter series are synthesised for (s)
    /// Order of the platform orientation jitter angles (the motion file's rotation order).
    EulerOrder platform_jitter_order = EulerOrder::xyz;
    JitterSynthesisOptions synthesis{};
    /// Named tracking targets (the scene's instances, SceneTargets); null: a named target is
    /// an input error. Must outlive the service.
    const TargetResolver* targets = nullptr;
};

/// Everything needed to place one BasicPlatform's instruments in the scene at any time.
/// Immutable after construction: every const method is thread-safe, deterministic for a
/// given seed, and allocates nothing (except to throw). Movable, not copyable.
class PoseService {
public:
    /// Builds the service for `platform` (shared: the service keeps it alive), the vehicle's
    /// nominal `vehicle` trajectory and its six-axis `platform_jitter` (from the motion file).
    /// Validates every instrument's chain up front (affine_transform, validate_mount; a named
    /// tracking target without options.targets) and builds the jitter samplers. Throws
    /// glint::Error (input) at the offending element.
    PoseService(std::shared_ptr<const model::Platform> platform,
                std::unique_ptr<Trajectory> vehicle, const model::PlatformJitter& platform_jitter,
                const PoseServiceOptions& options);

    PoseService(PoseService&&) noexcept;
    PoseService& operator=(PoseService&&) noexcept;
    ~PoseService();

    /// Number of instruments (list_instruments order: the schedule's instrument index).
    std::size_t instrument_count() const noexcept { return m_instruments.size(); }
    /// The path (instrument, attachments, mounts) of instrument `instrument`.
    const model::InstrumentPath& instrument_path(std::size_t instrument) const;
    /// The platform the service was built for.
    const model::Platform& platform() const noexcept { return *m_platform; }

    /// Instrument frame → scene ENU at `t_s` (formula at the top of this file). Throws
    /// glint::Error (internal) for an index out of range, and what the trajectory throws.
    Rigid instrument_to_scene(std::size_t instrument, double t_s) const;
    /// Instrument frame → vehicle body frame at `t_s`: A_0 · M_0 · J_0 · … · A_n (tracking
    /// mounts resolved against the jittered vehicle, as in instrument_to_scene).
    Rigid instrument_to_vehicle(std::size_t instrument, double t_s) const;
    /// The vehicle pose at `t_s` with platform jitter: what the instruments ride on (V · P).
    Pose vehicle_pose(double t_s) const;
    /// The vehicle pose of the trajectory alone (no jitter).
    Pose nominal_vehicle_pose(double t_s) const;
    /// The vehicle velocity (scene ENU, m/s) of the trajectory at `t_s`.
    Vec3 vehicle_velocity_m_s(double t_s) const;
    /// The vehicle trajectory.
    const Trajectory& trajectory() const noexcept { return *m_vehicle; }
    /// The platform's rotation order: the `.ppd`'s, or a FlexMotion euler engine's, else xyz.
    EulerOrder platform_rotation_order() const noexcept { return m_platform_jitter_order; }

private:
    /// One attachment > mount step of an instrument's chain.
    struct Link {
        Rigid placement;                             ///< the attachment's affine transform
        const model::Mount* mount = nullptr;         ///< null for the last (instrument) attachment
        bool time_varying = false;                   ///< false: `fixed` holds the mount transform
        Rigid fixed;                                 ///< the static mount transform
        const MountJitterSampler* jitter = nullptr;  ///< null: no jitter on this mount
        EulerOrder jitter_order = EulerOrder::xyz;   ///< the mount's rotation order
    };
    struct Chain {
        model::InstrumentPath path;
        std::vector<Link> links;   ///< outermost first; the last has no mount
        bool needs_scene = false;  ///< a tracking mount sits on the path
    };

    Rigid vehicle_to_scene(double t_s) const;
    /// Composes `chain` onto `vehicle_to_scene` (the jittered vehicle → scene ENU).
    Rigid compose_chain(const Chain& chain, const Rigid& vehicle_to_scene, double t_s) const;
    const Chain& chain(std::size_t instrument) const;

    std::shared_ptr<const model::Platform> m_platform;
    std::unique_ptr<Trajectory> m_vehicle;
    PlatformJitterSampler m_platform_jitter;
    std::vector<std::unique_ptr<MountJitterSampler>> m_mount_jitter;  ///< stable addresses
    std::vector<Chain> m_instruments;
    const TargetResolver* m_targets = nullptr;
    EulerOrder m_platform_jitter_order = EulerOrder::xyz;
};

/// The span jitter series are synthesised for, from a task list: [first start − 1 s, last
/// stop + 1 s]; [−1, 1] s without tasks.
TimeSpan jitter_span_of(const model::TaskList& tasks) noexcept;

/// Builds the pose service of one BasicPlatform entry, already read (glint/inputs/load.h):
/// places the scene frame at `scene` (the scene's origin; kDefaultSceneOrigin by default),
/// resolves named tracking targets with `targets` (must outlive the service; null: a named
/// target is an input error), builds the trajectory (tasks reference date-time; `log` gets its
/// clamp warning) and the jitter (seed; streams as described above, plugin index
/// inputs.plugin_index; span jitter_span_of(tasks); platform jitter angles in the `.ppd`
/// rotation order, or a FlexMotion euler engine's, else xyz; PSD tables as the loader read
/// them). Throws glint::Error (input) when the platform or motion cannot be used.
PoseService make_pose_service(const model::PlatformInputs& inputs, std::uint64_t seed,
                              const Log& log, const SceneFrame& scene = SceneFrame(),
                              const TargetResolver* targets = nullptr);

}  // namespace glint::motion
