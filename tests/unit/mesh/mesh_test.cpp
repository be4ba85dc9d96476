// SPDX-License-Identifier: Apache-2.0
// Tests of mesh building: the triangle counts, bounds and orientation of every primitive, bad
// primitive parameters, and the mesh validation (degenerate triangles dropped, errors).
#include "glint/mesh/mesh.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "glint/test/mesh_checks.h"

namespace glint::mesh {
namespace mesh_test {

using test::Bounds;
using test::bounds_of;
using test::expect_outward;
using ::testing::HasSubstr;
using Severity = Diagnostic::Severity;

std::string dump(const Diagnostics& diagnostics) {
    std::string out;
    for (const Diagnostic& d : diagnostics.items()) {
        out += (d.severity == Severity::error ? "error: " : "warning: ") + d.text() + "\n";
    }
    return out;
}

// ---- primitives -----------------------------------------------------------------------------

model::Mesh tessellate(const model::Primitive& p) {
    Diagnostics diagnostics;
    model::Mesh mesh = tessellate_primitive(p, 0, {}, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors()) << dump(diagnostics);
    EXPECT_TRUE(validate_mesh(mesh, 1, {}, diagnostics)) << dump(diagnostics);
    EXPECT_EQ(diagnostics.items().size(), 0u) << dump(diagnostics);
    return mesh;
}

TEST(MeshPrimitives, GroundPlane) {
    model::Primitive p;
    p.kind = model::PrimitiveKind::ground_plane;
    p.center_m = {1, 2, 3};
    const model::Mesh mesh = tessellate(p);
    // The default 100 km plane in 1 km tiles of two triangles (docs/scene.md, "Spawn offset").
    EXPECT_EQ(mesh.triangles.size(), 2u * 100u * 100u);
    EXPECT_EQ(mesh.vertices_m.size(), 101u * 101u);
    const Bounds b = bounds_of(mesh);
    EXPECT_FLOAT_EQ(b.lo[0], 1.0f - 50'000.0f);
    EXPECT_FLOAT_EQ(b.hi[1], 2.0f + 50'000.0f);
    EXPECT_FLOAT_EQ(b.lo[2], 3.0f);
    EXPECT_FLOAT_EQ(b.hi[2], 3.0f);
    expect_outward(mesh, {1, 2, 2});  // faces +z
    // A plane up to 1 km is one tile; one beyond 128 km keeps 128 tiles a side.
    p.size_m = 800.0;
    EXPECT_EQ(tessellate(p).triangles.size(), 2u);
    p.size_m = 1e6;
    EXPECT_EQ(tessellate(p).triangles.size(), 2u * 128u * 128u);
}

TEST(MeshPrimitives, Box) {
    model::Primitive p;
    p.kind = model::PrimitiveKind::box;
    p.lower_m = {-1, -2, 0};
    p.upper_m = {1, 2, 3};
    const model::Mesh mesh = tessellate(p);
    EXPECT_EQ(mesh.triangles.size(), 12u);
    EXPECT_EQ(mesh.vertices_m.size(), 8u);
    const Bounds b = bounds_of(mesh);
    EXPECT_EQ(b.lo, (std::array<float, 3>{-1, -2, 0}));
    EXPECT_EQ(b.hi, (std::array<float, 3>{1, 2, 3}));
    expect_outward(mesh, {0, 0, 1.5});
}

TEST(MeshPrimitives, Sphere) {
    model::Primitive p;
    p.kind = model::PrimitiveKind::sphere;
    p.center_m = {0, 0, 10};
    p.radius_m = 2;
    p.segments = 8;
    p.rings = 4;
    const model::Mesh mesh = tessellate(p);
    EXPECT_EQ(mesh.triangles.size(), 2u * 8 * 3);
    EXPECT_EQ(mesh.vertices_m.size(), 2u + 8 * 3);
    const Bounds b = bounds_of(mesh);
    EXPECT_FLOAT_EQ(b.lo[0], -2.0f);
    EXPECT_FLOAT_EQ(b.hi[0], 2.0f);
    EXPECT_FLOAT_EQ(b.lo[2], 8.0f);
    EXPECT_FLOAT_EQ(b.hi[2], 12.0f);
    for (const auto& v : mesh.vertices_m) {
        EXPECT_NEAR(std::hypot(v[0], v[1], v[2] - 10.0), 2.0, 1e-5);
    }
    expect_outward(mesh, {0, 0, 10});
}

TEST(MeshPrimitives, Disk) {
    model::Primitive p;
    p.kind = model::PrimitiveKind::disk;
    p.radius_m = 3;
    const model::Mesh mesh = tessellate(p);
    EXPECT_EQ(mesh.triangles.size(), 32u);
    const Bounds b = bounds_of(mesh);
    EXPECT_FLOAT_EQ(b.lo[0], -3.0f);
    EXPECT_FLOAT_EQ(b.hi[0], 3.0f);
    EXPECT_FLOAT_EQ(b.hi[2], 0.0f);
    expect_outward(mesh, {0, 0, -1});
}

TEST(MeshPrimitives, Cylinder) {
    model::Primitive p;
    p.kind = model::PrimitiveKind::cylinder;
    p.center_m = {0, 0, 1};
    p.radius_m = 1;
    p.height_m = 4;
    const model::Mesh mesh = tessellate(p);
    EXPECT_EQ(mesh.triangles.size(), 4u * 32);
    const Bounds b = bounds_of(mesh);
    EXPECT_FLOAT_EQ(b.lo[2], 1.0f);
    EXPECT_FLOAT_EQ(b.hi[2], 5.0f);
    EXPECT_FLOAT_EQ(b.hi[0], 1.0f);
    expect_outward(mesh, {0, 0, 3});
    p.caps = false;
    EXPECT_EQ(tessellate(p).triangles.size(), 2u * 32);
}

TEST(MeshPrimitives, BadParameters) {
    model::Primitive p;
    p.kind = model::PrimitiveKind::sphere;
    p.radius_m = -1;
    p.segments = 2;
    Diagnostics diagnostics;
    EXPECT_TRUE(
        tessellate_primitive(p, 0, {"s.yaml", 4, "objects[0]"}, diagnostics).triangles.empty());
    EXPECT_EQ(diagnostics.error_count(), 2u) << dump(diagnostics);
}

// ---- validation -----------------------------------------------------------------------------

TEST(MeshValidate, DropsDegenerateTriangles) {
    model::Mesh mesh;
    mesh.vertices_m = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}};
    mesh.triangles = {{0, 1, 2}, {0, 1, 3}, {0, 0, 2}};  // collinear, repeated index
    mesh.triangle_materials = {0, 0, 0};
    Diagnostics diagnostics;
    EXPECT_TRUE(validate_mesh(mesh, 1, {"m", 0, "x"}, diagnostics));
    EXPECT_EQ(mesh.triangles.size(), 1u);
    ASSERT_EQ(diagnostics.items().size(), 1u);
    EXPECT_EQ(diagnostics.items()[0].severity, Severity::warning);
    EXPECT_EQ(diagnostics.items()[0].message, "dropped 2 degenerate triangles");
}

TEST(MeshValidate, Errors) {
    model::Mesh mesh;
    mesh.vertices_m = {{0, 0, 0}, {1, 0, 0}, {0, std::nanf(""), 0}};
    mesh.triangles = {{0, 1, 7}};
    mesh.triangle_materials = {3};
    Diagnostics diagnostics;
    EXPECT_FALSE(validate_mesh(mesh, 1, {"m", 0, "x"}, diagnostics));
    const std::string all = dump(diagnostics);
    EXPECT_THAT(all, HasSubstr("vertex 2 is not finite"));
    EXPECT_THAT(all, HasSubstr("triangle 0: vertex index 7 is out of range (3 vertices)"));
    EXPECT_THAT(all, HasSubstr("triangle 0: material index 3 is out of range (1 material)"));
}

TEST(MeshValidate, EmptyMesh) {
    model::Mesh mesh;
    mesh.vertices_m = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    mesh.triangles = {{0, 1, 2}};
    mesh.triangle_materials = {0};
    Diagnostics diagnostics;
    EXPECT_FALSE(validate_mesh(mesh, 1, {"m", 0, "x"}, diagnostics));
    EXPECT_THAT(dump(diagnostics), HasSubstr("error: m: x: mesh has no triangles"));
}
}  // namespace mesh_test
}  // namespace glint::mesh
