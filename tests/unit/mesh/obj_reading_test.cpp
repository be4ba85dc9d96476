// SPDX-License-Identifier: Apache-2.0
// Tests of how the OBJ parser (mesh::parse_obj_mesh) reads its text: numbers at the very end
// of the text (nothing is read past it), exponents, coordinates valued as tinyobjloader valued
// them, huge lines, NULs, blanks and comments, the slow path of unusual coordinates, and the
// order of the errors.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include "glint/mesh/mesh.h"
#include "glint/test/diagnostics.h"

namespace glint::mesh {
namespace obj_reading_test {

using namespace std::string_literals;
using test::diagnostics_text;
using test::only_error;

const MaterialLookup kMaterials = [](const std::string& name) -> std::optional<std::uint32_t> {
    if (name == "grass") return 0;
    return std::nullopt;
};

model::Mesh parse(std::string_view text, Diagnostics& diagnostics) {
    return parse_obj_mesh(text, "m.obj", kMaterials, 0, 1, diagnostics);
}

/// Parses text that must have no problem.
model::Mesh parse_good(std::string_view text) {
    Diagnostics diagnostics;
    model::Mesh mesh = parse(text, diagnostics);
    EXPECT_TRUE(diagnostics.items().empty()) << diagnostics_text(diagnostics);
    return mesh;
}

const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

TEST(ObjReading, NumbersAtTheEndOfTheTextWithoutNewline) {
    // Each text is a view of a longer buffer: a digit past its end must not be read.
    const std::string vertex = kTriangle + "v 0 0 0.5" + "9";
    const model::Mesh a = parse_good(std::string_view(vertex).substr(0, vertex.size() - 1));
    ASSERT_EQ(a.vertices_m.size(), 4u);
    EXPECT_EQ(a.vertices_m[3], (std::array<float, 3>{0.0f, 0.0f, 0.5f}));

    const std::string exponent = kTriangle + "v 0 0 1e2" + "5";
    const model::Mesh b = parse_good(std::string_view(exponent).substr(0, exponent.size() - 1));
    ASSERT_EQ(b.vertices_m.size(), 4u);
    EXPECT_EQ(b.vertices_m[3][2], 100.0f);

    const std::string face = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3" + "4"s;
    const model::Mesh c = parse_good(std::string_view(face).substr(0, face.size() - 1));
    ASSERT_EQ(c.triangles.size(), 1u);
    EXPECT_EQ(c.triangles[0], (std::array<std::uint32_t, 3>{0, 1, 2}));
}

TEST(ObjReading, UtmCoordinatesKeepTheirMillimetres) {
    // A terrain in easting/northing: floats alone would step by 0.25 m at 4,000,000 m. The
    // mesh keeps the first vertex's whole metres as its origin and the rest in float.
    const model::Mesh mesh = parse_good(
        "v 500000.123 4000000.456 12.789\nv 500010.001 4000000.002 13.5\n"
        "v 500000.999 4000009.876 11.25\nf 1 2 3\n");
    EXPECT_EQ(mesh.origin_m, (std::array<double, 3>{500000.0, 4000000.0, 13.0}));
    const std::array<std::array<double, 3>, 3> written = {{{500000.123, 4000000.456, 12.789},
                                                           {500010.001, 4000000.002, 13.5},
                                                           {500000.999, 4000009.876, 11.25}}};
    for (std::size_t i = 0; i < 3; ++i) {
        for (std::size_t k = 0; k < 3; ++k) {
            // Floats of at most 10 m: 1e-6 m.
            EXPECT_NEAR(mesh.origin_m[k] + mesh.vertices_m[i][k], written[i][k], 1e-6)
                << i << ", " << k;
        }
    }
    // Near the origin nothing changes: the coordinates are the floats written.
    EXPECT_EQ(parse_good(kTriangle).origin_m, (std::array<double, 3>{0.0, 0.0, 0.0}));
}

TEST(ObjReading, Exponents) {
    const model::Mesh mesh = parse_good(kTriangle + "v 1e2 -2.5E-1 +3e+0\nv 1.5e-3 .5 -.25\n");
    ASSERT_EQ(mesh.vertices_m.size(), 5u);
    EXPECT_EQ(mesh.vertices_m[3], (std::array<float, 3>{100.0f, -0.25f, 3.0f}));
    EXPECT_FLOAT_EQ(mesh.vertices_m[4][0], 0.0015f);
    EXPECT_EQ(mesh.vertices_m[4][1], 0.5f);
    EXPECT_EQ(mesh.vertices_m[4][2], -0.25f);
}

TEST(ObjReading, CoordinatesValuedAsTinyobjloaderValuedThem) {
    // tinyobjloader summed the digits in double (706 + 2 × 0.1 + 5 × 0.01 + ...), which is
    // not always the correctly rounded value: 706.25003051757812 lies below the midpoint of
    // 706.25f and the next float, so correctly rounded it is 706.25f, but the sum lands above
    // it. Meshes keep the bits they had when glint read OBJ files through tinyobjloader.
    const model::Mesh mesh = parse_good(kTriangle + "v 706.25003051757812 0.123456789012 -0\n");
    ASSERT_EQ(mesh.vertices_m.size(), 4u);
    EXPECT_EQ(mesh.vertices_m[3][0], std::nextafter(706.25f, 1000.0f));
    EXPECT_FLOAT_EQ(mesh.vertices_m[3][1], 0.123456789012f);
    EXPECT_TRUE(std::signbit(mesh.vertices_m[3][2]));
}

TEST(ObjReading, HugeLines) {
    // A 1 MiB comment, a face spread over 1 MiB of blanks, a coordinate of 100 digits.
    const std::string blanks(1 << 20, ' ');
    const model::Mesh mesh =
        parse_good("#" + std::string(1 << 20, 'x') + "\n" + kTriangle + "f 1" + blanks + "2\t" +
                   blanks + "3" + blanks + "\n" + "v 0.0" + std::string(97, '1') + " 0 0\n");
    ASSERT_EQ(mesh.triangles.size(), 2u);
    EXPECT_EQ(mesh.triangles[1], (std::array<std::uint32_t, 3>{0, 1, 2}));
    ASSERT_EQ(mesh.vertices_m.size(), 4u);
    EXPECT_FLOAT_EQ(mesh.vertices_m[3][0], 0.011111111f);

    // A polygon of 5000 vertices on a circle, fan-triangulated from its first vertex.
    std::string polygon;
    const int n = 5000;
    for (int k = 0; k < n; ++k) {
        const double angle = 2.0 * 3.141592653589793 * k / n;
        polygon += "v " + std::to_string(100.0 * std::cos(angle)) + " " +
                   std::to_string(100.0 * std::sin(angle)) + " 0\n";
    }
    polygon += "f";
    for (int k = 1; k <= n; ++k) polygon += " " + std::to_string(k);
    const model::Mesh fan = parse_good(polygon);
    ASSERT_EQ(fan.triangles.size(), static_cast<std::size_t>(n - 2));
    EXPECT_EQ(fan.triangles.front(), (std::array<std::uint32_t, 3>{0, 1, 2}));
    EXPECT_EQ(fan.triangles.back(), (std::array<std::uint32_t, 3>{0, n - 2, n - 1}));
}

TEST(ObjReading, LinesAreReadUpToTheirFirstNul) {
    const model::Mesh mesh = parse_good("v 0 0 0\nv 1 0 0\nv 0 1 0\0 7 x\nf 1 2 3\0 99\n"s);
    ASSERT_EQ(mesh.vertices_m.size(), 3u);
    EXPECT_EQ(mesh.vertices_m[2], (std::array<float, 3>{0.0f, 1.0f, 0.0f}));
    EXPECT_EQ(mesh.triangles.size(), 1u);
}

TEST(ObjReading, BlanksCommentsAndLineEnds) {
    const model::Mesh mesh = parse_good(
        "# a comment\r\n\t v 0 0 0.5\r\n  v 1\t0 0  \rv 0 1 0\r\n\r\n# f 1 2 9\nf\t1 2 3 ");
    ASSERT_EQ(mesh.vertices_m.size(), 3u);
    EXPECT_EQ(mesh.vertices_m[0], (std::array<float, 3>{0.0f, 0.0f, 0.5f}));
    EXPECT_EQ(mesh.vertices_m[1], (std::array<float, 3>{1.0f, 0.0f, 0.0f}));
    EXPECT_EQ(mesh.triangles.size(), 1u);
}

TEST(ObjReading, CoordinatesThatAreNotPlainDecimals) {
    Diagnostics few;
    parse(kTriangle + "v 1 2\n", few);
    EXPECT_EQ(only_error(few).text(), "m.obj:5: v: vertex has fewer than 3 coordinates");

    Diagnostics bad;
    parse(kTriangle + "v 1 nan 2x\n", bad);
    ASSERT_EQ(bad.error_count(), 2u) << diagnostics_text(bad);
    EXPECT_EQ(bad.items()[0].text(), "m.obj:5: v: vertex y \"nan\" is not a finite number");
    EXPECT_EQ(bad.items()[1].text(), "m.obj:5: v: vertex z \"2x\" is not a finite number");

    Diagnostics huge;  // finite in double, not in float: the mesh validation says so
    parse(kTriangle + "v 1e300 0 0\n", huge);
    EXPECT_EQ(only_error(huge).text(), "m.obj: vertex 3 is not finite");

    // A fourth coordinate (w) is ignored; so is what follows it.
    const model::Mesh w = parse_good(kTriangle + "v 1 2 3 0.5 # w\n");
    EXPECT_EQ(w.vertices_m.back(), (std::array<float, 3>{1.0f, 2.0f, 3.0f}));
}

TEST(ObjReading, IndexErrorsComeBeforeMaterialAndFaceSizeErrors) {
    // As when tinyobjloader read the file after a first pass that checked the indices.
    Diagnostics diagnostics;
    parse("usemtl steel\n" + kTriangle + "f 1 2 9\nf 1 2\n", diagnostics);
    ASSERT_EQ(diagnostics.error_count(), 3u) << diagnostics_text(diagnostics);
    EXPECT_EQ(diagnostics.items()[0].text(),
              "m.obj:6: f: vertex index 9 is out of range (3 vertices so far)");
    EXPECT_EQ(diagnostics.items()[1].text(), "m.obj:1: usemtl: unknown material \"steel\"");
    EXPECT_EQ(diagnostics.items()[2].text(),
              "m.obj:7: f: face has 2 vertices, expected at least 3");
}

TEST(ObjReading, PlusMinusIndexIsZero) {
    // "+-3" passes the check as written (+ then -3) but tinyobjloader's atoi read it as 0.
    Diagnostics diagnostics;
    parse(kTriangle + "f 1 2 +-3\n", diagnostics);
    EXPECT_EQ(only_error(diagnostics).text(),
              "m.obj:5: f: vertex index 0 is out of range (3 vertices so far)");
}

}  // namespace obj_reading_test
}  // namespace glint::mesh
