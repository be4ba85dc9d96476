// SPDX-License-Identifier: Apache-2.0
// Ray queries on a built GeometryScene. A double-precision ray is first clipped to the
// enlarged scene box (slab test in double); a ray that misses the box never reaches Embree.
// Otherwise its origin moves to where the wanted interval starts inside the box (the box
// entry, or tmin when that is later) and into Embree's frame (less the scene's anchor), which
// keeps the single-precision trace short and its coordinates at the scene's own size. A hit
// is then rebuilt in double from Embree's triangle and barycentrics, not from its float
// distance: the position lies on the triangle whatever the distance the ray ran, the normal
// is the triangle's, and the spawn offset is a bound on the float error a ray leaving it
// meets (docs/scene.md, "Hit points and the spawn offset").
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "geometry_scene_impl.h"
#include "glint/core/error.h"

namespace glint::scene {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// A caller's ray as Embree traces it.
struct ClippedRay {
    float origin[3] = {0.0f, 0.0f, 0.0f};
    float direction[3] = {0.0f, 0.0f, 0.0f};
    float tnear = 0.0f;
    float tfar = 0.0f;
};

/// The ray origin + s · direction, s in [from, to], as Embree traces it: from `from` on, in
/// Embree's frame (scene ENU less `anchor_m`).
void set_clipped(const Vec3& origin, const Vec3& direction, double from, double to,
                 const Vec3& anchor_m, ClippedRay& ray) noexcept {
    const Vec3 start = (origin - anchor_m) + direction * from;
    for (std::size_t i = 0; i < 3; ++i) {
        ray.origin[i] = static_cast<float>(start[i]);
        ray.direction[i] = static_cast<float>(direction[i]);
    }
    ray.tnear = 0.0f;
    ray.tfar = static_cast<float>(to - from);
}

/// The part of origin + s · direction, s in (tmin, tmax), inside `box`, into `out`; false
/// (and `out` unspecified) when empty. Written in place: returning the 40-byte ray by value
/// cost a block copy per ray.
bool clip(const Bounds& box, const Vec3& anchor_m, const Vec3& origin, const Vec3& direction,
          double tmin_m, double tmax_m, ClippedRay& out) noexcept {
    if (box.empty() || !(tmin_m < tmax_m)) return false;
    // A ray Embree could not trace sensibly (NaN, infinite or zero) hits nothing.
    const double span = dot(direction, direction);
    if (!(span > 0.0) || !std::isfinite(span) || !std::isfinite(dot(origin, origin))) {
        return false;
    }
    // An origin inside the box (every bounce and shadow ray) needs no slab test: the interval
    // starts at tmin (the box entry is behind it) and everything it can hit lies before the
    // box exit, so Embree may as well search up to tmax.
    if (tmin_m >= 0.0 && std::isfinite(tmin_m) && origin.x >= box.lower.x &&
        origin.x <= box.upper.x && origin.y >= box.lower.y && origin.y <= box.upper.y &&
        origin.z >= box.lower.z && origin.z <= box.upper.z) {
        set_clipped(origin, direction, tmin_m, tmax_m, anchor_m, out);
        return true;
    }
    double enter = -kInfinity;
    double leave = kInfinity;
    for (std::size_t i = 0; i < 3; ++i) {
        if (direction[i] == 0.0) {
            if (!(origin[i] >= box.lower[i] && origin[i] <= box.upper[i])) return false;
            continue;
        }
        const double inverse = 1.0 / direction[i];
        double a = (box.lower[i] - origin[i]) * inverse;
        double b = (box.upper[i] - origin[i]) * inverse;
        if (a > b) std::swap(a, b);
        enter = std::max(enter, a);
        leave = std::min(leave, b);
    }
    const double from = std::max(tmin_m, enter);
    const double to = std::min(tmax_m, leave);
    if (!(from <= to) || !std::isfinite(from)) return false;
    set_clipped(origin, direction, from, to, anchor_m, out);
    return true;
}

void fill(RTCRay& out, const ClippedRay& ray, float time01) noexcept {
    out.org_x = ray.origin[0];
    out.org_y = ray.origin[1];
    out.org_z = ray.origin[2];
    out.dir_x = ray.direction[0];
    out.dir_y = ray.direction[1];
    out.dir_z = ray.direction[2];
    out.tnear = ray.tnear;
    out.tfar = ray.tfar;
    out.time = time01;
    out.mask = 0xFFFFFFFFu;
    out.id = 0;
    out.flags = 0;
}

/// `time_s` clamped into the window and mapped to Embree's [0, 1].
float ray_time(const TimeWindow& window, double time_s) noexcept {
    const double length_s = window.end_s - window.begin_s;
    if (!(length_s > 0.0) || !(time_s > window.begin_s)) return 0.0f;
    if (!(time_s < window.end_s)) return 1.0f;
    return static_cast<float>((time_s - window.begin_s) / length_s);
}

/// The spawn offset per unit of the magnitudes Embree's numbers carry near a hit: 4 float
/// ulps (2⁻²²), 8 times the smallest factor with which the scene's precision tests pass
/// (docs/scene.md, "Spawn offset").
constexpr double kSpawnRelative = 0x1p-22;
/// A floor for a hit whose magnitudes are all near zero, m.
constexpr double kSpawnFloor_m = 1e-9;

Vec3 vertex(const float* vertices, std::uint32_t index) noexcept {
    const float* v = vertices + 3 * static_cast<std::size_t>(index);
    return {v[0], v[1], v[2]};
}

double largest_abs(const Vec3& v) noexcept {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

/// The largest absolute row sum of `m` (its ∞-norm: how much it can stretch a vector's
/// largest coordinate).
double row_norm(const detail::Mat3& m) noexcept {
    double out = 0.0;
    for (std::size_t i = 0; i < 3; ++i) {
        out = std::max(out, std::abs(m(i, 0)) + std::abs(m(i, 1)) + std::abs(m(i, 2)));
    }
    return out;
}

/// The |n_z| below which a facet is too steep for a drape's bump slope (about 87° tilt).
constexpr double kBumpMinimumNz = 0.05;

/// The property maps at `hit` (Embree's barycentrics u, v on its triangle).
void apply_maps(const SurfaceMaps& maps, const detail::ObjectData& object, float u, float v,
                RayHit& hit) noexcept {
    MapPoint point{hit.position_m.x, hit.position_m.y, std::nullopt};
    if (!object.uvs.empty()) {
        const std::array<float, 6>& c = object.uvs[hit.triangle];
        const double b0 = 1.0 - double{u} - double{v};
        const double uu = b0 * c[0] + u * double{c[2]} + v * double{c[4]};
        const double vv = b0 * c[1] + u * double{c[3]} + v * double{c[5]};
        if (std::isfinite(uu) && std::isfinite(vv)) point.uv = std::array<double, 2>{uu, vv};
    }
    const SurfaceMaps::Applied applied = maps.apply(point, hit.material);
    hit.material = applied.material;
    hit.mixture_map = applied.mixture_map;
    hit.mixture_texel = applied.mixture_texel;
    hit.temperature_k = applied.temperature_k;
    // A bump map's slope tilts the normal as the height field z = h(x, y) tilts a level one:
    // n' ∝ n − g_t, g = (∂h/∂x, ∂h/∂y, 0) less its part along n. A drape's slope means
    // nothing on a near-vertical facet, which keeps its normal.
    if (applied.bumped && std::abs(hit.normal.z) > kBumpMinimumNz) {
        const Vec3 g{applied.slope_x, applied.slope_y, 0.0};
        const Vec3 tilted = hit.normal - (g - dot(g, hit.normal) * hit.normal);
        hit.bumped = true;
        hit.shading_normal = normalized(tilted);
    }
}

/// The hit Embree reported on the caller's ray origin_m + s · direction: Embree's instance,
/// triangle and barycentrics (u, v). The triangle's plane (computed in double from its float
/// vertices at build) is taken to Embree's frame through the instance's map as Embree holds
/// it; the position is where the caller's double ray crosses that plane, so it lies on
/// Embree's surface to double rounding whatever the distance the float ray ran. The normal is
/// the plane's, in scene ENU. The spawn offset bounds the float error of a ray leaving the hit
/// (docs/scene.md, "Hit points").
template <class SceneImpl>
void make_hit(const SceneImpl& impl, const Vec3& origin_m, const Vec3& direction, float time01,
              double time_s, std::uint32_t instance_id, std::uint32_t triangle, float u, float v,
              RayHit& hit) {
    const std::vector<detail::InstanceData>& instances = impl.instances;
    const std::vector<detail::ObjectData>& objects = impl.objects;
    const Vec3& anchor_m = impl.anchor_m;
    hit.instance = instance_id;
    hit.triangle = triangle;
    const detail::InstanceData& instance = instances[hit.instance];
    const detail::ObjectData& object = objects[instance.object];
    hit.material =
        object.materials.empty() ? object.single_material : object.materials[hit.triangle];

    detail::Affine to_frame = instance.to_frame;
    detail::Mat3 normal_matrix = instance.normal_matrix;
    if (instance.moving) {
        float xfm[12];
        rtcGetGeometryTransform(instance.geometry, time01, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
        to_frame = detail::from_float3x4(xfm);
        normal_matrix = detail::inverse_transpose(to_frame.linear);
    }
    const detail::TrianglePlane& plane = object.planes[triangle];
    // p = A q + T with normal · q = offset: (A⁻ᵀ normal) · (p − T) = offset.
    const Vec3 normal = normal_matrix * Vec3{plane.normal[0], plane.normal[1], plane.normal[2]};
    hit.normal = normalized(normal);
    const Vec3 start = origin_m - anchor_m;
    const double along = dot(normal, direction);
    const double t = (plane.offset_m + dot(normal, to_frame.translation_m - start)) / along;
    Vec3 in_frame;
    if (along != 0.0 && std::isfinite(t)) {
        in_frame = start + direction * t;
    } else {
        // A ray in the plane: the barycentric point, in the plane too (as good in it as
        // Embree's float u, v).
        const std::uint32_t* corners = object.triangles + 3 * static_cast<std::size_t>(triangle);
        const Vec3 v0 = vertex(object.vertices, corners[0]);
        const Vec3 e1 = vertex(object.vertices, corners[1]) - v0;
        const Vec3 e2 = vertex(object.vertices, corners[2]) - v0;
        in_frame = to_frame.apply(v0 + e1 * static_cast<double>(u) + e2 * static_cast<double>(v));
    }
    hit.position_m = in_frame + anchor_m;
    hit.distance_m = dot(hit.position_m - origin_m, direction);

    const double frame_size = largest_abs(in_frame) + largest_abs(to_frame.translation_m);
    const double triangle_size = plane.diameter_m * row_norm(to_frame.linear);
    hit.spawn_offset_m = kSpawnFloor_m + kSpawnRelative * (frame_size + 2.0 * triangle_size);
    hit.mixture_map = kNoMixture;
    hit.temperature_k = 0.0;
    hit.bumped = false;
    if (impl.maps.maps_material(hit.material)) apply_maps(impl.maps, object, u, v, hit);
    if (impl.facet_temperatures && hit.temperature_k == 0.0) {
        hit.temperature_k = impl.facet_temperatures->at(hit.instance, hit.triangle, u, v, time_s);
    }
}

/// Embree's packet of kPacketSize rays, 64-byte aligned as rtcIntersect16 requires, with
/// each lane's time.
struct alignas(64) Packet {
    alignas(64) int valid[kPacketSize];
    RTCRayHit16 rayhit;
    float time01[kPacketSize] = {};

    /// Loads `rays`, each clipped to `box` (a ray that misses it leaves its lane inactive);
    /// returns whether any lane is active.
    bool load(const Bounds& box, const Vec3& anchor_m, const TimeWindow& window,
              std::span<const PacketRay> rays) noexcept;
};
static_assert(kPacketSize == 16, "the packet queries use Embree's 16-wide calls");

void fill_lane(RTCRay16& out, std::size_t k, const ClippedRay& ray, float time01) noexcept {
    out.org_x[k] = ray.origin[0];
    out.org_y[k] = ray.origin[1];
    out.org_z[k] = ray.origin[2];
    out.dir_x[k] = ray.direction[0];
    out.dir_y[k] = ray.direction[1];
    out.dir_z[k] = ray.direction[2];
    out.tnear[k] = ray.tnear;
    out.tfar[k] = ray.tfar;
    out.time[k] = time01;
    out.mask[k] = 0xFFFFFFFFu;
    out.id[k] = 0;
    out.flags[k] = 0;
}

/// An inactive lane: a finite ray with an empty interval (Embree reads every lane's numbers,
/// whatever the valid mask says).
void fill_inactive_lane(RTCRay16& out, std::size_t k) noexcept {
    ClippedRay idle;
    idle.direction[2] = 1.0f;
    idle.tfar = -std::numeric_limits<float>::infinity();
    fill_lane(out, k, idle, 0.0f);
}

bool Packet::load(const Bounds& box, const Vec3& anchor_m, const TimeWindow& window,
                  std::span<const PacketRay> rays) noexcept {
    bool any = false;
    for (std::size_t k = 0; k < kPacketSize; ++k) {
        valid[k] = 0;
        rayhit.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
        rayhit.hit.primID[k] = RTC_INVALID_GEOMETRY_ID;
        rayhit.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
        fill_inactive_lane(rayhit.ray, k);
        if (k >= rays.size()) continue;
        const PacketRay& ray = rays[k];
        ClippedRay clipped;
        if (!clip(box, anchor_m, ray.origin_m, ray.direction, ray.tmin_m, ray.tmax_m, clipped)) {
            continue;
        }
        time01[k] = ray_time(window, ray.time_s);
        fill_lane(rayhit.ray, k, clipped, time01[k]);
        valid[k] = -1;
        any = true;
    }
    return any;
}

/// A packet query on a scene with moving instances: each ray answered alone. Embree's packet
/// kernels interpolate moving instances with other roundings than its single-ray kernel, so
/// this keeps the packet queries' bits those of the single queries.
template <typename Answer, typename Single>
void one_by_one(std::span<const PacketRay> rays, std::span<Answer> out, const Single& single) {
    for (std::size_t k = 0; k < rays.size(); ++k) out[k] = single(rays[k]);
}

void check_packet(std::size_t rays, std::size_t results) {
    if (rays > kPacketSize || results != rays) {
        throw internal_error("packet query of " + std::to_string(rays) + " rays into " +
                             std::to_string(results) + " results (at most " +
                             std::to_string(kPacketSize) + ")");
    }
}

}  // namespace

std::optional<RayHit> GeometryScene::intersect(const Vec3& origin_m, const Vec3& direction,
                                               double time_s, double tmin_m, double tmax_m) const {
    RayHit hit;
    if (!intersect_into(origin_m, direction, time_s, hit, tmin_m, tmax_m)) return std::nullopt;
    return hit;
}

bool GeometryScene::intersect_into(const Vec3& origin_m, const Vec3& direction, double time_s,
                                   RayHit& hit, double tmin_m, double tmax_m) const {
    const Impl& impl = *m_impl;
    ClippedRay clipped;
    if (!clip(impl.clip_bounds, impl.anchor_m, origin_m, direction, tmin_m, tmax_m, clipped)) {
        return false;
    }
    const float time01 = ray_time(impl.window, time_s);

    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rayhit;
    fill(rayhit.ray, clipped, time01);
    rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(impl.top.get(), &context, &rayhit);
    if (rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    make_hit(impl, origin_m, direction, time01, time_s, rayhit.hit.instID[0], rayhit.hit.primID,
             rayhit.hit.u, rayhit.hit.v, hit);
    return true;
}

void GeometryScene::intersect_packet(std::span<const PacketRay> rays,
                                     std::span<std::optional<RayHit>> hits) const {
    check_packet(rays.size(), hits.size());
    const Impl& impl = *m_impl;
    if (impl.any_moving) {
        one_by_one(rays, hits, [this](const PacketRay& r) {
            return intersect(r.origin_m, r.direction, r.time_s, r.tmin_m, r.tmax_m);
        });
        return;
    }
    Packet packet;
    const bool any = packet.load(impl.clip_bounds, impl.anchor_m, impl.window, rays);
    if (any) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        // Not RTC_INTERSECT_CONTEXT_FLAG_COHERENT: Embree 3.13.5's coherent packet kernels
        // never returned from rtcOccluded16 on shadow rays with an infinite tfar here.
        rtcIntersect16(packet.valid, impl.top.get(), &context, &packet.rayhit);
    }
    for (std::size_t k = 0; k < rays.size(); ++k) {
        const RTCHit16& hit = packet.rayhit.hit;
        if (packet.valid[k] == 0 || hit.geomID[k] == RTC_INVALID_GEOMETRY_ID) {
            hits[k].reset();
            continue;
        }
        make_hit(impl, rays[k].origin_m, rays[k].direction, packet.time01[k], rays[k].time_s,
                 hit.instID[0][k], hit.primID[k], hit.u[k], hit.v[k], hits[k].emplace());
    }
}

void GeometryScene::occluded_packet(std::span<const PacketRay> rays,
                                    std::span<bool> blocked) const {
    check_packet(rays.size(), blocked.size());
    const Impl& impl = *m_impl;
    if (impl.any_moving) {
        one_by_one(rays, blocked, [this](const PacketRay& r) {
            return occluded(r.origin_m, r.direction, r.time_s, r.tmin_m, r.tmax_m);
        });
        return;
    }
    Packet packet;
    const bool any = packet.load(impl.clip_bounds, impl.anchor_m, impl.window, rays);
    if (any) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        rtcOccluded16(packet.valid, impl.top.get(), &context, &packet.rayhit.ray);
    }
    for (std::size_t k = 0; k < rays.size(); ++k) {
        blocked[k] = packet.valid[k] != 0 && packet.rayhit.ray.tfar[k] < 0.0f;
    }
}

bool GeometryScene::occluded(const Vec3& origin_m, const Vec3& direction, double time_s,
                             double tmin_m, double tmax_m) const {
    const Impl& impl = *m_impl;
    ClippedRay clipped;
    if (!clip(impl.clip_bounds, impl.anchor_m, origin_m, direction, tmin_m, tmax_m, clipped)) {
        return false;
    }
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray;
    fill(ray, clipped, ray_time(impl.window, time_s));
    rtcOccluded1(impl.top.get(), &context, &ray);
    return ray.tfar < 0.0f;  // Embree sets tfar to −inf on a hit
}

Vec3 GeometryScene::spawn_origin(const RayHit& hit, const Vec3& direction) const noexcept {
    const double side = dot(direction, hit.normal) >= 0.0 ? 1.0 : -1.0;
    return hit.position_m + hit.normal * (side * hit.spawn_offset_m);
}

std::vector<GeometryScene::Facet> GeometryScene::static_facets(
    const std::function<bool(std::uint32_t)>& wanted) const {
    const Impl& impl = *m_impl;
    std::vector<Facet> out;
    for (std::size_t i = 0; i < impl.instances.size(); ++i) {
        const detail::InstanceData& instance = impl.instances[i];
        if (instance.moving || instance.absent) continue;
        const detail::ObjectData& object = impl.objects[instance.object];
        for (std::uint64_t t = 0; t < object.triangle_count; ++t) {
            const auto triangle = static_cast<std::uint32_t>(t);
            const std::uint32_t material =
                object.materials.empty() ? object.single_material : object.materials[triangle];
            if (!wanted(material)) continue;
            const std::uint32_t* corners = object.triangles + 3 * static_cast<std::size_t>(t);
            const Vec3 v0 = instance.to_frame.apply(vertex(object.vertices, corners[0]));
            const Vec3 v1 = instance.to_frame.apply(vertex(object.vertices, corners[1]));
            const Vec3 v2 = instance.to_frame.apply(vertex(object.vertices, corners[2]));
            const Vec3 in_frame = (v0 + v1 + v2) * (1.0 / 3.0);
            const detail::TrianglePlane& plane = object.planes[triangle];
            const Vec3 n =
                instance.normal_matrix * Vec3{plane.normal[0], plane.normal[1], plane.normal[2]};
            Facet f;
            f.instance = static_cast<std::uint32_t>(i);
            f.triangle = triangle;
            f.material = material;
            f.centroid_m = in_frame + impl.anchor_m;
            f.corners_m = {v0 + impl.anchor_m, v1 + impl.anchor_m, v2 + impl.anchor_m};
            f.normal = dot(n, n) > 0.0 ? normalized(n) : Vec3{};
            f.spawn_offset_m =
                kSpawnFloor_m +
                kSpawnRelative *
                    (largest_abs(in_frame) + largest_abs(instance.to_frame.translation_m) +
                     2.0 * plane.diameter_m * row_norm(instance.to_frame.linear));
            out.push_back(f);
        }
    }
    return out;
}

void GeometryScene::set_facet_temperatures(std::shared_ptr<const FacetTemperatures> temperatures) {
    m_impl->facet_temperatures = std::move(temperatures);
}

}  // namespace glint::scene
