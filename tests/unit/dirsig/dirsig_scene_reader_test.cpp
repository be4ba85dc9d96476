// SPDX-License-Identifier: Apache-2.0
// Tests of the DIRSIG classic scene readers (.scene, .glist, .mat): the tests/data/
// dirsig_scene fixture field by field (origin, $SCENE_DIR, materials and curve files,
// primitives, OBJ binding, nested glist composition, static and dynamic instances, tags),
// read_scene's choice of reader, and each bad input with its message, line and element path.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "glint/dirsig/scene_reader.h"
#include "glint/inputs/scene_atmosphere.h"
#include "glint/test/diagnostics.h"
#include "glint/test/temp_dir.h"

namespace glint::dirsig {
namespace dirsig_scene_reader_test {

using glint::test::TempDir;
using ::testing::HasSubstr;

const std::filesystem::path kData = std::filesystem::path(GLINT_TEST_DATA_DIR) / "dirsig_scene";

std::string dump(const Diagnostics& diagnostics) {
    std::string out;
    for (const Diagnostic& d : diagnostics.items()) {
        out +=
            (d.severity == Diagnostic::Severity::error ? "error: " : "warning: ") + d.text() + "\n";
    }
    return out;
}

void write(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

/// The one error of `diagnostics`; fails the test unless there is exactly one.
using glint::test::only_error;

const model::Instance* find_instance(const model::Scene& scene, const std::string& name) {
    for (const model::Instance& in : scene.instances) {
        if (in.name == name) return &in;
    }
    return nullptr;
}

TEST(DirsigSceneReader, ReadsFixtureFieldByField) {
    Diagnostics diagnostics;
    const model::Scene scene = read_dirsig_scene(kData / "site.scene", {}, diagnostics);
    ASSERT_FALSE(diagnostics.has_errors()) << dump(diagnostics);
    EXPECT_EQ(diagnostics.warning_count(), 0u) << dump(diagnostics);

    ASSERT_TRUE(scene.origin);
    EXPECT_DOUBLE_EQ(scene.origin->latitude_deg, 43.0);
    EXPECT_DOUBLE_EQ(scene.origin->longitude_deg, -77.6);
    EXPECT_DOUBLE_EQ(scene.origin->altitude_m, 150.0);

    ASSERT_EQ(scene.materials.size(), 2u);
    const model::Material& grass = scene.materials[0];
    EXPECT_EQ(grass.id, "1");
    EXPECT_EQ(grass.name, "Grass");
    EXPECT_EQ(grass.reflectance.wavelengths_um, (std::vector<double>{0.4, 0.7, 1.0}));
    EXPECT_EQ(grass.reflectance.values, (std::vector<double>{0.05, 0.45, 0.50}));
    EXPECT_EQ(grass.reflectance.file.resolved, kData / "materials" / "grass.txt");
    EXPECT_TRUE(grass.emissivity_is_default);
    EXPECT_DOUBLE_EQ(grass.emissivity.values[1], 0.55);
    EXPECT_DOUBLE_EQ(grass.temperature_k, 295.5);
    const model::Material& asphalt = scene.materials[1];
    EXPECT_EQ(asphalt.id, "2");
    EXPECT_EQ(asphalt.name, "Asphalt");
    EXPECT_EQ(asphalt.reflectance.values, (std::vector<double>{0.10, 0.12}));
    EXPECT_FALSE(asphalt.emissivity_is_default);
    EXPECT_EQ(asphalt.emissivity.wavelengths_um, (std::vector<double>{0.4, 14.0}));
    EXPECT_EQ(asphalt.emissivity.values, (std::vector<double>{0.85, 0.95}));
    EXPECT_DOUBLE_EQ(asphalt.temperature_k, 310.0);

    ASSERT_EQ(scene.objects.size(), 4u);
    const model::GeometryObject& ground = scene.objects[0];
    ASSERT_TRUE(ground.primitive);
    EXPECT_EQ(ground.primitive->kind, model::PrimitiveKind::ground_plane);
    EXPECT_DOUBLE_EQ(ground.primitive->size_m, 1000.0);
    EXPECT_EQ(ground.material_id, "1");
    EXPECT_EQ(ground.mesh.triangles.size(), 2u);
    const model::GeometryObject& shed = scene.objects[1];
    EXPECT_EQ(shed.name, "Shed");
    ASSERT_TRUE(shed.primitive);
    EXPECT_EQ(shed.primitive->kind, model::PrimitiveKind::box);
    EXPECT_EQ(shed.primitive->lower_m, (std::array<double, 3>{-5, -4, 0}));
    EXPECT_EQ(shed.primitive->upper_m, (std::array<double, 3>{5, 4, 3}));
    EXPECT_EQ(shed.mesh.triangles.size(), 12u);
    EXPECT_EQ(shed.mesh.triangle_materials[0], 1u);
    const model::GeometryObject& car = scene.objects[2];
    EXPECT_EQ(car.obj_file.resolved, kData / "car.obj");
    EXPECT_EQ(car.mesh.triangles.size(), 3u);
    EXPECT_EQ(car.mesh.triangle_materials[0], 1u);  // before usemtl: matid 2
    EXPECT_EQ(car.mesh.triangle_materials[1], 0u);  // usemtl Grass, by name
    const model::GeometryObject& crate = scene.objects[3];
    EXPECT_EQ(crate.name, "Crate");
    EXPECT_EQ(crate.obj_file.resolved, kData / "parts" / "crate.obj");
    EXPECT_EQ(crate.mesh.triangle_materials[0], 1u);  // usemtl 2, by id

    ASSERT_EQ(scene.instances.size(), 6u);
    const model::Instance* g = find_instance(scene, "Ground");
    ASSERT_NE(g, nullptr);
    EXPECT_EQ(g->object_index, 0u);
    EXPECT_FALSE(g->dynamic());
    EXPECT_FALSE(g->transform.matrix);
    const model::Instance* s = find_instance(scene, "::IMPORTANT::shed");
    ASSERT_NE(s, nullptr);
    EXPECT_EQ(s->object_index, 1u);
    EXPECT_TRUE(s->important);
    EXPECT_EQ(s->tags, (std::vector<std::string>{"building", "target"}));
    EXPECT_EQ(s->transform.translation_m, (std::array<double, 3>{10, 20, 0}));
    EXPECT_DOUBLE_EQ(s->transform.rotation_rad[2], std::numbers::pi / 2);
    EXPECT_EQ(s->transform.rotation_order, "zyx");
    EXPECT_EQ(s->transform.scale, (std::array<double, 3>{1, 2, 1}));
    EXPECT_EQ(s->where.file, (kData / "site.glist").string());
    EXPECT_EQ(s->where.line, 19);
    const model::Instance* parked = find_instance(scene, "parked");
    ASSERT_NE(parked, nullptr);
    ASSERT_TRUE(parked->transform.matrix);
    EXPECT_DOUBLE_EQ((*parked->transform.matrix)[3], 5.0);
    EXPECT_DOUBLE_EQ((*parked->transform.matrix)[7], 6.0);
    const model::Instance* driving = find_instance(scene, "driving");
    ASSERT_NE(driving, nullptr);
    ASSERT_TRUE(driving->dynamic());
    EXPECT_TRUE(driving->motion->flexible);
    EXPECT_EQ(driving->motion_file.resolved, kData / "flight.motion");
    const model::Instance* flying = find_instance(scene, "flying");
    ASSERT_NE(flying, nullptr);
    ASSERT_TRUE(flying->dynamic());
    EXPECT_TRUE(flying->motion->flexible);
    EXPECT_TRUE(flying->motion_file.empty());
    const model::Instance* c = find_instance(scene, "crate");
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->object_index, 3u);
    ASSERT_TRUE(c->transform.matrix);  // outer translation ∘ inner translation
    EXPECT_DOUBLE_EQ((*c->transform.matrix)[3], 101.0);
    EXPECT_DOUBLE_EQ((*c->transform.matrix)[7], 2.0);
    EXPECT_DOUBLE_EQ((*c->transform.matrix)[11], 3.0);
    EXPECT_DOUBLE_EQ((*c->transform.matrix)[0], 1.0);
}

TEST(DirsigSceneReader, ReadSceneChoosesByExtensionOrContent) {
    Diagnostics diagnostics;
    const model::Scene dirsig = inputs::read_scene(kData / "site.scene", {}, diagnostics);
    EXPECT_EQ(dirsig.objects.size(), 4u) << dump(diagnostics);
    TempDir dir;
    const std::string scene_text = "<classicscene><matfilename>" +
                                   (kData / "materials/site.mat").string() +
                                   "</matfilename></classicscene>";
    write(dir / "plain.txt", "\n  " + scene_text);
    Diagnostics d2;
    const model::Scene sniffed = inputs::read_scene(dir / "plain.txt", {}, d2);
    EXPECT_FALSE(d2.has_errors()) << dump(d2);
    EXPECT_EQ(sniffed.materials.size(), 2u);
    write(dir / "s.yaml", "objects: []\n");
    Diagnostics d3;
    inputs::read_scene(dir / "s.yaml", {}, d3);
    EXPECT_FALSE(d3.has_errors()) << dump(d3);
}

/// A scene in a temp dir using the fixture's materials, including `glist_text` as g.glist.
struct Bad {
    TempDir dir;
    Diagnostics diagnostics;
    model::Scene scene;

    void run(const std::string& glist_text) {
        write(dir / "s.scene",
              "<classicscene>\n<geometrylist>\n<geometrylistinclude>g.glist"
              "</geometrylistinclude>\n</geometrylist>\n<matfilename>" +
                  (kData / "materials/site.mat").string() + "</matfilename>\n</classicscene>\n");
        write(dir / "g.glist", glist_text);
        scene = read_dirsig_scene(dir / "s.scene", {}, diagnostics);
    }
};

TEST(DirsigSceneReaderErrors, MissingGlist) {
    TempDir dir;
    write(dir / "s.scene",
          "<classicscene>\n<matfilename>" + (kData / "materials/site.mat").string() +
              "</matfilename>\n<geometrylist>\n"
              "<geometrylistinclude name=\"A\">nowhere.glist</geometrylistinclude>\n"
              "</geometrylist>\n</classicscene>\n");
    Diagnostics diagnostics;
    read_dirsig_scene(dir / "s.scene", {}, diagnostics);
    const Diagnostic e = only_error(diagnostics);
    EXPECT_THAT(e.message, HasSubstr("geometry list nowhere.glist not found"));
    EXPECT_EQ(e.where.line, 4);
    EXPECT_EQ(e.where.element, "classicscene/geometrylist/geometrylistinclude[A]");
}

TEST(DirsigSceneReaderErrors, OdbInclude) {
    TempDir dir;
    write(dir / "s.scene", "<classicscene>\n<matfilename>" +
                               (kData / "materials/site.mat").string() +
                               "</matfilename>\n<geometrylist>\n"
                               "<geometrylistinclude>old.odb</geometrylistinclude>\n"
                               "</geometrylist>\n</classicscene>\n");
    Diagnostics diagnostics;
    read_dirsig_scene(dir / "s.scene", {}, diagnostics);
    const Diagnostic e = only_error(diagnostics);
    EXPECT_THAT(e.message, HasSubstr("odb geometry (old.odb) is not supported"));
    EXPECT_EQ(e.where.line, 4);
}

// ---- one bad glist, one error ----------------------------------------------------------------

/// A glist (run through Bad) and its only error: the message (whole, or a part of it), line
/// and element path.
struct GlistErrorCase {
    const char* name;
    const char* glist;
    const char* message;
    bool whole_message;  ///< the message is all of it, not a part
    int line;
    const char* element;
};

class DirsigGlistErrors : public ::testing::TestWithParam<GlistErrorCase> {};

TEST_P(DirsigGlistErrors, OnlyErrorMessageLineAndElement) {
    const GlistErrorCase& c = GetParam();
    Bad bad;
    bad.run(c.glist);
    const Diagnostic e = only_error(bad.diagnostics);
    if (c.whole_message) {
        EXPECT_EQ(e.message, c.message);
    } else {
        EXPECT_THAT(e.message, HasSubstr(c.message));
    }
    EXPECT_EQ(e.where.line, c.line);
    EXPECT_EQ(e.where.element, c.element);
}

const GlistErrorCase kGlistErrors[] = {
    {"GdbGeometry",
     "<geometrylist>\n<object>\n<basegeometry>\n<gdb><filename>house.gdb</filename></gdb>\n"
     "</basegeometry>\n<staticinstance/>\n</object>\n</geometrylist>\n",
     "gdb geometry (house.gdb) is not supported", false, 4, "geometrylist/object/basegeometry/gdb"},
    {"UnknownBaseGeometry",
     "<geometrylist>\n<object>\n<basegeometry>\n<checkers><matid>1</matid></checkers>\n"
     "</basegeometry>\n<staticinstance/>\n</object>\n</geometrylist>\n",
     "unknown basegeometry <checkers>", false, 4, "geometrylist/object/basegeometry/checkers"},
    {"MatrixWithFifteenValues",
     "<geometrylist>\n<object>\n<basegeometry><groundplane><matid>1</matid></groundplane>"
     "</basegeometry>\n<staticinstance name=\"m\">\n"
     "<matrix>1 0 0 0 0 1 0 0 0 0 1 0 0 0 0</matrix>\n</staticinstance>\n</object>\n"
     "</geometrylist>\n",
     "matrix has 15 values, expected 16", true, 5, "geometrylist/object/staticinstance[m]/matrix"},
    {"UnknownMaterialId",
     "<geometrylist>\n<object>\n<basegeometry>\n<groundplane>\n<matid>7</matid>\n"
     "</groundplane>\n</basegeometry>\n<staticinstance/>\n</object>\n</geometrylist>\n",
     "unknown material id \"7\"", true, 5, "geometrylist/object/basegeometry/groundplane/matid"},
    {"MissingNestedGlist",
     "<geometrylist>\n<object>\n<basegeometry>\n<glist><filename>sub/none.glist"
     "</filename></glist>\n</basegeometry>\n<staticinstance/>\n</object>\n"
     "</geometrylist>\n",
     "glist sub/none.glist not found", false, 4, "geometrylist/object/basegeometry/glist/filename"},
};

INSTANTIATE_TEST_SUITE_P(DirsigSceneReader, DirsigGlistErrors, ::testing::ValuesIn(kGlistErrors),
                         [](const ::testing::TestParamInfo<GlistErrorCase>& test_case) {
                             return std::string(test_case.param.name);
                         });

// ---- one bad curve file row, one error --------------------------------------------------------

/// The rows of r.txt, the REFLECTANCE_PROP curve file of material 5, and the only error: a
/// part of its message and, where checked, its line in r.txt and element path.
struct CurveFileCase {
    const char* name;
    const char* rows;
    const char* message;
    int line = 0;              ///< 0: not checked
    const char* element = "";  ///< "": not checked
};

class DirsigCurveFileErrors : public ::testing::TestWithParam<CurveFileCase> {};

TEST_P(DirsigCurveFileErrors, OnlyError) {
    const CurveFileCase& c = GetParam();
    TempDir dir;
    write(dir / "m.mat",
          "MATERIAL_ENTRY {\n  ID = 5\n  SURFACE_PROPERTIES {\n    REFLECTANCE_PROP {\n"
          "      TXT_FILENAME = r.txt\n    }\n  }\n}\n");
    write(dir / "r.txt", c.rows);
    Diagnostics diagnostics;
    read_dirsig_materials(dir / "m.mat", {}, diagnostics);
    const Diagnostic e = only_error(diagnostics);
    EXPECT_THAT(e.message, HasSubstr(c.message));
    if (c.line != 0) {
        EXPECT_EQ(e.where.file, (dir / "r.txt").string());
        EXPECT_EQ(e.where.line, c.line);
    }
    if (*c.element != '\0') {
        EXPECT_EQ(e.where.element, c.element);
    }
}

const CurveFileCase kCurveFileErrors[] = {
    {"RowNotTwoNumbers", "0.4 0.1\n0.5 abc\n", "expected two numbers, got \"0.5\" and \"abc\"", 2,
     "MATERIAL_ENTRY[5]/SURFACE_PROPERTIES/REFLECTANCE_PROP/TXT_FILENAME"},
    {"ThreeColumns", "0.4 0.1 7\n", "expected 2 columns"},
    {"DecreasingWavelengths", "0.4 0.1\n0.3 0.2\n", "not positive and strictly increasing"},
    {"ReflectanceAboveOne", "0.4 1.5\n", "reflectance 1.5 is outside [0, 1]"},
};

INSTANTIATE_TEST_SUITE_P(DirsigSceneReader, DirsigCurveFileErrors,
                         ::testing::ValuesIn(kCurveFileErrors),
                         [](const ::testing::TestParamInfo<CurveFileCase>& test_case) {
                             return std::string(test_case.param.name);
                         });

TEST(DirsigSceneReaderErrors, MaterialProblems) {
    TempDir dir;
    write(dir / "r.txt", "0.4 0.1\n");
    write(dir / "m.mat",
          "MATERIAL_ENTRY {\n  ID = 1\n  RAD_SOLVER_NAME = Ward\n  TEMP_SOLVER_NAME = THERM\n"
          "  SURFACE_PROPERTIES {\n    REFLECTANCE_PROP { TXT_FILENAME = r.txt }\n"
          "  }\n}\nMATERIAL_ENTRY {\n  ID = 1\n  BUNDLE_FILENAME = x.mat.hdf\n}\n"
          "MATERIAL_ENTRY {\n  ID = 3\n  TEMPERATURE = -4\n}\n");
    Diagnostics diagnostics;
    read_dirsig_materials(dir / "m.mat", {}, diagnostics);
    const std::string all = dump(diagnostics);
    EXPECT_THAT(all, HasSubstr("m.mat:3: MATERIAL_ENTRY[1]/RAD_SOLVER_NAME: radiometry solver "
                               "\"Ward\" of material \"1\" is not supported"));
    EXPECT_THAT(all, HasSubstr("m.mat:4: MATERIAL_ENTRY[1]/TEMP_SOLVER_NAME: temperature solver "
                               "\"Therm\" needs a TEMP_SOLVER block"));
    EXPECT_THAT(all, HasSubstr("m.mat:11: MATERIAL_ENTRY[1]/BUNDLE_FILENAME: material bundles"));
    EXPECT_THAT(all, HasSubstr("m.mat:9: MATERIAL_ENTRY[1]: duplicate material ID \"1\""));
    EXPECT_THAT(all, HasSubstr("m.mat:15: MATERIAL_ENTRY[3]/TEMPERATURE: temperature \"-4\""));
    EXPECT_THAT(all, HasSubstr("m.mat:13: MATERIAL_ENTRY[3]: missing SURFACE_PROPERTIES"));
    EXPECT_EQ(diagnostics.error_count(), 5u) << all;
    EXPECT_EQ(diagnostics.warning_count(), 1u) << all;
}

TEST(DirsigSceneReaderErrors, GlistIncludingItselfAndBadMotion) {
    Bad bad;
    bad.run(
        "<geometrylist>\n<object>\n<basegeometry><glist><filename>g.glist</filename></glist>"
        "</basegeometry>\n<staticinstance/>\n</object>\n<object>\n<basegeometry><groundplane>"
        "<matid>1</matid></groundplane></basegeometry>\n<dynamicinstance name=\"d\">\n"
        "<motion type=\"delta\"/>\n</dynamicinstance>\n</object>\n</geometrylist>\n");
    const std::string all = dump(bad.diagnostics);
    EXPECT_THAT(all, HasSubstr("g.glist:3: geometrylist/object/basegeometry/glist/filename: "
                               "glist g.glist includes itself"));
    EXPECT_THAT(all, HasSubstr("g.glist:9: geometrylist/object/dynamicinstance[d]/motion@type"));
}

TEST(DirsigSceneReaderErrors, BadOrigin) {
    TempDir dir;
    write(dir / "s.scene",
          "<classicscene>\n<sceneorigin>\n<location frame=\"geodetic\">\n"
          "<latitude>95</latitude><longitude>0</longitude>\n</location>\n</sceneorigin>\n"
          "<matfilename>$SCENE_DIR/none.mat</matfilename>\n</classicscene>\n");
    Diagnostics diagnostics;
    read_dirsig_scene(dir / "s.scene", {}, diagnostics);
    const std::string all = dump(diagnostics);
    EXPECT_THAT(all, HasSubstr(":4: classicscene/sceneorigin/location/latitude"));
    EXPECT_THAT(all, HasSubstr(":7: classicscene/matfilename: material file $SCENE_DIR/none.mat "
                               "not found"));
}

}  // namespace dirsig_scene_reader_test
}  // namespace glint::dirsig
