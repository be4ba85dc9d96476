// SPDX-License-Identifier: Apache-2.0
// Object scenes: the mesh checks, the Embree triangle geometry (vertex and index buffers
// allocated by Embree, so they are padded as its SSE loads need and counted by the memory
// monitor; vertices relative to the mesh's centre), the robust high-quality BVH, and the
// object's bounds and extent.
#include "object_scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>

#include "glint/core/error.h"

namespace glint::scene::detail {

static_assert(sizeof(std::array<std::uint32_t, 3>) == 3 * sizeof(std::uint32_t),
              "triangles are copied as a block");

void check_mesh(const model::GeometryObject& object, std::size_t material_count) {
    const model::Mesh& mesh = object.mesh;
    const std::string name = "object \"" + object.name + "\"";
    if (mesh.triangles.empty()) throw input_error(name + ": mesh has no triangles", object.where);
    if (mesh.triangle_materials.size() != mesh.triangles.size()) {
        throw input_error(name + ": mesh has " + std::to_string(mesh.triangles.size()) +
                              " triangles but " + std::to_string(mesh.triangle_materials.size()) +
                              " triangle materials",
                          object.where);
    }
    for (const auto& v : mesh.vertices_m) {
        if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) {
            throw input_error(name + ": mesh has a vertex that is not finite", object.where);
        }
    }
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        for (const std::uint32_t index : mesh.triangles[t]) {
            if (index >= mesh.vertices_m.size()) {
                throw input_error(name + ": triangle " + std::to_string(t) + " has vertex index " +
                                      std::to_string(index) + ", out of range (" +
                                      std::to_string(mesh.vertices_m.size()) + " vertices)",
                                  object.where);
            }
        }
        if (mesh.triangle_materials[t] >= material_count) {
            throw input_error(name + ": triangle " + std::to_string(t) + " has material index " +
                                  std::to_string(mesh.triangle_materials[t]) + ", out of range (" +
                                  std::to_string(material_count) + " materials)",
                              object.where);
        }
    }
}

namespace {

Vec3 buffer_vertex(const float* vertices, std::uint32_t index) {
    const float* v = vertices + 3 * static_cast<std::size_t>(index);
    return {v[0], v[1], v[2]};
}

/// The plane of the triangle `corners` of the (relative, float) vertex buffer.
TrianglePlane triangle_plane(const float* vertices, const std::array<std::uint32_t, 3>& corners) {
    const Vec3 v0 = buffer_vertex(vertices, corners[0]);
    const Vec3 v1 = buffer_vertex(vertices, corners[1]);
    const Vec3 v2 = buffer_vertex(vertices, corners[2]);
    TrianglePlane plane;
    const Vec3 n = cross(v1 - v0, v2 - v0);
    const double length = norm(n);
    if (length > 0.0 && std::isfinite(length)) {
        for (std::size_t k = 0; k < 3; ++k) plane.normal[k] = static_cast<float>(n[k] / length);
    }
    // Through v0 with the normal as stored (float), so the plane is exactly the one a hit uses.
    plane.offset_m = plane.normal[0] * v0.x + plane.normal[1] * v0.y + plane.normal[2] * v0.z;
    double diameter = 0.0;
    for (const Vec3& e : {v1 - v0, v2 - v0, v2 - v1}) {
        diameter = std::max({diameter, std::abs(e.x), std::abs(e.y), std::abs(e.z)});
    }
    plane.diameter_m = std::nextafter(static_cast<float>(diameter), INFINITY);
    return plane;
}

}  // namespace

ObjectData build_object_scene(EmbreeDevice& device, const model::GeometryObject& object) {
    const model::Mesh& mesh = object.mesh;
    const std::string what = "building object \"" + object.name + "\"";
    ObjectData data;
    GeometryPtr geometry = device.new_geometry(RTC_GEOMETRY_TYPE_TRIANGLE, what);

    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry.get(), RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                3 * sizeof(float), mesh.vertices_m.size()));
    device.check(what);
    if (!vertices) throw runtime_error("Embree failed while " + what + ": no vertex buffer");
    const Bounds box = mesh_bounds(mesh);
    // A float centre: a moving instance hands it to Embree as its decomposition's shift.
    const Vec3 center = (box.lower + box.upper) * 0.5;
    data.center_m = {static_cast<float>(center.x), static_cast<float>(center.y),
                     static_cast<float>(center.z)};
    const Vec3 shift = motion::to_vec3(mesh.origin_m) - data.center_m;
    for (std::size_t i = 0; i < mesh.vertices_m.size(); ++i) {
        const auto& v = mesh.vertices_m[i];
        for (std::size_t k = 0; k < 3; ++k) {
            vertices[3 * i + k] = static_cast<float>(static_cast<double>(v[k]) + shift[k]);
        }
    }
    data.vertices = vertices;

    auto* triangles = static_cast<std::uint32_t*>(
        rtcSetNewGeometryBuffer(geometry.get(), RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(std::uint32_t), mesh.triangles.size()));
    device.check(what);
    if (!triangles) throw runtime_error("Embree failed while " + what + ": no index buffer");
    std::memcpy(triangles, mesh.triangles.data(),
                mesh.triangles.size() * 3 * sizeof(std::uint32_t));
    data.triangles = triangles;
    data.planes.resize(mesh.triangles.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        data.planes[t] = triangle_plane(vertices, mesh.triangles[t]);
    }

    rtcCommitGeometry(geometry.get());
    device.check(what);

    data.scene = device.new_scene(RTC_SCENE_FLAG_ROBUST, RTC_BUILD_QUALITY_HIGH, what);
    rtcAttachGeometryByID(data.scene.get(), geometry.get(), 0);
    device.check(what);
    rtcCommitScene(data.scene.get());
    device.check(what);

    // The scene holds a reference to the geometry, which owns the buffers.
    // An object of one material (a terrain, most OBJ parts) keeps no per-triangle list: a hit
    // then needs no lookup (a cache miss on a large mesh).
    const auto& m = mesh.triangle_materials;
    if (!m.empty() && std::all_of(m.begin(), m.end(), [&](std::uint32_t v) { return v == m[0]; })) {
        data.single_material = m[0];
    } else {
        data.materials = m;
    }
    data.triangle_count = mesh.triangles.size();
    return data;
}

Bounds mesh_bounds(const model::Mesh& mesh) noexcept {
    Bounds box = empty_bounds();
    const Vec3 origin = motion::to_vec3(mesh.origin_m);
    for (const auto& v : mesh.vertices_m) {
        const Vec3 p = origin + Vec3{v[0], v[1], v[2]};
        expand(box, {p, p});
    }
    return box;
}

ObjectExtent mesh_extent(const model::Mesh& mesh) noexcept {
    ObjectExtent extent;
    const Bounds box = mesh_bounds(mesh);
    if (!box.empty()) extent.diagonal_m = norm(box.upper - box.lower);
    const Vec3 origin = motion::to_vec3(mesh.origin_m);
    for (const auto& v : mesh.vertices_m) {
        extent.radius_m = std::max(extent.radius_m, norm(origin + Vec3{v[0], v[1], v[2]}));
    }
    return extent;
}

}  // namespace glint::scene::detail
