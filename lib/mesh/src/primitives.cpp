// SPDX-License-Identifier: Apache-2.0
// Tessellation of the YAML scene's primitives (ground plane, box, UV sphere, disk, cylinder)
// into triangle meshes, and the mesh validation every mesh passes before Embree sees it.
// docs/scene.md ("Primitives", "Validation") is the reference for both.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "glint/core/text.h"
#include "glint/mesh/mesh.h"

namespace glint::mesh {
namespace {

using Vec3 = std::array<double, 3>;

constexpr int kMaxSegments = 4096;

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

Vec3 to_double(const std::array<float, 3>& v) { return {v[0], v[1], v[2]}; }

/// A repeated index, or an area <= 1e-12 × the squared longest edge (validate_mesh).
bool is_degenerate(const std::vector<std::array<float, 3>>& vertices,
                   const std::array<std::uint32_t, 3>& tri) {
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) return true;
    const Vec3 p0 = to_double(vertices[tri[0]]);
    const Vec3 p1 = to_double(vertices[tri[1]]);
    const Vec3 p2 = to_double(vertices[tri[2]]);
    const Vec3 e0 = sub(p1, p0);
    const Vec3 e1 = sub(p2, p0);
    const Vec3 e2 = sub(p2, p1);
    // std::max({...}) without the initializer list's stack copy: the first largest.
    double longest = dot(e0, e0);
    if (longest < dot(e1, e1)) longest = dot(e1, e1);
    if (longest < dot(e2, e2)) longest = dot(e2, e2);
    const Vec3 n = cross(e0, e1);
    const double twice_area = std::sqrt(dot(n, n));
    return !(twice_area / 2.0 > 1e-12 * longest);
}

/// Builds a mesh one vertex and one triangle at a time.
class MeshBuilder {
public:
    explicit MeshBuilder(std::uint32_t material) : m_material(material) {}

    std::uint32_t vertex(const Vec3& p) {
        if (m_points.empty()) m_mesh.origin_m = model::mesh_origin_for(p);
        m_points.push_back(p);
        const Vec3& o = m_mesh.origin_m;
        m_mesh.vertices_m.push_back({static_cast<float>(p[0] - o[0]),
                                     static_cast<float>(p[1] - o[1]),
                                     static_cast<float>(p[2] - o[2])});
        return static_cast<std::uint32_t>(m_points.size() - 1);
    }
    /// Adds triangle (a, b, c), flipped if needed so that its normal points away from
    /// `inside` (or along `+z` when `inside` is null).
    void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c, const Vec3* inside) {
        const Vec3 normal = cross(sub(m_points[b], m_points[a]), sub(m_points[c], m_points[a]));
        const Vec3 out = inside ? sub(m_points[a], *inside) : Vec3{0.0, 0.0, 1.0};
        if (dot(normal, out) < 0.0) std::swap(b, c);
        m_mesh.triangles.push_back({a, b, c});
        m_mesh.triangle_materials.push_back(m_material);
    }
    model::Mesh take() { return std::move(m_mesh); }

private:
    std::uint32_t m_material;
    std::vector<Vec3> m_points;
    model::Mesh m_mesh;
};

bool positive(double value) { return std::isfinite(value) && value > 0.0; }
bool finite3(const Vec3& v) {
    return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

/// The largest tile of a ground plane, m: a secondary ray leaves a triangle by an offset that
/// grows with the triangle's diameter (docs/scene.md, "Spawn offset"); one pair of triangles
/// 100 km across puts it at centimetres, 1 km tiles at under a millimetre.
constexpr double kGroundTile_m = 1000.0;
/// At most this many tiles per side (a 128 km plane keeps 1 km tiles; larger ones grow them).
constexpr int kMaxGroundTilesPerSide = 128;

model::Mesh ground_plane(const model::Primitive& p, std::uint32_t material) {
    MeshBuilder b(material);
    const double h = p.size_m / 2.0;
    const Vec3& c = p.center_m;
    const int n = std::clamp(static_cast<int>(std::ceil(p.size_m / kGroundTile_m)), 1,
                             kMaxGroundTilesPerSide);
    // (n + 1)² vertices on a regular grid, two counter-clockwise triangles per tile.
    const auto at = [&](int i) { return i == n ? h : -h + p.size_m * i / n; };
    std::vector<std::uint32_t> grid;
    grid.reserve(static_cast<std::size_t>(n + 1) * static_cast<std::size_t>(n + 1));
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) grid.push_back(b.vertex({c[0] + at(i), c[1] + at(j), c[2]}));
    }
    const auto v = [&](int i, int j) { return grid[static_cast<std::size_t>(j * (n + 1) + i)]; };
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            b.triangle(v(i, j), v(i + 1, j), v(i + 1, j + 1), nullptr);
            b.triangle(v(i, j), v(i + 1, j + 1), v(i, j + 1), nullptr);
        }
    }
    return b.take();
}

model::Mesh box(const model::Primitive& p, std::uint32_t material) {
    MeshBuilder b(material);
    std::array<std::uint32_t, 8> v{};  // index bits: x, y, z (0 lower, 1 upper)
    for (int i = 0; i < 8; ++i) {
        v[i] =
            b.vertex({(i & 1) ? p.upper_m[0] : p.lower_m[0], (i & 2) ? p.upper_m[1] : p.lower_m[1],
                      (i & 4) ? p.upper_m[2] : p.lower_m[2]});
    }
    const Vec3 centre{(p.lower_m[0] + p.upper_m[0]) / 2, (p.lower_m[1] + p.upper_m[1]) / 2,
                      (p.lower_m[2] + p.upper_m[2]) / 2};
    // Faces -x, +x, -y, +y, -z, +z as quads (a, b, c, d) around their edge.
    const int quads[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                             {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
    for (const auto& q : quads) {
        b.triangle(v[q[0]], v[q[1]], v[q[2]], &centre);
        b.triangle(v[q[0]], v[q[2]], v[q[3]], &centre);
    }
    return b.take();
}

model::Mesh sphere(const model::Primitive& p, std::uint32_t material) {
    MeshBuilder b(material);
    const Vec3& c = p.center_m;
    const double r = p.radius_m;
    const int s = p.segments;
    const int rings = p.rings;
    const auto north = b.vertex({c[0], c[1], c[2] + r});
    std::vector<std::uint32_t> circle_start;
    for (int i = 1; i < rings; ++i) {
        const double theta = std::numbers::pi * i / rings;
        circle_start.push_back(static_cast<std::uint32_t>(north + 1 + (i - 1) * s));
        for (int j = 0; j < s; ++j) {
            const double phi = 2.0 * std::numbers::pi * j / s;
            b.vertex({c[0] + r * std::sin(theta) * std::cos(phi),
                      c[1] + r * std::sin(theta) * std::sin(phi), c[2] + r * std::cos(theta)});
        }
    }
    const auto south = b.vertex({c[0], c[1], c[2] - r});
    const auto at = [&](int circle, int j) {
        return circle_start[circle] + static_cast<std::uint32_t>(j % s);
    };
    for (int j = 0; j < s; ++j) b.triangle(north, at(0, j), at(0, j + 1), &c);
    for (int i = 0; i + 1 < rings - 1; ++i) {
        for (int j = 0; j < s; ++j) {
            b.triangle(at(i, j), at(i + 1, j), at(i + 1, j + 1), &c);
            b.triangle(at(i, j), at(i + 1, j + 1), at(i, j + 1), &c);
        }
    }
    for (int j = 0; j < s; ++j) b.triangle(south, at(rings - 2, j), at(rings - 2, j + 1), &c);
    return b.take();
}

/// A ring of `s` vertices of radius `r` about `c` in the plane z = c.z; returns the first.
std::uint32_t circle(MeshBuilder& b, const Vec3& c, double r, int s) {
    std::uint32_t first = 0;
    for (int j = 0; j < s; ++j) {
        const double phi = 2.0 * std::numbers::pi * j / s;
        const auto v = b.vertex({c[0] + r * std::cos(phi), c[1] + r * std::sin(phi), c[2]});
        if (j == 0) first = v;
    }
    return first;
}

model::Mesh disk(const model::Primitive& p, std::uint32_t material) {
    MeshBuilder b(material);
    const auto centre = b.vertex(p.center_m);
    const auto rim = circle(b, p.center_m, p.radius_m, p.segments);
    const auto s = static_cast<std::uint32_t>(p.segments);
    for (std::uint32_t j = 0; j < s; ++j) b.triangle(centre, rim + j, rim + (j + 1) % s, nullptr);
    return b.take();
}

model::Mesh cylinder(const model::Primitive& p, std::uint32_t material) {
    MeshBuilder b(material);
    const Vec3& c = p.center_m;
    const Vec3 top{c[0], c[1], c[2] + p.height_m};
    const Vec3 middle{c[0], c[1], c[2] + p.height_m / 2.0};
    const auto s = static_cast<std::uint32_t>(p.segments);
    const auto lower = circle(b, c, p.radius_m, p.segments);
    const auto upper = circle(b, top, p.radius_m, p.segments);
    for (std::uint32_t j = 0; j < s; ++j) {
        const std::uint32_t k = (j + 1) % s;
        // Outward from the axis point at the same height as the face's first vertex.
        const Vec3 axis_low = c;
        const Vec3 axis_high = top;
        b.triangle(lower + j, lower + k, upper + k, &axis_low);
        b.triangle(upper + k, upper + j, lower + j, &axis_high);
    }
    if (p.caps) {
        const auto bottom_centre = b.vertex(c);
        const auto top_centre = b.vertex(top);
        for (std::uint32_t j = 0; j < s; ++j) {
            const std::uint32_t k = (j + 1) % s;
            b.triangle(bottom_centre, lower + j, lower + k, &middle);
            b.triangle(top_centre, upper + j, upper + k, &middle);
        }
    }
    return b.take();
}

/// "1 vertex", "3 vertices", "2 triangles".
std::string count_text(std::size_t n, const std::string& what) {
    if (n == 1) return "1 " + what;
    return std::to_string(n) + " " + (what == "vertex" ? std::string("vertices") : what + "s");
}

}  // namespace

model::Mesh tessellate_primitive(const model::Primitive& p, std::uint32_t material,
                                 const ErrorContext& where, Diagnostics& diagnostics) {
    const std::size_t errors = diagnostics.error_count();
    using Kind = model::PrimitiveKind;
    if (!finite3(p.center_m)) diagnostics.error(where, "center must be finite");
    if (p.kind == Kind::ground_plane && !positive(p.size_m)) {
        diagnostics.error(where, "ground plane size must be a number > 0");
    }
    if (p.kind == Kind::box) {
        if (!finite3(p.lower_m) || !finite3(p.upper_m)) {
            diagnostics.error(where, "box corners must be finite");
        } else {
            for (int axis = 0; axis < 3; ++axis) {
                if (!(p.lower_m[axis] < p.upper_m[axis])) {
                    diagnostics.error(where, std::string("box lower ") + "xyz"[axis] + " " +
                                                 format_shortest(p.lower_m[axis]) +
                                                 " is not below upper " +
                                                 format_shortest(p.upper_m[axis]));
                }
            }
        }
    }
    if (p.kind == Kind::sphere || p.kind == Kind::disk || p.kind == Kind::cylinder) {
        if (!positive(p.radius_m)) diagnostics.error(where, "radius must be a number > 0");
        if (p.segments < 3 || p.segments > kMaxSegments) {
            diagnostics.error(where, "segments must be an integer in [3, 4096]");
        }
    }
    if (p.kind == Kind::sphere && (p.rings < 2 || p.rings > kMaxSegments)) {
        diagnostics.error(where, "rings must be an integer in [2, 4096]");
    }
    if (p.kind == Kind::cylinder && !positive(p.height_m)) {
        diagnostics.error(where, "height must be a number > 0");
    }
    if (diagnostics.error_count() != errors) return {};
    switch (p.kind) {
        case Kind::ground_plane:
            return ground_plane(p, material);
        case Kind::box:
            return box(p, material);
        case Kind::sphere:
            return sphere(p, material);
        case Kind::disk:
            return disk(p, material);
        case Kind::cylinder:
            return cylinder(p, material);
    }
    return {};
}

bool validate_mesh(model::Mesh& mesh, std::size_t material_count, const ErrorContext& where,
                   Diagnostics& diagnostics) {
    const std::size_t errors = diagnostics.error_count();
    for (std::size_t i = 0; i < mesh.vertices_m.size(); ++i) {
        const auto& v = mesh.vertices_m[i];
        if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) {
            diagnostics.error(where, "vertex " + std::to_string(i) + " is not finite");
        }
    }
    if (mesh.triangle_materials.size() != mesh.triangles.size()) {
        diagnostics.error(where, "mesh has " + count_text(mesh.triangles.size(), "triangle") +
                                     " but " +
                                     count_text(mesh.triangle_materials.size(), "material") +
                                     " (one per triangle expected)");
        return false;
    }
    if (!mesh.triangle_uvs.empty() && mesh.triangle_uvs.size() != mesh.triangles.size()) {
        diagnostics.error(where, "mesh has " + count_text(mesh.triangles.size(), "triangle") +
                                     " but " +
                                     count_text(mesh.triangle_uvs.size(), "texture triangle") +
                                     " (one per triangle expected)");
        return false;
    }
    const std::size_t n_vertices = mesh.vertices_m.size();
    std::size_t degenerate = 0;
    std::size_t kept = 0;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        bool bad = false;
        for (const std::uint32_t index : tri) {
            if (index >= n_vertices) {
                diagnostics.error(where, "triangle " + std::to_string(t) + ": vertex index " +
                                             std::to_string(index) + " is out of range (" +
                                             count_text(n_vertices, "vertex") + ")");
                bad = true;
            }
        }
        if (mesh.triangle_materials[t] >= material_count) {
            diagnostics.error(where, "triangle " + std::to_string(t) + ": material index " +
                                         std::to_string(mesh.triangle_materials[t]) +
                                         " is out of range (" +
                                         count_text(material_count, "material") + ")");
            bad = true;
        }
        if (bad) continue;
        if (is_degenerate(mesh.vertices_m, tri)) {
            ++degenerate;
            continue;
        }
        mesh.triangles[kept] = tri;
        mesh.triangle_materials[kept] = mesh.triangle_materials[t];
        if (!mesh.triangle_uvs.empty()) mesh.triangle_uvs[kept] = mesh.triangle_uvs[t];
        ++kept;
    }
    if (diagnostics.error_count() != errors) return false;
    mesh.triangles.resize(kept);
    mesh.triangle_materials.resize(kept);
    if (!mesh.triangle_uvs.empty()) mesh.triangle_uvs.resize(kept);
    if (degenerate > 0) {
        diagnostics.warning(where, "dropped " + count_text(degenerate, "degenerate triangle"));
    }
    if (mesh.triangles.empty()) {
        diagnostics.error(where, "mesh has no triangles");
        return false;
    }
    return true;
}

}  // namespace glint::mesh
