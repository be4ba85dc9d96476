// SPDX-License-Identifier: Apache-2.0
// Tests of a DIRSIG scene folder laid out as real ones are (tests/data/dirsig_scene/tree):
// glists and OBJs found through `gdbdirectory`/`odbdirectory`, `search_paths="local"` against
// the default, a bundle's `localmaterials` and `assign`, a dynamic instance of a glist (every
// part moves), and the errors of missing files at the element and file:line naming them.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "glint/dirsig/scene_reader.h"
#include "glint/test/diagnostics.h"
#include "glint/test/temp_dir.h"

namespace glint::dirsig {
namespace scene_tree_test {

using glint::test::diagnostics_text;
using glint::test::only_error;
using glint::test::TempDir;
using ::testing::HasSubstr;

const std::filesystem::path kTree =
    std::filesystem::path(GLINT_TEST_DATA_DIR) / "dirsig_scene" / "tree";

void write(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

std::vector<const model::Instance*> named(const model::Scene& scene, const std::string& name) {
    std::vector<const model::Instance*> out;
    for (const model::Instance& in : scene.instances) {
        if (in.name == name) out.push_back(&in);
    }
    return out;
}

std::size_t material_index(const model::Scene& scene, const std::string& id) {
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        if (scene.materials[i].id == id) return i;
    }
    ADD_FAILURE() << "no material " << id;
    return 0;
}

TEST(DirsigSceneTree, LoadsThroughDatabaseDirectories) {
    Diagnostics diagnostics;
    const model::Scene scene = read_dirsig_scene(kTree / "tree.scene", {}, diagnostics);
    ASSERT_FALSE(diagnostics.has_errors()) << diagnostics_text(diagnostics);
    EXPECT_EQ(diagnostics.warning_count(), 0u) << diagnostics_text(diagnostics);

    // The scene's two materials, then the bundle's; its "paint" keeps the scene's id unique.
    ASSERT_EQ(scene.materials.size(), 4u);
    EXPECT_EQ(scene.materials[1].id, "paint");
    EXPECT_EQ(scene.materials[1].name, "WhitePaint");
    EXPECT_EQ(scene.materials[2].id, "paint@truck.mat");
    EXPECT_EQ(scene.materials[2].name, "RedPaint");
    EXPECT_EQ(scene.materials[3].id, "rubber");

    // lists/terrain.glist names objects/small.obj: found in the geometry directory.
    const model::GeometryObject& rock = scene.objects[1];
    EXPECT_EQ(rock.name, "Rock");
    EXPECT_EQ(rock.obj_file.resolved, kTree / "geometry" / "objects" / "small.obj");
    EXPECT_EQ(rock.mesh.triangles.size(), 4u);

    // The bundle's body: assign maps usemtl body_mtl to its local "paint"; the wheel binds
    // usemtl Rubber to the local material's name.
    const model::GeometryObject& body = scene.objects[2];
    EXPECT_EQ(body.name, "Body");
    EXPECT_EQ(body.obj_file.resolved, kTree / "geometry/bundles/truck/body.obj");
    ASSERT_EQ(body.mesh.triangle_materials.size(), 2u);
    EXPECT_EQ(body.mesh.triangle_materials[0], material_index(scene, "paint@truck.mat"));
    const model::GeometryObject& wheel = scene.objects[3];
    EXPECT_EQ(wheel.mesh.triangle_materials[0], material_index(scene, "rubber"));

    // Parked truck: three parts composed with the outer placement (static).
    const auto bodies = named(scene, "body");
    ASSERT_EQ(bodies.size(), 2u);
    EXPECT_FALSE(bodies[0]->dynamic());
    ASSERT_TRUE(bodies[0]->transform.matrix);
    EXPECT_NEAR((*bodies[0]->transform.matrix)[3], 0.3, 1e-12);
    EXPECT_NEAR((*bodies[0]->transform.matrix)[11], 0.1, 1e-12);
    EXPECT_NEAR((*bodies[0]->transform.matrix)[1], -1.0, 1e-12);  // 90° about z
    // Moving truck: every part carries the instance's motion, its placement baked in.
    ASSERT_TRUE(bodies[1]->dynamic());
    EXPECT_TRUE(bodies[1]->motion->flexible);
    EXPECT_FALSE(bodies[1]->transform.matrix);
    const model::GeometryObject& moving_body = scene.objects[bodies[1]->object_index];
    EXPECT_NE(bodies[1]->object_index, 2u);
    EXPECT_EQ(moving_body.mesh.triangles, body.mesh.triangles);
    EXPECT_FLOAT_EQ(moving_body.mesh.vertices_m[0][2], 0.1f);
    EXPECT_FLOAT_EQ(moving_body.mesh.vertices_m[0][0], -0.2f);
    for (const std::string name : {"front_wheel", "rear_wheel"}) {
        const auto wheels = named(scene, name);
        ASSERT_EQ(wheels.size(), 2u) << name;
        EXPECT_FALSE(wheels[0]->dynamic());
        ASSERT_TRUE(wheels[1]->dynamic());
        EXPECT_EQ(wheels[1]->motion, bodies[1]->motion);  // one motion shared by the parts
        const float dx = name == "front_wheel" ? 0.15f : -0.15f;
        EXPECT_FLOAT_EQ(scene.objects[wheels[1]->object_index].mesh.vertices_m[1][0], 0.05f + dx);
    }
    // ground, rock, 3 parked parts, 3 moving parts.
    EXPECT_EQ(scene.instances.size(), 8u);
}

/// A scene folder in a temp dir: s.scene with gdbdirectory geometry, including
/// lists/a.glist (whose text is given) and the fixture's materials.
struct Folder {
    TempDir dir;
    Diagnostics diagnostics;
    model::Scene scene;

    void run(const std::string& glist_text,
             const std::string& dirs = "<gdbdirectory>$SCENE_DIR/geometry</gdbdirectory>\n") {
        write(dir / "s.scene", "<classicscene>\n" + dirs +
                                   "<geometrylist>\n<geometrylistinclude>lists/a.glist"
                                   "</geometrylistinclude>\n</geometrylist>\n<matfilename>" +
                                   (kTree / "materials/tree.mat").string() +
                                   "</matfilename>\n</classicscene>\n");
        write(dir / "geometry/lists/a.glist", glist_text);
        scene = read_dirsig_scene(dir / "s.scene", {}, diagnostics);
    }
};

const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
const char* kQuad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";

TEST(DirsigSceneTree, LocalAndDefaultSearchResolveToDifferentFiles) {
    Folder f;
    write(f.dir / "geometry/objects/m.obj", kTriangle);    // through gdbdirectory
    write(f.dir / "geometry/lists/objects/m.obj", kQuad);  // beside the glist
    f.run(
        "<geometrylist>\n"
        "<object name=\"Default\">\n"
        "<basegeometry><obj><filename>objects/m.obj</filename><matid>terrain</matid></obj>"
        "</basegeometry>\n<staticinstance/>\n</object>\n"
        "<object name=\"Local\" search_paths=\"local\">\n"
        "<basegeometry><obj><filename>objects/m.obj</filename><matid>terrain</matid></obj>"
        "</basegeometry>\n<staticinstance/>\n</object>\n"
        "</geometrylist>\n");
    ASSERT_FALSE(f.diagnostics.has_errors()) << diagnostics_text(f.diagnostics);
    ASSERT_EQ(f.scene.objects.size(), 2u);
    EXPECT_EQ(f.scene.objects[0].obj_file.resolved, f.dir / "geometry/objects/m.obj");
    EXPECT_EQ(f.scene.objects[0].mesh.triangles.size(), 1u);
    EXPECT_EQ(f.scene.objects[1].obj_file.resolved, f.dir / "geometry/lists/objects/m.obj");
    EXPECT_EQ(f.scene.objects[1].mesh.triangles.size(), 2u);
    // The default's choice is a guess when both exist: one warning at the naming line.
    ASSERT_EQ(f.diagnostics.warning_count(), 1u) << diagnostics_text(f.diagnostics);
    const Diagnostic& w = f.diagnostics.items().front();
    EXPECT_EQ(w.where.file, (f.dir / "geometry/lists/a.glist").string());
    EXPECT_EQ(w.where.line, 3);
    EXPECT_EQ(w.where.element, "geometrylist/object[Default]/basegeometry/obj/filename");
    EXPECT_THAT(w.message, HasSubstr("is taken from the database directory"));
}

TEST(DirsigSceneTree, FallbackBesideTheGlistWarnsOnce) {
    Folder f;
    write(f.dir / "geometry/lists/objects/m.obj", kTriangle);
    const std::string object =
        "<object>\n<basegeometry><obj><filename>objects/m.obj</filename><matid>terrain</matid>"
        "</obj></basegeometry>\n<staticinstance/>\n</object>\n";
    f.run("<geometrylist>\n" + object + object + "</geometrylist>\n");
    ASSERT_FALSE(f.diagnostics.has_errors()) << diagnostics_text(f.diagnostics);
    EXPECT_EQ(f.scene.objects[1].obj_file.resolved, f.dir / "geometry/lists/objects/m.obj");
    ASSERT_EQ(f.diagnostics.warning_count(), 1u) << diagnostics_text(f.diagnostics);
    EXPECT_EQ(f.diagnostics.items().front().where.line, 3);
    EXPECT_THAT(f.diagnostics.items().front().message,
                HasSubstr("is not in the scene's database directories"));
}

TEST(DirsigSceneTree, GlistIncludeFoundThroughObjectDirectory) {
    Folder f;
    write(f.dir / "db/lists/a.glist",
          "<geometrylist><object><basegeometry><groundplane><matid>terrain</matid>"
          "</groundplane></basegeometry><staticinstance/></object></geometrylist>\n");
    // Only the odb directory is given: lists/a.glist is db/lists/a.glist (the one Folder
    // writes under geometry/ is not searched).
    f.run("<geometrylist/>\n", "<odbdirectory>$SCENE_DIR/db</odbdirectory>\n");
    EXPECT_FALSE(f.diagnostics.has_errors()) << diagnostics_text(f.diagnostics);
    EXPECT_EQ(f.diagnostics.warning_count(), 0u) << diagnostics_text(f.diagnostics);
    EXPECT_EQ(f.scene.objects.size(), 1u);
}

TEST(DirsigSceneTree, LocalIncludeIsBesideTheScene) {
    Folder f;
    write(f.dir / "lists/a.glist",
          "<geometrylist><object><basegeometry><groundplane><matid>terrain</matid>"
          "</groundplane></basegeometry><staticinstance/></object></geometrylist>\n");
    // geometry/lists/a.glist (empty) is what the default finds; local takes lists/a.glist.
    TempDir& dir = f.dir;
    write(dir / "s.scene",
          "<classicscene>\n<gdbdirectory>$SCENE_DIR/geometry</gdbdirectory>\n<geometrylist>\n"
          "<geometrylistinclude search_paths=\"local\">lists/a.glist</geometrylistinclude>\n"
          "</geometrylist>\n<matfilename>" +
              (kTree / "materials/tree.mat").string() + "</matfilename>\n</classicscene>\n");
    write(dir / "geometry/lists/a.glist", "<geometrylist/>\n");
    const model::Scene scene = read_dirsig_scene(dir / "s.scene", {}, f.diagnostics);
    EXPECT_FALSE(f.diagnostics.has_errors()) << diagnostics_text(f.diagnostics);
    EXPECT_EQ(scene.objects.size(), 1u);
}

TEST(DirsigSceneTree, MirroredPartOfAMovingGlistKeepsItsFrontOutside) {
    Folder f;
    write(f.dir / "geometry/lists/m.obj", kTriangle);
    write(f.dir / "geometry/lists/inner.glist",
          "<geometrylist><object search_paths=\"local\"><basegeometry><obj>"
          "<filename>m.obj</filename><matid>terrain</matid></obj></basegeometry>"
          "<staticinstance name=\"part\"><scale><cartesiantriple><x>-1</x><y>1</y><z>1</z>"
          "</cartesiantriple></scale></staticinstance></object></geometrylist>\n");
    f.run(
        "<geometrylist>\n<object search_paths=\"local\">\n<basegeometry><glist>"
        "<filename>inner.glist</filename></glist></basegeometry>\n"
        "<dynamicinstance><motion type=\"flexible\"><locationengine type=\"fixed\">"
        "<location frame=\"scene\"><x>0</x><y>0</y><z>0</z></location></locationengine>"
        "<orientationengine type=\"velocity\"/></motion></dynamicinstance>\n</object>\n"
        "</geometrylist>\n");
    ASSERT_FALSE(f.diagnostics.has_errors()) << diagnostics_text(f.diagnostics);
    ASSERT_EQ(f.scene.instances.size(), 1u);
    const model::Instance& part = f.scene.instances[0];
    EXPECT_TRUE(part.dynamic());
    ASSERT_EQ(part.object_index, 1u);  // the baked copy of object 0
    const model::Mesh& mesh = f.scene.objects[1].mesh;
    EXPECT_FLOAT_EQ(mesh.vertices_m[1][0], -1.0f);
    // (v1 - v0) × (v2 - v0) still points +z, as the unmirrored triangle's does.
    const auto& t = mesh.triangles[0];
    const auto& a = mesh.vertices_m[t[0]];
    const auto& b = mesh.vertices_m[t[1]];
    const auto& c = mesh.vertices_m[t[2]];
    const float nz = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    EXPECT_GT(nz, 0.0f);
}

TEST(DirsigSceneTreeErrors, MissingObjNamesTheElementAndLine) {
    Folder f;
    f.run(
        "<geometrylist>\n<object name=\"Car\">\n<basegeometry>\n"
        "<obj><filename>objects/x.obj</filename><matid>terrain</matid></obj>\n"
        "</basegeometry>\n<staticinstance/>\n</object>\n</geometrylist>\n");
    const Diagnostic e = only_error(f.diagnostics);
    EXPECT_EQ(e.where.file, (f.dir / "geometry/lists/a.glist").string());
    EXPECT_EQ(e.where.line, 4);
    EXPECT_EQ(e.where.element, "geometrylist/object[Car]/basegeometry/obj/filename");
    EXPECT_THAT(e.message, HasSubstr("obj file objects/x.obj not found (tried " +
                                     (f.dir / "geometry/objects/x.obj").string() + ", " +
                                     (f.dir / "geometry/lists/objects/x.obj").string() + ")"));
}

TEST(DirsigSceneTreeErrors, ObjThatIsAFolder) {
    Folder f;
    std::filesystem::create_directories(f.dir / "geometry/lists/objects/x.obj");
    f.run(
        "<geometrylist>\n<object search_paths=\"local\">\n<basegeometry>\n"
        "<obj><filename>objects/x.obj</filename><matid>terrain</matid></obj>\n"
        "</basegeometry>\n<staticinstance/>\n</object>\n</geometrylist>\n");
    const Diagnostic e = only_error(f.diagnostics);
    EXPECT_EQ(e.where.line, 4);
    EXPECT_THAT(e.message, HasSubstr("obj file objects/x.obj not found"));
}

TEST(DirsigSceneTreeErrors, MissingLocalMaterials) {
    Folder f;
    write(f.dir / "geometry/lists/m.obj", kTriangle);
    f.run(
        "<geometrylist>\n<object search_paths=\"local\">\n"
        "<localmaterials>gone.mat</localmaterials>\n"
        "<basegeometry><obj><filename>m.obj</filename><matid>terrain</matid></obj>"
        "</basegeometry>\n<staticinstance/>\n</object>\n</geometrylist>\n");
    const Diagnostic e = only_error(f.diagnostics);
    EXPECT_EQ(e.where.line, 3);
    EXPECT_EQ(e.where.element, "geometrylist/object/localmaterials");
    EXPECT_THAT(e.message, HasSubstr("local material file gone.mat not found"));
}

TEST(DirsigSceneTreeErrors, AssignOfUnknownMaterial) {
    Folder f;
    write(f.dir / "geometry/lists/m.obj", "usemtl red\n" + std::string(kTriangle));
    f.run(
        "<geometrylist>\n<object search_paths=\"local\">\n<basegeometry><obj>"
        "<filename>m.obj</filename>\n<assign id=\"nope\">red</assign>\n</obj></basegeometry>\n"
        "<staticinstance/>\n</object>\n</geometrylist>\n");
    ASSERT_TRUE(f.diagnostics.has_errors());
    const Diagnostic& e = f.diagnostics.items().front();
    EXPECT_EQ(e.where.line, 4);
    EXPECT_EQ(e.where.element, "geometrylist/object/basegeometry/obj/assign@id");
    EXPECT_EQ(e.message, "unknown material id \"nope\"");
}

TEST(DirsigSceneTreeErrors, AssignMapsUsemtlToSceneMaterial) {
    Folder f;
    write(f.dir / "geometry/lists/m.obj", "usemtl red\n" + std::string(kTriangle));
    f.run(
        "<geometrylist>\n<object search_paths=\"local\">\n<assign id=\"paint\">red</assign>\n"
        "<basegeometry><obj><filename>m.obj</filename></obj></basegeometry>\n"
        "<staticinstance/>\n</object>\n</geometrylist>\n");
    ASSERT_FALSE(f.diagnostics.has_errors()) << diagnostics_text(f.diagnostics);
    EXPECT_EQ(f.scene.objects[0].mesh.triangle_materials[0], 1u);
}

TEST(DirsigSceneTreeErrors, DynamicPartUnderDynamicGlist) {
    Folder f;
    write(f.dir / "geometry/lists/m.obj", kTriangle);
    const std::string motion =
        "<motion type=\"flexible\"><locationengine type=\"fixed\"><location frame=\"scene\">"
        "<x>0</x><y>0</y><z>0</z></location></locationengine>"
        "<orientationengine type=\"velocity\"/></motion>";
    write(f.dir / "geometry/lists/inner.glist",
          "<geometrylist>\n<object search_paths=\"local\">\n<basegeometry><obj>"
          "<filename>m.obj</filename><matid>terrain</matid></obj></basegeometry>\n"
          "<dynamicinstance name=\"spin\">" +
              motion +
              "</dynamicinstance>\n</object>\n"
              "</geometrylist>\n");
    f.run(
        "<geometrylist>\n<object search_paths=\"local\">\n<basegeometry><glist>"
        "<filename>inner.glist</filename></glist></basegeometry>\n"
        "<dynamicinstance name=\"move\">" +
        motion +
        "</dynamicinstance>\n</object>\n"
        "</geometrylist>\n");
    const Diagnostic e = only_error(f.diagnostics);
    EXPECT_EQ(e.where.file, (f.dir / "geometry/lists/inner.glist").string());
    EXPECT_EQ(e.where.line, 4);
    EXPECT_THAT(e.message, HasSubstr("cannot be moved by a dynamicinstance"));
}

TEST(DirsigSceneTreeErrors, UnknownSearchPathsValueWarns) {
    Folder f;
    write(f.dir / "geometry/m.obj", kTriangle);
    f.run(
        "<geometrylist>\n<object search_paths=\"everywhere\">\n<basegeometry><obj>"
        "<filename>m.obj</filename><matid>terrain</matid></obj></basegeometry>\n"
        "<staticinstance/>\n</object>\n</geometrylist>\n");
    EXPECT_FALSE(f.diagnostics.has_errors()) << diagnostics_text(f.diagnostics);
    ASSERT_EQ(f.diagnostics.warning_count(), 1u) << diagnostics_text(f.diagnostics);
    EXPECT_EQ(f.diagnostics.items().front().where.element, "geometrylist/object@search_paths");
}

}  // namespace scene_tree_test
}  // namespace glint::dirsig
