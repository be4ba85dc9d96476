// SPDX-License-Identifier: Apache-2.0
// The pose service (glint/motion/pose_service.h): instrument chains compiled once (placements
// and static mounts precomputed, jitter samplers built), then composed per call.
#include "glint/motion/pose_service.h"

#include <algorithm>
#include <string>
#include <unordered_map>
#include <utility>

#include "glint/core/error.h"
#include "glint/motion/euler.h"

namespace glint::motion {
namespace {

/// Every mount of the platform in depth-first document order → its index (jitter stream id).
void number_mounts(const std::vector<model::Attachment>& attachments,
                   std::unordered_map<const model::Mount*, std::uint64_t>& index) {
    for (const model::Attachment& attachment : attachments) {
        for (const model::Mount& mount : attachment.mounts) {
            index.emplace(&mount, index.size());
            number_mounts(mount.attachments, index);
        }
    }
}

/// A small rotation from three jitter angles about x, y, z, applied in `order`.
Quaternion jitter_rotation(const Vec3& angles_rad, EulerOrder order) noexcept {
    if (angles_rad.x == 0.0 && angles_rad.y == 0.0 && angles_rad.z == 0.0) {
        return Quaternion::identity();
    }
    return euler_to_quaternion(angles_rad, order);
}

}  // namespace

PoseService::PoseService(std::shared_ptr<const model::Platform> platform,
                         std::unique_ptr<Trajectory> vehicle,
                         const model::PlatformJitter& platform_jitter,
                         const PoseServiceOptions& options)
    : m_platform(std::move(platform)),
      m_vehicle(std::move(vehicle)),
      m_targets(options.targets),
      m_platform_jitter_order(options.platform_jitter_order) {
    if (!m_platform) throw internal_error("PoseService: no platform");
    if (!m_vehicle) throw internal_error("PoseService: no vehicle trajectory");
    const TimeSpan span = options.jitter_span;
    m_platform_jitter = PlatformJitterSampler(platform_jitter, options.seed, {options.plugin_index},
                                              span.begin_s, span.end_s, options.synthesis);

    std::unordered_map<const model::Mount*, std::uint64_t> mount_index;
    number_mounts(m_platform->attachments, mount_index);
    std::unordered_map<const model::Mount*, const MountJitterSampler*> samplers;
    const auto sampler_of = [&](const model::Mount& mount) -> const MountJitterSampler* {
        if (!mount.deviates.any()) return nullptr;
        if (const auto found = samplers.find(&mount); found != samplers.end()) {
            return found->second;
        }
        auto sampler = std::make_unique<MountJitterSampler>(
            mount.deviates, options.seed,
            std::vector<std::uint64_t>{options.plugin_index, mount_index.at(&mount)}, span.begin_s,
            span.end_s, options.synthesis);
        const MountJitterSampler* raw = sampler->any() ? sampler.get() : nullptr;
        m_mount_jitter.push_back(std::move(sampler));
        samplers.emplace(&mount, raw);
        return raw;
    };

    for (const model::InstrumentPath& path : model::list_instruments(*m_platform)) {
        Chain chain;
        chain.path = path;
        if (path.attachments.size() != path.mounts.size() + 1) {
            throw internal_error("instrument path has " + std::to_string(path.attachments.size()) +
                                 " attachments for " + std::to_string(path.mounts.size()) +
                                 " mounts");
        }
        for (std::size_t i = 0; i < path.attachments.size(); ++i) {
            Link link;
            link.placement = affine_transform(path.attachments[i]->transform);
            if (i < path.mounts.size()) {
                const model::Mount& mount = *path.mounts[i];
                validate_mount(mount);
                link.mount = &mount;
                if (mount.type == model::MountType::tracking) {
                    chain.needs_scene = true;
                    link.time_varying = true;
                    if (!mount.tracking->point_m) {
                        // Fails now, with the mount's location, rather than at the first pose:
                        // no scene, or no instance of that name.
                        tracking_target_m(mount, 0.0, m_targets);
                    }
                } else {
                    link.time_varying = mount_is_time_varying(mount);
                    if (!link.time_varying) link.fixed = mount_transform(mount, 0.0);
                }
                link.jitter = sampler_of(mount);
                link.jitter_order =
                    parse_euler_order(mount.rotation_order).value_or(EulerOrder::xyz);
            }
            chain.links.push_back(link);
        }
        m_instruments.push_back(std::move(chain));
    }
}

PoseService::PoseService(PoseService&&) noexcept = default;
PoseService& PoseService::operator=(PoseService&&) noexcept = default;
PoseService::~PoseService() = default;

const PoseService::Chain& PoseService::chain(std::size_t instrument) const {
    if (instrument >= m_instruments.size()) {
        throw internal_error("instrument index " + std::to_string(instrument) +
                             " out of range (the platform has " +
                             std::to_string(m_instruments.size()) + " instruments)");
    }
    return m_instruments[instrument];
}

const model::InstrumentPath& PoseService::instrument_path(std::size_t instrument) const {
    return chain(instrument).path;
}

Pose PoseService::nominal_vehicle_pose(double t_s) const { return m_vehicle->pose_at(t_s); }

Vec3 PoseService::vehicle_velocity_m_s(double t_s) const { return m_vehicle->velocity_m_s(t_s); }

Rigid PoseService::vehicle_to_scene(double t_s) const {
    const Pose pose = m_vehicle->pose_at(t_s);
    Rigid v{pose.orientation, pose.position_m};
    if (m_platform_jitter.any()) {
        const PlatformJitterSampler::Sample j = m_platform_jitter.at(t_s);
        v.translation_m += j.location_m;
        v.rotation =
            normalized(v.rotation * jitter_rotation(j.orientation_rad, m_platform_jitter_order));
    }
    return v;
}

Pose PoseService::vehicle_pose(double t_s) const {
    const Rigid v = vehicle_to_scene(t_s);
    return {v.translation_m, v.rotation};
}

Rigid PoseService::compose_chain(const Chain& chain, const Rigid& vehicle_to_scene,
                                 double t_s) const {
    Rigid to_scene = vehicle_to_scene;
    for (const Link& link : chain.links) {
        to_scene = to_scene * link.placement;
        if (link.mount == nullptr) break;
        Rigid mount = link.fixed;
        if (link.time_varying) {
            MountContext context;
            context.parent_to_scene = to_scene;
            context.targets = m_targets;
            mount = mount_transform(*link.mount, t_s, context);
        }
        to_scene = to_scene * mount;
        if (link.jitter != nullptr) {
            to_scene =
                to_scene * rigid_rotation(jitter_rotation(link.jitter->at(t_s), link.jitter_order));
        }
    }
    return to_scene;
}

Rigid PoseService::instrument_to_scene(std::size_t instrument, double t_s) const {
    const Chain& c = chain(instrument);
    return compose_chain(c, vehicle_to_scene(t_s), t_s);
}

Rigid PoseService::instrument_to_vehicle(std::size_t instrument, double t_s) const {
    const Chain& c = chain(instrument);
    if (!c.needs_scene) return compose_chain(c, Rigid::identity(), t_s);
    const Rigid vehicle = vehicle_to_scene(t_s);
    return inverse(vehicle) * compose_chain(c, vehicle, t_s);
}

TimeSpan jitter_span_of(const model::TaskList& tasks) noexcept {
    if (tasks.tasks.empty()) return {-1.0, 1.0};
    double begin = tasks.tasks.front().start_s;
    double end = tasks.tasks.front().stop_s;
    for (const model::Task& task : tasks.tasks) {
        begin = std::min(begin, task.start_s);
        end = std::max(end, task.stop_s);
    }
    return {begin - 1.0, end + 1.0};
}

PoseService make_pose_service(const model::PlatformInputs& inputs, std::uint64_t seed,
                              const Log& log, const SceneFrame& scene,
                              const TargetResolver* targets) {
    if (!inputs.platform) throw internal_error("make_pose_service: no platform");
    const model::PlatformMotion& motion = inputs.motion;
    const model::TaskList& tasks = inputs.tasks;
    std::unique_ptr<Trajectory> trajectory = make_trajectory(motion, scene, tasks.reference, log);
    PoseServiceOptions options;
    model::PlatformJitter jitter;
    if (motion.generic) {
        jitter = motion.generic->jitter;
        options.platform_jitter_order =
            parse_euler_order(motion.generic->rotation_order).value_or(EulerOrder::xyz);
    }
    if (motion.flexible) {
        jitter = motion.flexible->jitter;
        if (motion.flexible->orientation.type == model::OrientationEngineType::euler) {
            options.platform_jitter_order =
                parse_euler_order(motion.flexible->orientation.rotation_order)
                    .value_or(EulerOrder::xyz);
        }
    }

    options.seed = seed;
    options.plugin_index = inputs.plugin_index;
    options.targets = targets;
    options.jitter_span = jitter_span_of(tasks);
    return PoseService(inputs.platform, std::move(trajectory), jitter, options);
}

}  // namespace glint::motion
