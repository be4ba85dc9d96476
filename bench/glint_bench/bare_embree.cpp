// SPDX-License-Identifier: Apache-2.0
// The bare Embree baseline of glint-bench (bare_embree.h).
#include "bare_embree.h"

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstring>
#include <functional>
#include <limits>

#include "glint/core/error.h"
#include "glint/motion/euler.h"
#include "glint/motion/geometry.h"
#include "measurements.h"

namespace glint::bench {
namespace {

using Clock = std::chrono::steady_clock;

/// Rays per task of the parallel loops.
constexpr std::size_t kGrain = 256;

/// The object → scene map of a static transform as Embree's column-major 3×4 floats, with
/// the same conventions as the scene component (translation + R · (scale ∘ p), R the
/// rotations in rotation_order, first letter first; or the row-major 4×4 matrix).
std::array<float, 12> float3x4(const model::Instance& instance) {
    const model::StaticTransform& t = instance.transform;
    motion::Mat3 linear;
    motion::Vec3 translation;
    if (t.matrix) {
        for (std::size_t i = 0; i < 3; ++i) {
            for (std::size_t j = 0; j < 3; ++j) linear(i, j) = (*t.matrix)[i * 4 + j];
            translation[i] = (*t.matrix)[i * 4 + 3];
        }
    } else {
        const auto order = motion::parse_euler_order(t.rotation_order);
        if (!order) {
            throw input_error(
                "rotation order \"" + t.rotation_order + "\" is not a permutation of xyz",
                instance.where);
        }
        const motion::Mat3 rotation =
            motion::euler_to_matrix(motion::to_vec3(t.rotation_rad), *order);
        for (std::size_t i = 0; i < 3; ++i) {
            for (std::size_t j = 0; j < 3; ++j) linear(i, j) = rotation(i, j) * t.scale[j];
        }
        translation = motion::to_vec3(t.translation_m);
    }
    std::array<float, 12> out{};
    for (std::size_t j = 0; j < 3; ++j) {
        for (std::size_t i = 0; i < 3; ++i) out[j * 3 + i] = static_cast<float>(linear(i, j));
    }
    for (std::size_t i = 0; i < 3; ++i) out[9 + i] = static_cast<float>(translation[i]);
    return out;
}

void fill(RTCRayHit& rayhit, const BareRay& ray) noexcept {
    rayhit.ray.org_x = ray.origin[0];
    rayhit.ray.org_y = ray.origin[1];
    rayhit.ray.org_z = ray.origin[2];
    rayhit.ray.dir_x = ray.direction[0];
    rayhit.ray.dir_y = ray.direction[1];
    rayhit.ray.dir_z = ray.direction[2];
    rayhit.ray.tnear = 0.0f;
    rayhit.ray.tfar = std::numeric_limits<float>::infinity();
    rayhit.ray.time = 0.0f;
    rayhit.ray.mask = 0xFFFFFFFFu;
    rayhit.ray.id = 0;
    rayhit.ray.flags = 0;
    rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
}

int arena_threads(unsigned threads) {
    return threads == 0 ? tbb::task_arena::automatic : static_cast<int>(threads);
}

}  // namespace

BareEmbreeScene::BareEmbreeScene(const model::Scene& scene, const std::string& config) {
    const auto start = Clock::now();
    m_device = rtcNewDevice(config.empty() ? nullptr : config.c_str());
    if (m_device == nullptr) {
        throw runtime_error("Embree refused to make a device (configuration \"" + config + "\")");
    }
    rtcSetDeviceErrorFunction(
        m_device,
        [](void* user, RTCError code, const char* message) {
            auto* state = static_cast<ErrorState*>(user);
            if (state->code != RTC_ERROR_NONE) return;
            state->code = code;
            state->message = message != nullptr ? message : "";
        },
        &m_error);

    m_objects.assign(scene.objects.size(), nullptr);
    for (const model::Instance& instance : scene.instances) {
        if (instance.dynamic()) {
            throw input_error("the bare Embree baseline takes static instances only",
                              instance.where);
        }
        RTCScene& object_scene = m_objects.at(instance.object_index);
        if (object_scene != nullptr) continue;
        const model::Mesh& mesh = scene.objects[instance.object_index].mesh;
        RTCGeometry geometry = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(
            rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                    3 * sizeof(float), mesh.vertices_m.size()));
        auto* triangles = static_cast<std::uint32_t*>(
            rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                    3 * sizeof(std::uint32_t), mesh.triangles.size()));
        check("making the buffers of an object");
        std::memcpy(vertices, mesh.vertices_m.data(), mesh.vertices_m.size() * 3 * sizeof(float));
        std::memcpy(triangles, mesh.triangles.data(),
                    mesh.triangles.size() * 3 * sizeof(std::uint32_t));
        rtcCommitGeometry(geometry);
        object_scene = rtcNewScene(m_device);
        rtcSetSceneFlags(object_scene, RTC_SCENE_FLAG_ROBUST);
        rtcSetSceneBuildQuality(object_scene, RTC_BUILD_QUALITY_HIGH);
        rtcAttachGeometryByID(object_scene, geometry, 0);
        rtcReleaseGeometry(geometry);
        rtcCommitScene(object_scene);
        check("building an object scene");
    }

    m_top = rtcNewScene(m_device);
    rtcSetSceneFlags(m_top, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(m_top, RTC_BUILD_QUALITY_HIGH);
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const model::Instance& instance = scene.instances[i];
        RTCGeometry geometry = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(geometry, m_objects[instance.object_index]);
        const std::array<float, 12> xfm = float3x4(instance);
        rtcSetGeometryTransform(geometry, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm.data());
        rtcCommitGeometry(geometry);
        rtcAttachGeometryByID(m_top, geometry, static_cast<unsigned>(i));
        rtcReleaseGeometry(geometry);
    }
    rtcCommitScene(m_top);
    check("building the top-level scene");
    m_build_seconds = seconds_since(start);
}

BareEmbreeScene::~BareEmbreeScene() {
    if (m_top != nullptr) rtcReleaseScene(m_top);
    for (RTCScene s : m_objects) {
        if (s != nullptr) rtcReleaseScene(s);
    }
    if (m_device != nullptr) rtcReleaseDevice(m_device);
}

void BareEmbreeScene::check(const std::string& what) const {
    if (m_error.code != RTC_ERROR_NONE) {
        throw runtime_error("Embree failed while " + what + ": " + m_error.message);
    }
}

std::string BareEmbreeScene::version() const {
    const auto major = rtcGetDeviceProperty(m_device, RTC_DEVICE_PROPERTY_VERSION_MAJOR);
    const auto minor = rtcGetDeviceProperty(m_device, RTC_DEVICE_PROPERTY_VERSION_MINOR);
    const auto patch = rtcGetDeviceProperty(m_device, RTC_DEVICE_PROPERTY_VERSION_PATCH);
    return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch);
}

unsigned BareEmbreeScene::native_packet_width() const {
    if (rtcGetDeviceProperty(m_device, RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED) != 0) return 16;
    if (rtcGetDeviceProperty(m_device, RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED) != 0) return 8;
    if (rtcGetDeviceProperty(m_device, RTC_DEVICE_PROPERTY_NATIVE_RAY4_SUPPORTED) != 0) return 4;
    return 0;
}

namespace {

/// One timing: passes over `rays` until `min_seconds` have gone by.
BareTiming time_passes(const BareEmbreeScene& scene, std::span<const BareRay> rays,
                       unsigned threads, double min_seconds) {
    BareTiming timing;
    if (rays.empty()) return timing;
    tbb::task_arena arena(arena_threads(threads));
    tbb::combinable<std::uint64_t> hits([] { return std::uint64_t{0}; });
    const RTCScene top = scene.top();
    const auto start = Clock::now();
    do {
        arena.execute([&] {
            tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), kGrain),
                              [&](const tbb::blocked_range<std::size_t>& range) {
                                  std::uint64_t local = 0;
                                  RTCIntersectContext context;
                                  rtcInitIntersectContext(&context);
                                  for (std::size_t i = range.begin(); i != range.end(); ++i) {
                                      RTCRayHit rayhit;
                                      fill(rayhit, rays[i]);
                                      rtcIntersect1(top, &context, &rayhit);
                                      local += rayhit.hit.geomID != RTC_INVALID_GEOMETRY_ID;
                                  }
                                  hits.local() += local;
                              });
        });
        ++timing.passes;
        timing.seconds = seconds_since(start);
    } while (timing.seconds < min_seconds);
    timing.rays = std::uint64_t{timing.passes} * rays.size();
    timing.hits = hits.combine(std::plus<>());
    return timing;
}

}  // namespace

BareTiming time_intersect(const BareEmbreeScene& scene, std::span<const BareRay> rays,
                          unsigned threads, double min_seconds, unsigned repeats) {
    BareTiming best;
    for (unsigned r = 0; r < std::max(1u, repeats); ++r) {
        const BareTiming t = time_passes(scene, rays, threads, min_seconds);
        if (r == 0 || t.rays_per_s() > best.rays_per_s()) best = t;
    }
    return best;
}

std::vector<float> intersect_distances(const BareEmbreeScene& scene, std::span<const BareRay> rays,
                                       unsigned threads) {
    std::vector<float> out(rays.size(), std::numeric_limits<float>::infinity());
    tbb::task_arena arena(arena_threads(threads));
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), kGrain),
                          [&](const tbb::blocked_range<std::size_t>& range) {
                              RTCIntersectContext context;
                              rtcInitIntersectContext(&context);
                              for (std::size_t i = range.begin(); i != range.end(); ++i) {
                                  RTCRayHit rayhit;
                                  fill(rayhit, rays[i]);
                                  rtcIntersect1(scene.top(), &context, &rayhit);
                                  if (rayhit.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
                                      out[i] = rayhit.ray.tfar;
                                  }
                              }
                          });
    });
    return out;
}

}  // namespace glint::bench
