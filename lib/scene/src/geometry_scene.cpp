// SPDX-License-Identifier: Apache-2.0
// GeometryScene::build: checks the options and the scene, builds one Embree scene per
// instanced object, finds the scene bounds (every step pose, padded for what interpolation
// between steps may add) and the anchor of Embree's frame (their centre), then the top-level
// scene of instances — static ones with their fixed transform, dynamic ones with
// quaternion-decomposed transforms at the time steps instance_motion.cpp chooses — all
// relative to the anchor. Also the small accessors.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "geometry_scene_impl.h"
#include "glint/core/error.h"
#include "glint/core/text.h"
#include "instance_motion.h"
#include "object_scene.h"

namespace glint::scene {
namespace {

using detail::Affine;

/// Embree's limit on time steps (RTC_MAX_TIME_STEP_COUNT).
constexpr unsigned kMaxEmbreeTimeSteps = RTC_MAX_TIME_STEP_COUNT;
/// Enlargement of the clipping box: relative part (× its size or coordinates) and absolute.
constexpr double kClipPadRelative = 1e-3;
constexpr double kClipPad_m = 1.0;

void check_options(const BuildOptions& options) {
    const MotionSampling& m = options.motion;
    if (m.min_time_steps < 2) {
        throw usage_error("min_time_steps is " + std::to_string(m.min_time_steps) +
                          ", expected at least 2");
    }
    if (m.max_time_steps < m.min_time_steps || m.max_time_steps > kMaxEmbreeTimeSteps) {
        throw usage_error("max_time_steps is " + std::to_string(m.max_time_steps) + ", expected " +
                          std::to_string(m.min_time_steps) + " (min_time_steps) to " +
                          std::to_string(kMaxEmbreeTimeSteps));
    }
    if (!(m.max_step_rotation_deg > 0.0) || !std::isfinite(m.max_step_rotation_deg)) {
        throw usage_error("max_step_rotation_deg is " + format_shortest(m.max_step_rotation_deg) +
                          ", expected a positive angle");
    }
    if (!(m.max_step_fraction > 0.0) || !std::isfinite(m.max_step_fraction)) {
        throw usage_error("max_step_fraction is " + format_shortest(m.max_step_fraction) +
                          ", expected a positive fraction");
    }
    const TimeWindow& w = options.window;
    if (!std::isfinite(w.begin_s) || !std::isfinite(w.end_s)) {
        throw usage_error("the time window is not finite");
    }
    if (w.end_s < w.begin_s) {
        throw usage_error("the time window ends (" + format_shortest(w.end_s) +
                          " s) before it begins (" + format_shortest(w.begin_s) + " s)");
    }
}

/// The map a static (or instantaneous) instance gives Embree: from the object's vertex
/// buffer (relative to its centre) to Embree's frame (scene ENU less the anchor).
Affine frame_affine(const Affine& affine, const detail::ObjectData& object, const Vec3& anchor_m) {
    return {affine.linear, affine.apply(object.center_m) - anchor_m};
}

/// Places a static (or instantaneous) instance in Embree's frame; keeps the map Embree holds
/// (its float matrix) and the normal matrix for the hits.
void place_fixed(RTCGeometry geometry, const Affine& affine, const detail::ObjectData& object,
                 const Vec3& anchor_m, detail::InstanceData& data) {
    const std::array<float, 12> xfm = detail::to_float3x4(frame_affine(affine, object, anchor_m));
    rtcSetGeometryTransform(geometry, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm.data());
    float held[12];
    std::copy(xfm.begin(), xfm.end(), held);
    data.to_frame = detail::from_float3x4(held);
    // Of the float map too: the plane a hit is rebuilt on is then Embree's to double rounding
    // (the double map's normal would tilt it by ~1e-7, 5 mm across a 50 km triangle).
    data.normal_matrix = detail::inverse_transpose(data.to_frame.linear);
}

/// The bounds a moving instance sweeps over the window, padded for what interpolation
/// between steps may add.
Bounds swept_bounds(const detail::MotionSamples& samples, const Bounds& object_box,
                    const detail::ObjectExtent& extent, const MotionSampling& sampling) {
    Bounds swept = detail::empty_bounds();
    for (const motion::Pose& pose : samples.poses) {
        detail::expand(swept, detail::transformed(object_box, detail::pose_affine(pose)));
    }
    // Between steps a point turns on an arc that leaves the chord by at most
    // r (1 − cos(θ/2)); the trajectory itself may stray from the interpolation by the
    // sampling tolerance.
    const double arc_m = extent.radius_m * (1.0 - std::cos(0.5 * samples.max_step_rotation_rad));
    const double pad_m =
        arc_m + std::max(samples.max_error_m, sampling.max_step_fraction * extent.diagonal_m);
    return detail::padded(swept, pad_m);
}

/// Places a moving instance: one quaternion decomposition per step, its object's centre as
/// the shift (applied before the rotation) and the anchor taken off the translation.
void place_moving(RTCGeometry geometry, const detail::MotionSamples& samples,
                  const detail::ObjectData& object, const Vec3& anchor_m,
                  detail::InstanceData& data) {
    rtcSetGeometryTimeStepCount(geometry, static_cast<unsigned>(samples.poses.size()));
    for (std::size_t k = 0; k < samples.poses.size(); ++k) {
        const motion::Pose& pose = samples.poses[k];
        RTCQuaternionDecomposition qd;
        rtcInitQuaternionDecomposition(&qd);
        const motion::Quaternion& q = pose.orientation;
        rtcQuaternionDecompositionSetQuaternion(&qd, static_cast<float>(q.w),
                                                static_cast<float>(q.x), static_cast<float>(q.y),
                                                static_cast<float>(q.z));
        rtcQuaternionDecompositionSetShift(&qd, static_cast<float>(object.center_m.x),
                                           static_cast<float>(object.center_m.y),
                                           static_cast<float>(object.center_m.z));
        const Vec3 t = pose.position_m - anchor_m;
        rtcQuaternionDecompositionSetTranslation(&qd, static_cast<float>(t.x),
                                                 static_cast<float>(t.y), static_cast<float>(t.z));
        rtcSetGeometryTransformQuaternion(geometry, static_cast<unsigned>(k), &qd);
    }
    data.moving = true;
    data.geometry = geometry;
}

/// Embree's frame origin for scene bounds `bounds`: their centre, to whole metres (0 for an
/// empty scene).
Vec3 frame_anchor(const Bounds& bounds) {
    if (bounds.empty()) return {};
    const Vec3 center = (bounds.lower + bounds.upper) * 0.5;
    return {std::round(center.x), std::round(center.y), std::round(center.z)};
}

Bounds clip_box(const Bounds& bounds) {
    if (bounds.empty()) return bounds;
    double size_m = norm(bounds.upper - bounds.lower);
    for (std::size_t i = 0; i < 3; ++i) {
        size_m = std::max({size_m, std::abs(bounds.lower[i]), std::abs(bounds.upper[i])});
    }
    return detail::padded(bounds, kClipPad_m + kClipPadRelative * size_m);
}

}  // namespace

GeometryScene GeometryScene::build(
    const model::Scene& scene, const std::vector<std::unique_ptr<motion::Trajectory>>& trajectories,
    const BuildOptions& options, Log log) {
    check_options(options);
    for (const model::Instance& instance : scene.instances) {
        if (instance.object_index >= scene.objects.size()) {
            throw input_error("instance \"" + instance.name + "\" refers to object " +
                                  std::to_string(instance.object_index) + ", out of range (" +
                                  std::to_string(scene.objects.size()) + " objects)",
                              instance.where);
        }
    }
    for (const model::GeometryObject& object : scene.objects) {
        detail::check_mesh(object, scene.materials.size());
    }

    auto impl = std::make_unique<Impl>();
    impl->maps = SurfaceMaps(scene);
    impl->window = options.window;
    impl->device = std::make_unique<detail::EmbreeDevice>(options.device);
    detail::EmbreeDevice& device = *impl->device;

    impl->objects.resize(scene.objects.size());
    for (const model::Instance& instance : scene.instances) {
        detail::ObjectData& data = impl->objects[instance.object_index];
        if (data.scene) continue;
        const model::GeometryObject& object = scene.objects[instance.object_index];
        data = detail::build_object_scene(device, object);
        if (impl->maps.uses_uv()) data.uvs = object.mesh.triangle_uvs;
    }

    bool any_moving = false;
    const std::size_t n = scene.instances.size();
    impl->instances.resize(n);
    impl->time_steps.assign(n, 1);
    impl->instance_geometries.reserve(n);
    impl->bounds = detail::empty_bounds();
    std::vector<detail::MotionSamples> samples(n);
    for (std::size_t i = 0; i < n; ++i) {
        const model::Instance& instance = scene.instances[i];
        if (!instance.dynamic() || options.static_only) continue;
        const motion::Trajectory* trajectory =
            i < trajectories.size() ? trajectories[i].get() : nullptr;
        if (!trajectory) {
            throw input_error("dynamic instance \"" + instance.name + "\" has no trajectory",
                              instance.where);
        }
        const model::Mesh& mesh = scene.objects[instance.object_index].mesh;
        samples[i] = detail::sample_motion(*trajectory, options.window, options.motion,
                                           detail::mesh_extent(mesh), instance.where);
        if (!samples[i].within_tolerance) {
            log.warning(format_located(
                instance.where,
                "instance \"" + instance.name + "\": " + std::to_string(samples[i].poses.size()) +
                    " time steps leave steps of up to " +
                    format_shortest(samples[i].max_step_rotation_rad * 180.0 / std::numbers::pi) +
                    " deg and an interpolation error of up to " +
                    format_shortest(samples[i].max_error_m) + " m (above the tolerances)"));
        }
        any_moving = any_moving || samples[i].poses.size() > 1;
    }

    impl->any_moving = any_moving;
    // First where every instance is (its map, or its swept box), so the anchor of Embree's
    // frame is known before any float matrix is made.
    std::vector<detail::Affine> fixed(n);
    for (std::size_t i = 0; i < n; ++i) {
        const model::Instance& instance = scene.instances[i];
        const model::Mesh& mesh = scene.objects[instance.object_index].mesh;
        detail::InstanceData& data = impl->instances[i];
        data.object = instance.object_index;
        if (instance.dynamic() && options.static_only) {
            data.absent = true;
            data.bounds = detail::empty_bounds();
            continue;
        }
        const Bounds object_box = detail::mesh_bounds(mesh);
        if (!instance.dynamic()) {
            fixed[i] = detail::static_affine(instance.transform, instance.where);
            data.bounds = detail::transformed(object_box, fixed[i]);
        } else if (samples[i].poses.size() == 1) {
            fixed[i] = detail::pose_affine(samples[i].poses.front());
            data.bounds = detail::transformed(object_box, fixed[i]);
        } else {
            data.bounds =
                swept_bounds(samples[i], object_box, detail::mesh_extent(mesh), options.motion);
            impl->time_steps[i] = static_cast<unsigned>(samples[i].poses.size());
        }
        detail::expand(impl->bounds, data.bounds);
    }
    impl->anchor_m = frame_anchor(impl->bounds);

    impl->top = device.new_scene(RTC_SCENE_FLAG_ROBUST,
                                 any_moving ? RTC_BUILD_QUALITY_MEDIUM : RTC_BUILD_QUALITY_HIGH,
                                 "building the top-level scene");
    for (std::size_t i = 0; i < n; ++i) {
        const model::Instance& instance = scene.instances[i];
        const std::string what = "placing instance \"" + instance.name + "\"";
        detail::InstanceData& data = impl->instances[i];
        if (data.absent) continue;
        const detail::ObjectData& object = impl->objects[data.object];
        impl->instanced_triangles += object.triangle_count;

        detail::GeometryPtr geometry = device.new_geometry(RTC_GEOMETRY_TYPE_INSTANCE, what);
        rtcSetGeometryInstancedScene(geometry.get(), object.scene.get());
        if (impl->time_steps[i] > 1) {
            place_moving(geometry.get(), samples[i], object, impl->anchor_m, data);
        } else {
            place_fixed(geometry.get(), fixed[i], object, impl->anchor_m, data);
        }
        rtcCommitGeometry(geometry.get());
        device.check(what);
        rtcAttachGeometryByID(impl->top.get(), geometry.get(), static_cast<unsigned>(i));
        device.check(what);
        impl->instance_geometries.push_back(std::move(geometry));
    }
    rtcCommitScene(impl->top.get());
    device.check("building the top-level scene");
    impl->clip_bounds = clip_box(impl->bounds);
    log.debug("Embree scene: " + std::to_string(n) + " instances, " +
              std::to_string(impl->instanced_triangles) + " instanced triangles, " +
              std::to_string(device.used_bytes()) + " bytes held by Embree");
    return GeometryScene(std::move(impl));
}

GeometryScene::GeometryScene(std::unique_ptr<Impl> impl) : m_impl(std::move(impl)) {}
GeometryScene::GeometryScene(GeometryScene&&) noexcept = default;
GeometryScene& GeometryScene::operator=(GeometryScene&&) noexcept = default;
GeometryScene::~GeometryScene() = default;

const Bounds& GeometryScene::bounds() const noexcept { return m_impl->bounds; }
const SurfaceMaps& GeometryScene::maps() const noexcept { return m_impl->maps; }
Bounds GeometryScene::instance_bounds(std::size_t instance) const noexcept {
    if (instance >= m_impl->instances.size()) return detail::empty_bounds();
    return m_impl->instances[instance].bounds;
}

const TimeWindow& GeometryScene::window() const noexcept { return m_impl->window; }
const DeviceInfo& GeometryScene::device() const noexcept { return m_impl->device->info(); }
std::uint64_t GeometryScene::instanced_triangle_count() const noexcept {
    return m_impl->instanced_triangles;
}
const std::vector<unsigned>& GeometryScene::time_steps() const noexcept {
    return m_impl->time_steps;
}

}  // namespace glint::scene
