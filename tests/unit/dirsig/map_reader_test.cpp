// SPDX-License-Identifier: Apache-2.0
// Tests of the `.scene` property-map reader (map_reader.cpp, map_images.cpp): a material
// map's look-up table decoded into texel slots (8- and 16-bit images), a mixture map's bands
// into normalised weights (ENVI float cube), the projector's attributes, `<mapdirectory>`,
// a disabled map skipped without a word, and every bad map with its message and place.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "glint/dirsig/scene_reader.h"
#include "glint/test/diagnostics.h"
#include "glint/test/temp_dir.h"

namespace glint::dirsig {
namespace map_reader_test {

using glint::test::only_error;
using glint::test::TempDir;
using ::testing::HasSubstr;

void write(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

/// A binary PGM of `width` × values.size()/width texels (line 0 first); 16-bit when `wide`.
void write_pgm(const std::filesystem::path& path, std::size_t width,
               const std::vector<unsigned>& values, bool wide = false) {
    std::string text = "P5\n" + std::to_string(width) + " " +
                       std::to_string(values.size() / width) + "\n" + (wide ? "65535" : "255") +
                       "\n";
    for (const unsigned v : values) {
        if (wide) text.push_back(static_cast<char>(v >> 8));
        text.push_back(static_cast<char>(v & 0xffu));
    }
    write(path, text);
}

/// An ENVI float32 BIP cube, `bands` values per texel.
void write_envi(const std::filesystem::path& path, std::size_t width, std::size_t height,
                std::size_t bands, const std::vector<float>& values) {
    write(path.string() + ".hdr",
          "ENVI\nsamples = " + std::to_string(width) + "\nlines = " + std::to_string(height) +
              "\nbands = " + std::to_string(bands) +
              "\nheader offset = 0\nfile type = ENVI Standard\ndata type = 4\n"
              "interleave = bip\nbyte order = 0\n");
    std::string bytes(values.size() * 4, '\0');
    std::memcpy(bytes.data(), values.data(), bytes.size());
    write(path, bytes);
}

/// Every texel's slot, line by line.
std::vector<std::uint32_t> slots(const model::MapRaster& raster) {
    std::vector<std::uint32_t> out;
    for (std::uint64_t t = 0; t < std::uint64_t{raster.width} * raster.height; ++t) {
        out.push_back(raster.slot(t));
    }
    return out;
}

const char* kMat = R"(MATERIAL_ENTRY {
    ID = 1
    NAME = Terrain
    SURFACE_PROPERTIES { REFLECTANCE_PROP_NAME = SimpleReflectance
        REFLECTANCE_PROP { TXT_FILENAME = flat.txt } }
}
MATERIAL_ENTRY {
    ID = 11
    NAME = Grass
    SURFACE_PROPERTIES { REFLECTANCE_PROP_NAME = SimpleReflectance
        REFLECTANCE_PROP { TXT_FILENAME = flat.txt } }
}
MATERIAL_ENTRY {
    ID = 12
    NAME = Soil
    SURFACE_PROPERTIES { REFLECTANCE_PROP_NAME = SimpleReflectance
        REFLECTANCE_PROP { TXT_FILENAME = flat.txt } }
}
)";

/// A scene whose `<maplist>` holds `maps`, in a folder with its .mat, curve and maps/.
std::filesystem::path write_scene(const TempDir& dir, const std::string& maps,
                                  const std::string& extra = "") {
    write(dir.path() / "site.mat", kMat);
    write(dir.path() / "flat.txt", "0.4 0.2\n2.5 0.2\n");
    const auto scene = dir.path() / "site.scene";
    write(scene, std::string("<classicscene>\n") +
                     "  <sceneorigin><location frame=\"geodetic\"><latitude>43</latitude>"
                     "<longitude>-77</longitude></location></sceneorigin>\n"
                     "  <matfilename>site.mat</matfilename>\n" +
                     extra +
                     "  <mapdirectory>$SCENE_DIR/maps</mapdirectory>\n"
                     "  <maplist>\n" +
                     maps + "  </maplist>\n</classicscene>\n");
    std::filesystem::create_directories(dir.path() / "maps");
    return scene;
}

const char* kDrape =
    "<projector origin=\"cartesian\" flipx=\"false\" flipy=\"true\" extendx=\"repeat\" "
    "extendy=\"mirror\"><drapeprojector><insertpoint><x>-5</x><y>-2.5</y><z>0</z>"
    "</insertpoint><gsd>2.5</gsd></drapeprojector></projector>\n";

std::string material_map(const std::string& image, const std::string& table,
                         const std::string& attributes = "enabled=\"true\"",
                         const std::string& projector = kDrape) {
    return "<materialmap name=\"Classes\" " + attributes +
           ">\n<matidlist><matid>1</matid></matidlist>\n" + projector + "<dcmatlut>" + table +
           "</dcmatlut>\n<image><filename>" + image + "</filename></image>\n</materialmap>\n";
}

const char* kTable =
    "<entry><dc>10</dc><matid>11</matid></entry><entry><dc>20</dc><matid>12</matid></entry>"
    "<entry><dc>30</dc><matid>11</matid></entry>";

TEST(MapReader, MaterialMapSlotsFromTheTable) {
    TempDir dir;
    const auto scene_file = write_scene(dir, material_map("classes.pgm", kTable));
    write_pgm(dir.path() / "maps" / "classes.pgm", 3, {10, 20, 30, 30, 20, 10});
    Diagnostics diagnostics;
    const model::Scene scene = read_dirsig_scene(scene_file, {}, diagnostics);
    ASSERT_FALSE(diagnostics.has_errors()) << test::diagnostics_text(diagnostics);
    // The one warning: the drape projector's element names are glint's reading.
    ASSERT_EQ(diagnostics.warning_count(), 1u) << test::diagnostics_text(diagnostics);
    EXPECT_THAT(diagnostics.items()[0].message, HasSubstr("<drapeprojector>"));
    ASSERT_EQ(scene.maps.size(), 1u);
    const model::PropertyMap& map = scene.maps[0];
    EXPECT_EQ(map.kind, model::MapKind::material);
    EXPECT_EQ(map.name, "Classes");
    EXPECT_EQ(map.applies_to, (std::vector<std::uint32_t>{0}));
    EXPECT_EQ(map.slot_materials, (std::vector<std::uint32_t>{1, 2}));
    ASSERT_TRUE(map.raster);
    EXPECT_EQ(map.raster->width, 3u);
    EXPECT_EQ(map.raster->height, 2u);
    // A binary PGM is mapped as it is: its own counts, looked up per texel.
    EXPECT_EQ(map.raster->code_bytes, 1u);
    EXPECT_EQ(map.raster->code_stride, 1u);
    EXPECT_EQ(slots(*map.raster), (std::vector<std::uint32_t>{0, 1, 0, 0, 1, 0}));
    EXPECT_EQ(map.image.resolved, dir.path() / "maps" / "classes.pgm");
    const model::MapProjector& p = map.projector;
    EXPECT_FALSE(p.uv);
    EXPECT_EQ(p.origin, model::MapOrigin::cartesian);
    EXPECT_FALSE(p.flip_x);
    EXPECT_TRUE(p.flip_y);
    EXPECT_EQ(p.extend_x, model::MapExtend::repeat);
    EXPECT_EQ(p.extend_y, model::MapExtend::mirror);
    EXPECT_EQ(p.insert_point_m, (std::array<double, 2>{-5.0, -2.5}));
    EXPECT_EQ(p.gsd_m, (std::array<double, 2>{2.5, 2.5}));
}

TEST(MapReader, SixteenBitCountsAndUvProjector) {
    TempDir dir;
    const std::string table =
        "<entry><dc>1000</dc><matid>11</matid></entry><entry><dc>60000</dc><matid>12</matid>"
        "</entry>";
    const auto scene_file =
        write_scene(dir, material_map("wide.pgm", table, "enabled=\"true\" mixing=\"false\"",
                                      "<projector origin=\"image\"><uvprojector/></projector>"));
    write_pgm(dir.path() / "maps" / "wide.pgm", 2, {60000, 1000}, true);
    Diagnostics diagnostics;
    const model::Scene scene = read_dirsig_scene(scene_file, {}, diagnostics);
    ASSERT_FALSE(diagnostics.has_errors()) << test::diagnostics_text(diagnostics);
    EXPECT_EQ(diagnostics.warning_count(), 0u) << test::diagnostics_text(diagnostics);
    ASSERT_EQ(scene.maps.size(), 1u);
    EXPECT_TRUE(scene.maps[0].projector.uv);
    EXPECT_EQ(scene.maps[0].projector.origin, model::MapOrigin::image);
    EXPECT_EQ(scene.maps[0].projector.extend_x, model::MapExtend::none);
    EXPECT_EQ(scene.maps[0].raster->code_bytes, 2u);
    EXPECT_EQ(slots(*scene.maps[0].raster), (std::vector<std::uint32_t>{1, 0}));
}

TEST(MapReader, ColourPnmIsMappedWithItsStrideAndAWarning) {
    TempDir dir;
    const auto scene_file = write_scene(dir, material_map("rgb.ppm", kTable));
    // Two texels, R G B each: the first channel holds the counts.
    write(dir.path() / "maps" / "rgb.ppm", std::string("P6\n2 1\n255\n") + char(20) + char(1) +
                                               char(2) + char(10) + char(3) + char(4));
    Diagnostics diagnostics;
    const model::Scene scene = read_dirsig_scene(scene_file, {}, diagnostics);
    ASSERT_FALSE(diagnostics.has_errors()) << test::diagnostics_text(diagnostics);
    EXPECT_THAT(test::diagnostics_text(diagnostics),
                HasSubstr("has 3 channels; the first holds the digital counts"));
    ASSERT_EQ(scene.maps.size(), 1u);
    EXPECT_EQ(scene.maps[0].raster->code_stride, 3u);
    EXPECT_EQ(slots(*scene.maps[0].raster), (std::vector<std::uint32_t>{1, 0}));
}

TEST(MapReader, AnImageTooLargeIsRefusedBeforeItIsRead) {
    TempDir dir;
    const auto scene_file = write_scene(dir, material_map("huge.pgm", kTable));
    // Only the header: 10⁵ × 10⁵ texels is refused before any is read.
    write(dir.path() / "maps" / "huge.pgm", "P5\n100000 100000\n255\n");
    Diagnostics diagnostics;
    const model::Scene scene = read_dirsig_scene(scene_file, {}, diagnostics);
    EXPECT_THAT(only_error(diagnostics).message,
                HasSubstr("image \"huge.pgm\" is 100000 x 100000 texels, more than 2147483648"));
    EXPECT_TRUE(scene.maps.empty());
}

TEST(MapReader, BumpMapHeightsFromCountsAndScale) {
    TempDir dir;
    const auto scene_file = write_scene(
        dir, "<bumpmap name=\"B\"><matidlist><matid>1</matid></matidlist>" + std::string(kDrape) +
                 "<scale>0.5</scale><image><filename>b.pgm</filename></image></bumpmap>\n");
    write_pgm(dir.path() / "maps" / "b.pgm", 3, {0, 51, 255});
    Diagnostics diagnostics;
    const model::Scene scene = read_dirsig_scene(scene_file, {}, diagnostics);
    ASSERT_FALSE(diagnostics.has_errors()) << test::diagnostics_text(diagnostics);
    // Two warnings: the drape's and the bump map's element names are glint's reading.
    EXPECT_EQ(diagnostics.warning_count(), 2u) << test::diagnostics_text(diagnostics);
    ASSERT_EQ(scene.maps.size(), 1u);
    EXPECT_EQ(scene.maps[0].kind, model::MapKind::bump);
    // Heights: scale × count / 255.
    EXPECT_EQ(scene.maps[0].raster->weights, (std::vector<float>{0.0f, 0.1f, 0.5f}));
}

TEST(MapReader, DisabledMapIsSkippedWithoutAWord) {
    TempDir dir;
    // Its image does not exist, a texture map's band list is empty and a normal map's kind
    // is refused when enabled: none is looked at.
    const auto scene_file =
        write_scene(dir, material_map("missing.pgm", kTable, "enabled=\"false\"") +
                             "<texturemap name=\"T\" enabled=\"false\"><bandlist/></texturemap>\n"
                             "<normalmap name=\"B\" enabled=\"false\"/>\n");
    Diagnostics diagnostics;
    const model::Scene scene = read_dirsig_scene(scene_file, {}, diagnostics);
    EXPECT_TRUE(diagnostics.items().empty()) << test::diagnostics_text(diagnostics);
    EXPECT_TRUE(scene.maps.empty());
}

TEST(MapReader, MixtureMapWeightsNormalised) {
    TempDir dir;
    const std::string map =
        "<mixturemap name=\"Mix\" enabled=\"true\"><matidlist><matid>1</matid></matidlist>"
        "<projector><uvprojector/></projector>"
        "<bandmaterials><matid>11</matid><matid>12</matid></bandmaterials>"
        "<image><filename>mix.img</filename></image></mixturemap>\n";
    const auto scene_file = write_scene(dir, map);
    write_envi(dir.path() / "maps" / "mix.img", 2, 1, 2, {3.0f, 1.0f, 0.0f, 0.0f});
    Diagnostics diagnostics;
    const model::Scene scene = read_dirsig_scene(scene_file, {}, diagnostics);
    ASSERT_FALSE(diagnostics.has_errors()) << test::diagnostics_text(diagnostics);
    ASSERT_EQ(diagnostics.warning_count(), 1u) << test::diagnostics_text(diagnostics);
    EXPECT_THAT(diagnostics.items()[0].message, HasSubstr("<bandmaterials>"));
    ASSERT_EQ(scene.maps.size(), 1u);
    const model::PropertyMap& m = scene.maps[0];
    EXPECT_EQ(m.kind, model::MapKind::mixture);
    EXPECT_EQ(m.band_materials, (std::vector<std::uint32_t>{1, 2}));
    ASSERT_TRUE(m.raster);
    EXPECT_EQ(m.raster->bands, 2u);
    // (3, 1) → (0.75, 0.25); an all-zero texel stays zero (the facet keeps its material).
    EXPECT_EQ(m.raster->weights, (std::vector<float>{0.75f, 0.25f, 0.0f, 0.0f}));
}

/// A texture map over material 1 (made textured: three flat classes of reflectance 0.2, 0.4
/// and 0.6 in its .ems) with one band per image of `images`.
std::string texture_map(const std::string& name, const std::vector<std::string>& images) {
    std::string bands;
    for (const std::string& image : images) {
        bands += "<band><bandpass><min>0.4</min><max>0.7</max></bandpass><image><filename>" +
                 image + "</filename></image></band>";
    }
    return "<texturemap name=\"" + name +
           "\"><matidlist><matid>1</matid></matidlist><projector><uvprojector/></projector>"
           "<bandlist>" +
           bands + "</bandlist></texturemap>\n";
}

void make_textured(const TempDir& dir) {
    std::string mat = kMat;
    const std::string plain =
        "REFLECTANCE_PROP_NAME = SimpleReflectance\n        "
        "REFLECTANCE_PROP { TXT_FILENAME = flat.txt } }";
    mat.replace(mat.find(plain), plain.size(),
                "EMISSIVITY_PROP_NAME = ClassicEmissivity\n        "
                "EMISSIVITY_PROP { FILENAME = classes.ems } }");
    write(dir.path() / "site.mat", mat);
    write(dir.path() / "classes.ems",
          "3\nCURVE_BEGIN\n0.3 0.8\n1.0 0.8\nCURVE_END\nCURVE_BEGIN\n0.3 0.6\n1.0 0.6\n"
          "CURVE_END\nCURVE_BEGIN\n0.3 0.4\n1.0 0.4\nCURVE_END\n");
}

TEST(MapReader, TextureMapClassesAndZScores) {
    TempDir dir;
    const auto scene_file = write_scene(
        dir, texture_map("A", {"bright.pgm"}) + texture_map("B", {"bright.pgm", "bright.pgm"}));
    make_textured(dir);
    write_pgm(dir.path() / "maps" / "bright.pgm", 4, {10, 20, 30, 40});
    Diagnostics diagnostics;
    const model::Scene scene = read_dirsig_scene(scene_file, {}, diagnostics);
    ASSERT_FALSE(diagnostics.has_errors()) << test::diagnostics_text(diagnostics);
    // The .ems's texture classes, then the materials: Terrain, Grass, Soil and two variants,
    // made once though two maps cover the material.
    ASSERT_EQ(scene.materials.size(), 5u);
    EXPECT_EQ(scene.materials[3].id, "1#1");
    EXPECT_EQ(scene.materials[4].id, "1#2");
    EXPECT_EQ(scene.materials[4].texture_parent, std::optional<std::uint32_t>(0));
    EXPECT_NEAR(scene.materials[4].reflectance.values[0], 0.6, 1e-12);
    EXPECT_NEAR(scene.materials[4].emissivity.values[0], 0.4, 1e-12);
    ASSERT_EQ(scene.maps.size(), 2u);
    const model::PropertyMap& a = scene.maps[0];
    EXPECT_EQ(a.kind, model::MapKind::texture);
    ASSERT_EQ(a.texture_classes.size(), 1u);
    EXPECT_EQ(a.texture_classes[0].materials, (std::vector<std::uint32_t>{0, 3, 4}));
    // Classes ρ 0.2, 0.4, 0.6: z = −√1.5, 0, √1.5. Texels 10..40: z = ±1.342, ±0.447.
    const std::vector<float>& z = a.texture_classes[0].z;
    ASSERT_EQ(z.size(), 3u);
    EXPECT_NEAR(z[0], -std::sqrt(1.5), 1e-6);
    EXPECT_NEAR(z[1], 0.0, 1e-6);
    EXPECT_NEAR(z[2], std::sqrt(1.5), 1e-6);
    ASSERT_EQ(a.raster->bands, 1u);
    EXPECT_NEAR(a.raster->weights[0], -3.0 / std::sqrt(5.0), 1e-6);
    EXPECT_NEAR(a.raster->weights[2], 1.0 / std::sqrt(5.0), 1e-6);
    EXPECT_EQ(scene.maps[1].raster->bands, 2u);
    EXPECT_EQ(scene.maps[1].texture_classes[0].z.size(), 6u);
}

TEST(MapReader, AMixturesMaterialCannotBeMappedAgain) {
    TempDir dir;
    const std::string mixture =
        "<mixturemap name=\"Mix\"><matidlist><matid>1</matid></matidlist>"
        "<projector><uvprojector/></projector>"
        "<bandmaterials><matid>11</matid><matid>12</matid></bandmaterials>"
        "<image><filename>mix.img</filename></image></mixturemap>\n";
    const std::string bumps = "<bumpmap name=\"Bumps\"><matidlist><matid>12</matid></matidlist>" +
                              std::string(kDrape) +
                              "<scale>0.1</scale><image><filename>b.pgm</filename></image>"
                              "</bumpmap>\n";
    const auto scene_file = write_scene(dir, mixture + bumps);
    write_envi(dir.path() / "maps" / "mix.img", 1, 1, 2, {0.5f, 0.5f});
    write_pgm(dir.path() / "maps" / "b.pgm", 1, {0});
    Diagnostics diagnostics;
    read_dirsig_scene(scene_file, {}, diagnostics);
    const Diagnostic error = only_error(diagnostics);
    EXPECT_EQ(error.message,
              "<mixturemap> \"Mix\": material \"12\" is covered by <bumpmap> \"Bumps\", which "
              "cannot apply to a mixture's material (drawn per path after the maps)");
    EXPECT_EQ(error.where.line, 6);
}

struct BadMap {
    const char* name;
    std::string maps;
    std::string image;  ///< written to maps/classes.pgm when not empty: "dc dc ..." one line
    const char* message;
};

class MapReaderErrors : public ::testing::TestWithParam<BadMap> {};

TEST_P(MapReaderErrors, OneErrorWithItsMessage) {
    const BadMap& bad = GetParam();
    TempDir dir;
    const auto scene_file = write_scene(dir, bad.maps);
    if (!bad.image.empty()) {
        std::vector<unsigned> dcs;
        std::size_t at = 0;
        while (at < bad.image.size()) {
            std::size_t end = bad.image.find(' ', at);
            if (end == std::string::npos) end = bad.image.size();
            dcs.push_back(static_cast<unsigned>(std::stoul(bad.image.substr(at, end - at))));
            at = end + 1;
        }
        write_pgm(dir.path() / "maps" / "classes.pgm", dcs.size(), dcs);
        write_pgm(dir.path() / "maps" / "other.pgm", 1, {5});
    }
    Diagnostics diagnostics;
    const model::Scene scene = read_dirsig_scene(scene_file, {}, diagnostics);
    const Diagnostic error = only_error(diagnostics);
    EXPECT_THAT(error.message, HasSubstr(bad.message)) << bad.name;
    EXPECT_EQ(error.where.file, scene_file.string()) << bad.name;
    EXPECT_GT(error.where.line, 0) << bad.name;
    EXPECT_TRUE(scene.maps.empty()) << bad.name;
}

const std::string kMixtureProjector = "<projector><uvprojector/></projector>";

INSTANTIATE_TEST_SUITE_P(
    MapReader, MapReaderErrors,
    ::testing::Values(
        BadMap{"missing image", material_map("nope.pgm", kTable), "",
               "<materialmap> \"Classes\" image \"nope.pgm\" not found"},
        BadMap{"unlisted count", material_map("classes.pgm", kTable), "10 20 40 40",
               "holds 1 digital count that <dcmatlut> does not list: 40 (2 texels)"},
        BadMap{"unknown material",
               material_map("classes.pgm", "<entry><dc>10</dc><matid>99</matid></entry>"), "10",
               "unknown material id \"99\""},
        BadMap{"count twice",
               material_map("classes.pgm",
                            "<entry><dc>10</dc><matid>11</matid></entry>"
                            "<entry><dc>10</dc><matid>12</matid></entry>"),
               "10", "digital count 10 is listed twice, for different materials"},
        BadMap{"mixing", material_map("classes.pgm", kTable, "mixing=\"true\""), "10",
               "mixing=\"true\" is not supported"},
        BadMap{"no projector kind",
               material_map("classes.pgm", kTable, "", "<projector extendx=\"mirror\"/>"), "10",
               "<projector> needs <uvprojector/> or <drapeprojector>"},
        BadMap{"bad extend",
               material_map("classes.pgm", kTable, "",
                            "<projector extendx=\"wrap\"><uvprojector/></projector>"),
               "10", "wrap"},
        BadMap{"no gsd",
               material_map("classes.pgm", kTable, "", "<projector><drapeprojector/></projector>"),
               "10", "missing required element <gsd>"},
        BadMap{"normal map", "<normalmap name=\"Normals\" enabled=\"true\"/>\n", "",
               "<normalmap> \"Normals\" is not supported"},
        BadMap{"empty band list", texture_map("T", {}), "", "<bandlist> has no <band>"},
        BadMap{"bump through uv",
               "<bumpmap name=\"B\"><matidlist><matid>1</matid></matidlist>" + kMixtureProjector +
                   "<scale>0.1</scale><image><filename>classes.pgm</filename></image>"
                   "</bumpmap>\n",
               "10", "a bump map through texture coordinates is not supported"},
        BadMap{"bump without scale",
               "<bumpmap name=\"B\"><matidlist><matid>1</matid></matidlist>" + kMixtureProjector +
                   "<image><filename>classes.pgm</filename></image></bumpmap>\n",
               "10", "missing required element <scale>"},
        BadMap{"band sizes differ", texture_map("T", {"classes.pgm", "other.pgm"}), "10 20",
               "band image \"other.pgm\" is 1 x 1, the first band's 2 x 1"},
        BadMap{"mixture bands",
               "<mixturemap name=\"Mix\"><matidlist><matid>1</matid></matidlist>" +
                   kMixtureProjector +
                   "<bandmaterials><matid>11</matid><matid>12</matid></bandmaterials>"
                   "<image><filename>classes.pgm</filename></image></mixturemap>\n",
               "10 20", "has 1 band but 2 materials are listed"}),
    [](const ::testing::TestParamInfo<BadMap>& case_info) {
        std::string name = case_info.param.name;
        for (char& c : name) {
            if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
        }
        return name;
    });

}  // namespace map_reader_test
}  // namespace glint::dirsig
