// SPDX-License-Identifier: Apache-2.0
// Point sources of DIRSIG scenes: glist `<basesource><pointsource matid=…>` objects with
// `.mat` point-source materials (OPTICAL_DESCRIPTION = SOURCE, INTENSITY_FILENAME). The
// street fixture (tests/data/dirsig_scene/lights) places a lamp post statically and a car
// bundle's headlight through a static and a dynamic instance of the bundle; the error cases
// name the element and file:line.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "glint/dirsig/scene_reader.h"
#include "glint/test/diagnostics.h"
#include "glint/test/temp_dir.h"

namespace glint::dirsig {
namespace point_source_reader_test {

using glint::test::diagnostics_text;
using glint::test::only_error;
using glint::test::TempDir;
using ::testing::HasSubstr;

namespace fs = std::filesystem;

const fs::path kLights = fs::path(GLINT_TEST_DATA_DIR) / "dirsig_scene" / "lights";

void write(const fs::path& path, const std::string& text) {
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

std::vector<std::string> warnings_of(const Diagnostics& diagnostics) {
    std::vector<std::string> out;
    for (const Diagnostic& d : diagnostics.items()) {
        if (d.severity == Diagnostic::Severity::warning) out.push_back(d.message);
    }
    return out;
}

TEST(PointSourceReader, StreetFixtureLoadsItsThreeSources) {
    Diagnostics diagnostics;
    const model::Scene scene = read_dirsig_scene(kLights / "lights.scene", {}, diagnostics);
    ASSERT_FALSE(diagnostics.has_errors()) << diagnostics_text(diagnostics);
    // One guess per source material, one pointing that is not applied (the bundle is read
    // once for both cars).
    const std::vector<std::string> warnings = warnings_of(diagnostics);
    ASSERT_EQ(warnings.size(), 3u) << diagnostics_text(diagnostics);
    EXPECT_THAT(warnings[0], HasSubstr("\"Sodium Lamp\": INTENSITY_FILENAME read as wavelength"));
    EXPECT_THAT(diagnostics_text(diagnostics), HasSubstr("\"Headlamp\": INTENSITY_FILENAME"));
    EXPECT_THAT(diagnostics_text(diagnostics), HasSubstr("<pointing> is read, not applied"));

    ASSERT_EQ(scene.point_sources.size(), 3u);
    const model::PointSource& lamp = scene.point_sources[0];
    EXPECT_EQ(lamp.name, "lamp");
    EXPECT_FALSE(lamp.dynamic());
    EXPECT_EQ((std::array<double, 3>{0.4, 0.3, 0.5}), lamp.position_m);
    const model::Material& sodium = scene.materials[lamp.material];
    EXPECT_TRUE(sodium.point_source);
    EXPECT_EQ(sodium.name, "Sodium Lamp");
    EXPECT_EQ(sodium.intensity_w_per_sr_um.values, (std::vector<double>{2.0, 2.0}));
    // A source material is black: no surface may use it.
    EXPECT_EQ(sodium.reflectance.values, (std::vector<double>{0.0, 0.0}));
    EXPECT_EQ(sodium.emissivity.values, (std::vector<double>{0.0, 0.0}));

    // The parked car's headlight: (0, 0.2, 0.05) turned 90° about z, moved to (−0.4, −0.3).
    const model::PointSource& parked = scene.point_sources[1];
    EXPECT_EQ(parked.name, "headlight");
    EXPECT_FALSE(parked.dynamic());
    EXPECT_NEAR(parked.position_m[0], -0.6, 1e-12);
    EXPECT_NEAR(parked.position_m[1], -0.3, 1e-12);
    EXPECT_NEAR(parked.position_m[2], 0.05, 1e-12);
    const model::Material& headlamp = scene.materials[parked.material];
    EXPECT_EQ(headlamp.id, "headlamp");
    EXPECT_EQ(headlamp.intensity_w_per_sr_um.wavelengths_um.size(), 5u);

    // The driving car's headlight rides its motion at its place in the bundle, with the
    // motion its body moves by.
    const model::PointSource& driving = scene.point_sources[2];
    ASSERT_TRUE(driving.dynamic());
    EXPECT_EQ((std::array<double, 3>{0.0, 0.2, 0.05}), driving.position_m);
    EXPECT_EQ(driving.material, parked.material);
    bool shared = false;
    for (const model::Instance& in : scene.instances) {
        shared = shared || (in.name == "body" && in.motion == driving.motion);
    }
    EXPECT_TRUE(shared) << "the headlight moves with the car's body";
}

/// A folder holding s.scene, which includes a.glist (given) and names s.mat (given).
struct Folder {
    TempDir dir;
    Diagnostics diagnostics;
    model::Scene scene;

    void run(const std::string& glist_text, const std::string& mat_text) {
        write(dir / "s.scene",
              "<classicscene>\n<geometrylist><geometrylistinclude>a.glist</geometrylistinclude>"
              "</geometrylist>\n<matfilename>s.mat</matfilename>\n</classicscene>\n");
        write(dir / "a.glist", glist_text);
        write(dir / "s.mat", mat_text);
        write(dir / "lamp.txt", "0.4 1\n1.0 1\n");
        write(dir / "grey.txt", "0.4 0.5\n1.0 0.5\n");
        scene = read_dirsig_scene(dir / "s.scene", {}, diagnostics);
    }
};

const std::string kMaterials =
    "MATERIAL_ENTRY {\n ID = lamp\n OPTICAL_DESCRIPTION = SOURCE\n"
    " INTENSITY_FILENAME = lamp.txt\n}\n"
    "MATERIAL_ENTRY {\n ID = grey\n SURFACE_PROPERTIES {\n"
    "  REFLECTANCE_PROP { TXT_FILENAME = grey.txt }\n }\n}\n";

std::string object(const std::string& body) {
    return "<geometrylist>\n<object name=\"L\">\n" + body +
           "\n<staticinstance/>\n</object>\n"
           "</geometrylist>\n";
}

TEST(PointSourceReaderErrors, ASurfaceMaterialIsNotASource) {
    Folder f;
    f.run(object("<basesource><pointsource matid=\"grey\"/></basesource>"), kMaterials);
    const Diagnostic e = only_error(f.diagnostics);
    EXPECT_EQ(e.where.file, (f.dir / "a.glist").string());
    EXPECT_EQ(e.where.line, 3);
    EXPECT_EQ(e.where.element, "geometrylist/object[L]/basesource/pointsource@matid");
    EXPECT_THAT(e.message, HasSubstr("material \"grey\" is not a point-source material"));
    EXPECT_TRUE(f.scene.point_sources.empty());
}

TEST(PointSourceReaderErrors, UnknownMaterial) {
    Folder f;
    f.run(object("<basesource><pointsource matid=\"sun2\"/></basesource>"), kMaterials);
    const Diagnostic e = only_error(f.diagnostics);
    EXPECT_EQ(e.where.line, 3);
    EXPECT_EQ(e.message, "unknown material id \"sun2\"");
}

TEST(PointSourceReaderErrors, ASurfaceMayNotUseASourceMaterial) {
    Folder f;
    f.run(object("<basegeometry><box><matid>lamp</matid><lowerextent><point><x>0</x><y>0</y>"
                 "<z>0</z></point></lowerextent><upperextent><point><x>1</x><y>1</y><z>1</z>"
                 "</point></upperextent></box></basegeometry>"),
          kMaterials);
    const Diagnostic e = only_error(f.diagnostics);
    EXPECT_EQ(e.where.line, 2);
    EXPECT_THAT(e.message,
                HasSubstr("object \"L\" uses point-source material \"lamp\" on a surface"));
}

TEST(PointSourceReaderErrors, GeometryAndSourceTogether) {
    Folder f;
    f.run(object("<basegeometry><groundplane><matid>grey</matid></groundplane></basegeometry>\n"
                 "<basesource><pointsource matid=\"lamp\"/></basesource>"),
          kMaterials);
    const Diagnostic e = only_error(f.diagnostics);
    EXPECT_EQ(e.where.line, 4);
    EXPECT_EQ(e.message, "give either <basegeometry> or <basesource>");
}

TEST(PointSourceReaderErrors, TwoSourcesInOneBase) {
    Folder f;
    f.run(object("<basesource><pointsource matid=\"lamp\"/><pointsource matid=\"lamp\"/>"
                 "</basesource>"),
          kMaterials);
    const Diagnostic e = only_error(f.diagnostics);
    EXPECT_EQ(e.where.line, 3);
    EXPECT_THAT(e.message, HasSubstr("expected exactly one <pointsource>, got 2 elements"));
}

TEST(PointSourceReaderErrors, ZeroPointingVector) {
    Folder f;
    f.run(object("<basesource><pointsource matid=\"lamp\"><pointing><vector><x>0</x><y>0</y>"
                 "<z>0</z></vector></pointing></pointsource></basesource>"),
          kMaterials);
    const Diagnostic e = only_error(f.diagnostics);
    EXPECT_EQ(e.message, "pointing vector must be finite and not zero");
}

TEST(PointSourceReaderErrors, SourceMaterialWithoutIntensityFile) {
    Folder f;
    f.run(object("<basesource><pointsource matid=\"lamp\"/></basesource>"),
          "MATERIAL_ENTRY {\n ID = lamp\n OPTICAL_DESCRIPTION = SOURCE\n}\n");
    ASSERT_TRUE(f.diagnostics.has_errors());
    const Diagnostic& e = f.diagnostics.items().front();
    EXPECT_EQ(e.where.file, (f.dir / "s.mat").string());
    EXPECT_EQ(e.where.line, 1);
    EXPECT_THAT(e.message, HasSubstr("(OPTICAL_DESCRIPTION = SOURCE) needs INTENSITY_FILENAME"));
}

TEST(PointSourceReaderErrors, NegativeIntensityIsRefusedAtItsLine) {
    Folder f;
    write(f.dir / "neg.txt", "0.4 1\n0.5 -2\n");
    f.run(object("<basesource><pointsource matid=\"lamp\"/></basesource>"),
          "MATERIAL_ENTRY {\n ID = lamp\n OPTICAL_DESCRIPTION = SOURCE\n"
          " INTENSITY_FILENAME = neg.txt\n}\n");
    ASSERT_TRUE(f.diagnostics.has_errors()) << diagnostics_text(f.diagnostics);
    bool found = false;
    for (const Diagnostic& d : f.diagnostics.items()) {
        if (d.severity != Diagnostic::Severity::error) continue;
        found = true;
        EXPECT_EQ(d.where.line, 2);
        EXPECT_THAT(d.where.file, HasSubstr("neg.txt"));
        EXPECT_THAT(d.message, HasSubstr("intensity -2 is not a finite number >= 0"));
    }
    EXPECT_TRUE(found);
}

TEST(PointSourceReaderErrors, IntensityAboveOneIsAccepted) {
    Folder f;
    write(f.dir / "bright.txt", "0.4 1500\n1.0 2500\n");
    f.run(object("<basesource><pointsource matid=\"lamp\"/></basesource>"),
          "MATERIAL_ENTRY {\n ID = lamp\n OPTICAL_DESCRIPTION = SOURCE\n"
          " INTENSITY_FILENAME = bright.txt\n SURFACE_PROPERTIES {\n"
          "  REFLECTANCE_PROP { TXT_FILENAME = grey.txt }\n }\n}\n");
    ASSERT_FALSE(f.diagnostics.has_errors()) << diagnostics_text(f.diagnostics);
    EXPECT_THAT(diagnostics_text(f.diagnostics),
                HasSubstr("SURFACE_PROPERTIES of point-source material \"lamp\" are not read"));
    ASSERT_EQ(f.scene.point_sources.size(), 1u);
    EXPECT_EQ(f.scene.materials[0].intensity_w_per_sr_um.values,
              (std::vector<double>{1500.0, 2500.0}));
}

}  // namespace point_source_reader_test
}  // namespace glint::dirsig
