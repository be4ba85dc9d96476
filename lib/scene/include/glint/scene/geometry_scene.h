// SPDX-License-Identifier: Apache-2.0
// The Embree 3 scene the path tracer traces: every geometry object of a model::Scene becomes
// one triangle mesh in its own Embree scene (built once, shared by all its instances), and
// every instance an Embree instance of it in the top-level scene (a two-level BVH). Static
// instances carry their fixed transform; dynamic instances carry a quaternion-decomposed
// motion transform with time steps spanning the capture window, so a ray's time inside the
// window sees the instance where its trajectory puts it (Embree interpolates between steps;
// quaternion interpolation keeps a spinning rotor rigid).
//
// Precision: Embree works in single precision. intersect() and occluded() take double-
// precision rays and first clip them to the scene's bounding box (slightly enlarged) in
// double precision, so a sensor 36,000 km up does not lose the ground to float rounding.
// Embree's frame has its origin at the centre of the scene's bounds and each object's
// vertices are stored relative to the object's centre, so Embree's numbers are as large as
// the scene and the objects, not as their distance from the scene origin (UTM coordinates
// work). A hit's position is rebuilt in double from its triangle, so it lies on the surface
// however far the ray ran; the distances reported are from the caller's origin.
// spawn_origin() moves a secondary ray's origin off the surface by a bound on the float
// error of Embree's numbers near the hit, so no surface is hit again by a ray leaving it.
//
// Errors: Embree device errors (out of memory, invalid arguments, unsupported CPU) are
// collected by the device's error callback and rethrown as glint::Error (runtime) after the
// call that raised them. A memory cap (bytes) is enforced by Embree's memory monitor: a build
// that would exceed it fails with glint::Error (runtime: glint::ErrorCategory has no resource
// category) naming the cap and the amount requested.
//
// Thread safety: after build(), intersect/occluded/normal queries may be called from any
// number of threads at once. The object owns its Embree device and scenes.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "glint/core/datetime.h"
#include "glint/core/log.h"
#include "glint/model/scene.h"
#include "glint/motion/frames.h"
#include "glint/motion/geometry.h"
#include "glint/motion/scene_instances.h"
#include "glint/motion/trajectory.h"
#include "glint/scene/facet_temperatures.h"
#include "glint/scene/surface_maps.h"

namespace glint::scene {

using motion::Vec3;

/// Embree device settings (recorded in provenance through DeviceInfo).
struct DeviceSettings {
    unsigned threads = 0;  ///< threads Embree may use to build; 0 = all hardware threads
    /// ISA Embree should use ("sse2", "sse4.2", "avx", "avx2", "avx512"); empty = best the
    /// CPU supports. An unknown name is a glint::Error (usage).
    std::string isa;
    /// Cap on the memory Embree may allocate, bytes; 0 = no cap (--max-memory).
    std::uint64_t max_memory_bytes = 0;
};

/// What the device reports about itself, for provenance.
struct DeviceInfo {
    std::string embree_version;  ///< e.g. "3.13.5"
    std::string config;          ///< the rtcNewDevice configuration string used
    unsigned threads = 0;        ///< as requested (0 = all)
};

/// The time window dynamic instances are sampled over, seconds after the tasks reference
/// time. begin_s == end_s is an instant (one pose per dynamic instance).
struct TimeWindow {
    double begin_s = 0.0;
    double end_s = 0.0;
};

/// How finely dynamic instances are sampled in time.
struct MotionSampling {
    /// At least this many time steps over a window of non-zero length (≥ 2).
    unsigned min_time_steps = 2;
    /// At most this many (Embree allows up to 129).
    unsigned max_time_steps = 129;
    /// Steps are added until no step turns the instance by more than this angle, or moves
    /// it by more than max_step_fraction of its object's bounding-box diagonal beyond what
    /// linear interpolation between the step poses reproduces.
    double max_step_rotation_deg = 5.0;
    double max_step_fraction = 0.01;
};

/// Everything build() needs besides the scene.
struct BuildOptions {
    DeviceSettings device;
    TimeWindow window;
    MotionSampling motion;
    /// Leave the dynamic instances (those with a motion) out: no ray meets them and
    /// static_facets() lists none of them; the others keep their indices. THERM's shadow
    /// history in a scene where something moves is traced in such a scene.
    bool static_only = false;
};

/// A ray's closest hit.
struct RayHit {
    double distance_m = 0.0;  ///< along the (unit) direction, from the caller's origin
    Vec3 position_m;          ///< origin + distance · direction, scene ENU
    /// Unit geometric normal in scene ENU at the ray's time, on the side of the triangle's
    /// front face (counter-clockwise vertices); not flipped towards the ray: the triangle's
    /// plane normal (the edges' cross product of its float vertices, normalized in double,
    /// stored as float), taken through the instance's normal matrix and normalized.
    Vec3 normal;
    /// How far spawn_origin() moves a ray leaving this hit off the surface, m: a bound on the
    /// single-precision error of Embree's numbers near the hit (4 float ulps of the hit's
    /// coordinates in Embree's frame, its instance's translation and its triangle's size;
    /// docs/scene.md).
    double spawn_offset_m = 0.0;
    /// Index into model::Scene::materials: the triangle's, or what the property maps make
    /// of it there (surface_maps.h).
    std::uint32_t material = 0;
    std::uint32_t instance = 0;  ///< index into model::Scene::instances
    std::uint32_t triangle = 0;  ///< index into the object's mesh triangles
    /// A mixture map's texel covers the hit (maps().mix gives its materials and weights);
    /// kNoMixture otherwise.
    std::uint32_t mixture_map = kNoMixture;
    std::uint64_t mixture_texel = 0;
    /// A temperature map's value at the hit, K; 0: the material's own temperature.
    double temperature_k = 0.0;
    /// A bump map tilts the shading normal: `shading_normal` (unit, on the side of `normal`)
    /// is the one the surface's BSDF uses; `normal` stays the geometry's. Unset otherwise.
    bool bumped = false;
    Vec3 shading_normal;
};

/// Rays traced together by GeometryScene's packet queries.
inline constexpr std::size_t kPacketSize = 16;

/// One ray of a packet query: origin_m + s · direction, s in (tmin_m, tmax_m), at `time_s`.
struct PacketRay {
    Vec3 origin_m;      ///< scene ENU
    Vec3 direction;     ///< unit
    double time_s = 0;  ///< clamped into the window
    double tmin_m = 0.0;
    double tmax_m = std::numeric_limits<double>::infinity();
};

/// Axis-aligned bounds in scene ENU metres (of every instance over the whole window).
struct Bounds {
    Vec3 lower;
    Vec3 upper;
    bool empty() const noexcept {
        return !(lower.x <= upper.x && lower.y <= upper.y && lower.z <= upper.z);
    }
};

/// The built Embree scene.
class GeometryScene {
public:
    /// Builds the scene. `trajectories` is indexed like scene.instances
    /// (motion::make_instance_trajectories); it must hold a trajectory for every dynamic
    /// instance. Throws
    /// glint::Error: usage for bad settings (unknown ISA, min_time_steps < 2, window end <
    /// begin), input when a dynamic instance has no trajectory or a mesh has a material
    /// index out of range or a static transform is singular, runtime when the memory cap
    /// is exceeded and for other Embree errors. An empty scene (no instances) is valid:
    /// every ray misses.
    static GeometryScene build(const model::Scene& scene,
                               const std::vector<std::unique_ptr<motion::Trajectory>>& trajectories,
                               const BuildOptions& options, Log log = {});

    GeometryScene(GeometryScene&&) noexcept;
    GeometryScene& operator=(GeometryScene&&) noexcept;
    ~GeometryScene();

    /// The closest hit of the ray origin + s · direction with s in (tmin_m, tmax_m), at time
    /// `time_s` (clamped into the window). `direction` must be unit length.
    std::optional<RayHit> intersect(const Vec3& origin_m, const Vec3& direction, double time_s,
                                    double tmin_m = 0.0,
                                    double tmax_m = std::numeric_limits<double>::infinity()) const;
    /// intersect() into `hit` (left unspecified on a miss); returns whether the ray hit. For
    /// loops that keep one hit and would otherwise copy it out of an optional every bounce.
    bool intersect_into(const Vec3& origin_m, const Vec3& direction, double time_s, RayHit& hit,
                        double tmin_m = 0.0,
                        double tmax_m = std::numeric_limits<double>::infinity()) const;
    /// intersect() for each of up to kPacketSize rays, traced together by Embree's packet
    /// kernel (rtcIntersect16): hits[i] is what intersect() gives for rays[i]. Faster than
    /// single queries for coherent rays (a camera's rays through neighbouring pixels). The
    /// answers are the same bits as intersect()'s: Embree's packet and single-ray kernels
    /// compute the same numbers on static scenes (checked by the scene tests on the Embree the
    /// build links); a scene with moving instances traces the rays one by one, because there
    /// they do not.
    /// Throws glint::Error (internal) for more than kPacketSize rays or hits.size() !=
    /// rays.size().
    void intersect_packet(std::span<const PacketRay> rays,
                          std::span<std::optional<RayHit>> hits) const;
    /// occluded() for each of up to kPacketSize rays, traced together (rtcOccluded16):
    /// blocked[i] is what occluded() gives for rays[i], under the same rules as
    /// intersect_packet. Throws glint::Error (internal) for more than kPacketSize rays or
    /// blocked.size() != rays.size().
    void occluded_packet(std::span<const PacketRay> rays, std::span<bool> blocked) const;
    /// Whether anything lies on the ray for s in (tmin_m, tmax_m) at `time_s`.
    bool occluded(const Vec3& origin_m, const Vec3& direction, double time_s, double tmin_m = 0.0,
                  double tmax_m = std::numeric_limits<double>::infinity()) const;

    /// An origin for a ray leaving `hit` towards `direction`: the hit position moved off the
    /// surface along the normal (to the side `direction` points to) by hit.spawn_offset_m.
    Vec3 spawn_origin(const RayHit& hit, const Vec3& direction) const noexcept;

    /// Bounds of the whole scene over the window (empty for an empty scene).
    const Bounds& bounds() const noexcept;
    /// The scene's property maps (applied to every hit; a mixture's draw is the caller's).
    const SurfaceMaps& maps() const noexcept;

    /// A triangle of a static instance in scene ENU (for per-facet work: THERM).
    struct Facet {
        std::uint32_t instance = 0;
        std::uint32_t triangle = 0;
        std::uint32_t material = 0;  ///< the triangle's own (before any property map)
        Vec3 centroid_m;
        /// Its corners: a point with barycentrics (u, v) (Embree's) is corner 0 + u (corner 1
        /// − corner 0) + v (corner 2 − corner 0).
        std::array<Vec3, 3> corners_m;
        Vec3 normal;  ///< unit, on the front face's side (zero for a degenerate triangle)
        double spawn_offset_m = 0.0;  ///< as a hit there would have it (spawn_origin())
    };
    /// Every triangle of the static instances whose material index `wanted` says, in instance
    /// then triangle order.
    std::vector<Facet> static_facets(const std::function<bool(std::uint32_t)>& wanted) const;
    /// Per-facet temperatures over cells and time (THERM): a hit on a listed facet reports
    /// its cell's temperature at the ray's time (RayHit::temperature_k) unless a temperature
    /// map gave one. Set before tracing; null clears.
    void set_facet_temperatures(std::shared_ptr<const FacetTemperatures> temperatures);
    /// Bounds of instance `instance` (index into scene.instances) over the window — a moving
    /// instance's swept box; empty for an index out of range.
    Bounds instance_bounds(std::size_t instance) const noexcept;
    /// The window the scene was built for.
    const TimeWindow& window() const noexcept;
    /// Device information for provenance.
    const DeviceInfo& device() const noexcept;
    /// Total triangles over all instances (instanced triangles counted once per instance).
    std::uint64_t instanced_triangle_count() const noexcept;
    /// Time steps used by each instance (1 for static ones), indexed like scene.instances.
    const std::vector<unsigned>& time_steps() const noexcept;

private:
    struct Impl;
    explicit GeometryScene(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> m_impl;
};

}  // namespace glint::scene
