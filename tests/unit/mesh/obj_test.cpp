// SPDX-License-Identifier: Apache-2.0
// Tests of the OBJ parser (mesh::parse_obj_mesh): face indices are range-checked as written
// (no narrowing: 4294967299 is not 3), relative and texture/normal indices too, each problem
// at its own line; lines end at "\n", "\r\n" or "\r" as tinyobjloader reads them.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

#include "glint/mesh/mesh.h"
#include "glint/test/diagnostics.h"

namespace glint::mesh {
namespace obj_test {

using test::diagnostics_text;
using test::only_error;

const MaterialLookup kMaterials = [](const std::string& name) -> std::optional<std::uint32_t> {
    if (name == "grass") return 0;
    return std::nullopt;
};

model::Mesh parse(const std::string& text, Diagnostics& diagnostics) {
    return parse_obj_mesh(text, "m.obj", kMaterials, 0, 1, diagnostics);
}

const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

TEST(ObjParser, IndexThatWouldWrapIsOutOfRange) {
    Diagnostics diagnostics;
    const model::Mesh mesh = parse(kTriangle + "f 1 2 4294967299\n", diagnostics);
    EXPECT_TRUE(mesh.triangles.empty());
    EXPECT_EQ(only_error(diagnostics).text(),
              "m.obj:4: f: vertex index 4294967299 is out of range (3 vertices so far)");
}

TEST(ObjParser, IndicesBeyondEveryIntegerType) {
    Diagnostics huge;
    parse(kTriangle + "f 1 2 99999999999999999999999\n", huge);
    EXPECT_EQ(only_error(huge).message,
              "vertex index 99999999999999999999999 is out of range (3 vertices so far)");
    Diagnostics negative;
    parse(kTriangle + "f 1 2 -4294967297\n", negative);
    EXPECT_EQ(only_error(negative).message,
              "vertex index -4294967297 is out of range (3 vertices so far)");
}

TEST(ObjParser, RelativeIndices) {
    Diagnostics good;
    const model::Mesh mesh = parse(kTriangle + "f -3 -2 -1\n", good);
    EXPECT_FALSE(good.has_errors()) << diagnostics_text(good);
    ASSERT_EQ(mesh.triangles.size(), 1u);
    EXPECT_EQ(mesh.triangles[0], (std::array<std::uint32_t, 3>{0, 1, 2}));

    Diagnostics bad;
    parse(kTriangle + "f -1 -2 -4\n", bad);
    EXPECT_EQ(only_error(bad).text(),
              "m.obj:4: f: vertex index -4 is out of range (3 vertices so far)");
    Diagnostics zero;
    parse(kTriangle + "f 1 0 2\n", zero);
    EXPECT_EQ(only_error(zero).message, "vertex index 0 is out of range (3 vertices so far)");
}

TEST(ObjParser, TextureAndNormalIndices) {
    const std::string head = kTriangle + "vt 0 0\nvn 0 0 1\nvn 0 0 1\n";
    Diagnostics good;
    const model::Mesh mesh = parse(head + "f 1/1/2 2//1 3/-1\nf 1/1 2/1/-2 3\n", good);
    EXPECT_FALSE(good.has_errors()) << diagnostics_text(good);
    EXPECT_EQ(mesh.triangles.size(), 2u);

    Diagnostics texcoord;
    parse(head + "f 1/2 2/1 3/1\n", texcoord);
    EXPECT_EQ(only_error(texcoord).text(),
              "m.obj:7: f: texture coordinate index 2 is out of range (1 texture coordinates "
              "so far)");
    Diagnostics normal;
    parse(head + "f 1//1 2//4294967297 3//1\n", normal);
    EXPECT_EQ(only_error(normal).text(),
              "m.obj:7: f: normal index 4294967297 is out of range (2 normals so far)");
    Diagnostics before;  // counts are those before the face
    parse(kTriangle + "f 1//1 2//1 3//1\nvn 0 0 1\n", before);
    EXPECT_EQ(only_error(before).message, "normal index 1 is out of range (0 normals so far)");
}

TEST(ObjParser, TextureCoordinatesPerTriangleCorner) {
    // A quad (fanned into two triangles) with texture coordinates, relative ones included,
    // then a face without: NaN. A face before the first with coordinates gets NaN too.
    const std::string text = kTriangle +
                             "v 1 1 0\nf 1 2 3\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0.25 0.75\n"
                             "f 1/1 2/2 4/3 3/-1\nf 1 2 4\n";
    Diagnostics diagnostics;
    const model::Mesh mesh = parse(text, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors()) << diagnostics_text(diagnostics);
    ASSERT_EQ(mesh.triangles.size(), 4u);
    ASSERT_EQ(mesh.triangle_uvs.size(), 4u);
    EXPECT_TRUE(std::isnan(mesh.triangle_uvs[0][0]));
    EXPECT_EQ(mesh.triangle_uvs[1], (std::array<float, 6>{0, 0, 1, 0, 1, 1}));
    EXPECT_EQ(mesh.triangle_uvs[2], (std::array<float, 6>{0, 0, 1, 1, 0.25f, 0.75f}));
    EXPECT_TRUE(std::isnan(mesh.triangle_uvs[3][5]));
    // A mesh without any: none kept.
    Diagnostics plain;
    EXPECT_TRUE(parse(kTriangle + "vt 0 0\nf 1 2 3\n", plain).triangle_uvs.empty());
}

TEST(ObjParser, IndexThatIsNotAnInteger) {
    Diagnostics letters;
    parse(kTriangle + "f 1 2 3x\n", letters);
    EXPECT_EQ(only_error(letters).text(), "m.obj:4: f: vertex index \"3x\" is not an integer");
    Diagnostics empty;
    parse(kTriangle + "f 1 2 /1\n", empty);
    EXPECT_EQ(only_error(empty).message, "vertex index \"\" is not an integer");
    Diagnostics sign;
    parse(kTriangle + "f 1 2 +3\n", sign);  // a leading + is an integer
    EXPECT_FALSE(sign.has_errors()) << diagnostics_text(sign);
}

TEST(ObjParser, LinesEndAtCarriageReturnsToo) {
    // tinyobjloader ends a line at "\r" alone: the statement lines must follow it.
    Diagnostics diagnostics;
    parse("v 0 0 0\rv 1 0 0\r\nv 0 1 0\r\rf 1 2 3\rf 1 2 9\n", diagnostics);
    EXPECT_EQ(only_error(diagnostics).text(),
              "m.obj:6: f: vertex index 9 is out of range (3 vertices so far)");
}

TEST(ObjParser, EachBadFaceOnce) {
    Diagnostics diagnostics;
    const model::Mesh mesh = parse(kTriangle + "f 1 2 7\nf 1 2 3\nf 4294967296 1 2\n", diagnostics);
    ASSERT_EQ(diagnostics.error_count(), 2u) << diagnostics_text(diagnostics);
    EXPECT_EQ(diagnostics.items()[0].where.line, 4);
    EXPECT_EQ(diagnostics.items()[1].where.line, 6);
    EXPECT_TRUE(mesh.triangles.empty());  // an empty mesh on error
}

}  // namespace obj_test
}  // namespace glint::mesh
