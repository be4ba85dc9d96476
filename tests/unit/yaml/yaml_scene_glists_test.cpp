// SPDX-License-Identifier: Apache-2.0
// Tests of the glint YAML scene's `glists:` key: DIRSIG `.glist` geometry lists appended to
// the scene (the tests/data/dirsig_scene fixture's glist with its OBJ, nested glist and
// motion), their matid/usemtl bound to the YAML materials by id text, $SCENE_DIR, and each
// bad input (unknown material id at the glist's line, a missing glist, a malformed key).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>

#include "glint/dirsig/read_options.h"
#include "glint/test/diagnostics.h"
#include "glint/test/temp_dir.h"
#include "glint/yaml/scene_reader.h"

namespace glint::yaml {
namespace yaml_scene_glists_test {

using glint::test::diagnostics_text;
using glint::test::only_error;
using glint::test::TempDir;
using ::testing::HasSubstr;

const std::filesystem::path kGlistData =
    std::filesystem::path(GLINT_TEST_DATA_DIR) / "dirsig_scene";

void write(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

/// YAML materials with the ids the fixture glist uses (1 and 2; usemtl Grass by name).
const std::string kMaterials = R"(materials:
  - id: 1
    name: Grass
    reflectance: {wavelengths: [0.4, 0.7], values: [0.1, 0.2]}
  - id: 2
    name: asphalt
    reflectance: {wavelengths: [0.4, 0.7], values: [0.3, 0.4]}
)";

/// A glist of one ground plane of material `matid`, its `<matid>` on line 5.
std::string ground_glist(const std::string& matid) {
    return "<geometrylist>\n<object name=\"g\">\n<basegeometry>\n<groundplane>\n<matid>" + matid +
           "</matid>\n</groundplane>\n</basegeometry>\n<staticinstance/>\n</object>\n"
           "</geometrylist>\n";
}

model::Scene read(const std::filesystem::path& file, Diagnostics& diagnostics) {
    return read_yaml_scene(file, dirsig::ReadOptions{}, diagnostics);
}

TEST(YamlSceneGlists, AppendsTheFixtureGlistAfterTheYamlObjects) {
    TempDir dir;
    write(dir / "scene.yaml", kMaterials +
                                  "objects:\n  - name: plate\n    primitive: disk\n"
                                  "    material: 2\n    radius: 1\n"
                                  "glists:\n  - " +
                                  (kGlistData / "site.glist").string() + "\n");
    Diagnostics diagnostics;
    const model::Scene scene = read(dir / "scene.yaml", diagnostics);
    ASSERT_FALSE(diagnostics.has_errors()) << diagnostics_text(diagnostics);
    EXPECT_EQ(diagnostics.warning_count(), 0u) << diagnostics_text(diagnostics);

    ASSERT_EQ(scene.materials.size(), 2u);
    // plate from the YAML; ground, Shed, Car from site.glist; Crate from the nested glist.
    ASSERT_EQ(scene.objects.size(), 5u);
    EXPECT_EQ(scene.objects[0].name, "plate");
    EXPECT_EQ(scene.objects[1].mesh.triangle_materials[0], 0u);  // matid 1
    EXPECT_EQ(scene.objects[2].name, "Shed");
    EXPECT_EQ(scene.objects[2].mesh.triangle_materials[0], 1u);  // matid 2
    const model::GeometryObject& car = scene.objects[3];
    EXPECT_EQ(car.obj_file.resolved, kGlistData / "car.obj");
    EXPECT_EQ(car.mesh.triangle_materials[0], 1u);  // before usemtl: matid 2
    EXPECT_EQ(car.mesh.triangle_materials[1], 0u);  // usemtl Grass: the YAML name
    EXPECT_EQ(scene.objects[4].obj_file.resolved, kGlistData / "parts" / "crate.obj");
    EXPECT_EQ(scene.objects[4].mesh.triangle_materials[0], 1u);  // usemtl 2: the YAML id

    // 1 YAML instance, then Ground, shed, parked, driving, flying and the nested crate.
    ASSERT_EQ(scene.instances.size(), 7u);
    EXPECT_EQ(scene.instances[0].name, "plate");
    EXPECT_EQ(scene.instances[1].name, "Ground");
    EXPECT_EQ(scene.instances[1].object_index, 1u);
    EXPECT_EQ(scene.instances[1].where.file, (kGlistData / "site.glist").string());
    EXPECT_TRUE(scene.instances[2].important);
    EXPECT_TRUE(scene.instances[4].dynamic());  // flight.motion, relative to the glist
    EXPECT_EQ(scene.instances[4].motion_file.resolved, kGlistData / "flight.motion");
    EXPECT_EQ(scene.instances[6].name, "crate");
    EXPECT_EQ(scene.instances[6].object_index, 4u);
    ASSERT_TRUE(scene.instances[6].transform.matrix);
    EXPECT_DOUBLE_EQ((*scene.instances[6].transform.matrix)[3], 101.0);
}

TEST(YamlSceneGlists, PathsAreRelativeToTheYamlFileAndSceneDirExpands) {
    TempDir dir;
    write(dir / "sub" / "outer.glist",
          "<geometrylist>\n<object>\n<basegeometry><glist><filename>inner/in.glist</filename>"
          "</glist></basegeometry>\n<staticinstance/>\n</object>\n</geometrylist>\n");
    write(dir / "sub" / "inner" / "in.glist", ground_glist("paint"));
    write(dir / "other.glist", ground_glist("paint"));
    write(dir / "scene.yaml",
          "materials:\n  - id: paint\n    reflectance: {wavelengths: [0.4, 0.7], "
          "values: [0.1, 0.2]}\nglists: [sub/outer.glist, $SCENE_DIR/other.glist]\n");
    Diagnostics diagnostics;
    const model::Scene scene = read(dir / "scene.yaml", diagnostics);
    EXPECT_EQ(diagnostics.items().size(), 0u) << diagnostics_text(diagnostics);
    ASSERT_EQ(scene.objects.size(), 2u);  // no `objects:` needed with glists
    EXPECT_EQ(scene.instances.size(), 2u);
    EXPECT_EQ(scene.instances[0].where.file, (dir / "sub" / "inner" / "in.glist").string());
    EXPECT_EQ(scene.instances[1].where.file, (dir / "other.glist").string());
    const std::vector<std::uint32_t>& materials = scene.objects[1].mesh.triangle_materials;
    ASSERT_FALSE(materials.empty());
    EXPECT_EQ(std::count(materials.begin(), materials.end(), 0u),
              static_cast<std::ptrdiff_t>(materials.size()));
}

TEST(YamlSceneGlists, UnknownMaterialIdIsAnErrorAtTheGlistLine) {
    TempDir dir;
    write(dir / "g.glist", ground_glist("7"));
    write(dir / "scene.yaml", kMaterials + "glists:\n  - g.glist\n");
    Diagnostics diagnostics;
    read(dir / "scene.yaml", diagnostics);
    const Diagnostic e = only_error(diagnostics);
    EXPECT_EQ(e.message, "unknown material id \"7\"");
    EXPECT_EQ(e.where.file, (dir / "g.glist").string());
    EXPECT_EQ(e.where.line, 5);
    EXPECT_EQ(e.where.element, "geometrylist/object[g]/basegeometry/groundplane/matid");
}

TEST(YamlSceneGlists, MaterialNamesDoNotBindMatid) {
    TempDir dir;
    write(dir / "g.glist", ground_glist("Grass"));  // a name, not an id
    write(dir / "scene.yaml", kMaterials + "glists: [g.glist]\n");
    Diagnostics diagnostics;
    read(dir / "scene.yaml", diagnostics);
    EXPECT_EQ(only_error(diagnostics).message, "unknown material id \"Grass\"");
}

TEST(YamlSceneGlists, MissingGlistIsAnErrorAtTheYamlLine) {
    TempDir dir;
    write(dir / "scene.yaml", kMaterials + "objects: []\nglists:\n  - nowhere.glist\n");
    Diagnostics diagnostics;
    read(dir / "scene.yaml", diagnostics);
    const Diagnostic e = only_error(diagnostics);
    EXPECT_THAT(e.message, HasSubstr("glist nowhere.glist not found ("));
    EXPECT_EQ(e.where.file, (dir / "scene.yaml").string());
    EXPECT_EQ(e.where.line, 10);
    EXPECT_EQ(e.where.element, "glists[0]");
}

TEST(YamlSceneGlists, MalformedGlistsKey) {
    TempDir dir;
    write(dir / "scene.yaml", kMaterials + "glists: g.glist\n");
    Diagnostics d1;
    read(dir / "scene.yaml", d1);
    const Diagnostic e = only_error(d1);
    EXPECT_EQ(e.message, "expected a list of .glist paths");
    EXPECT_EQ(e.where.line, 8);
    EXPECT_EQ(e.where.element, "glists");

    write(dir / "scene.yaml", kMaterials + "glists:\n  - {file: g.glist}\n");
    Diagnostics d2;
    read(dir / "scene.yaml", d2);
    EXPECT_EQ(only_error(d2).where.element, "glists[0]");

    write(dir / "scene.yaml", kMaterials + "glists: [$NO_SUCH_GLINT_VARIABLE/g.glist]\n");
    Diagnostics d3;
    read(dir / "scene.yaml", d3);
    EXPECT_THAT(only_error(d3).message, HasSubstr("undefined variable $NO_SUCH_GLINT_VARIABLE"));

    write(dir / "scene.yaml", kMaterials);
    Diagnostics d4;
    read(dir / "scene.yaml", d4);
    EXPECT_EQ(only_error(d4).message, "missing required key \"objects\" (or \"glists\")");
}

}  // namespace yaml_scene_glists_test
}  // namespace glint::yaml
