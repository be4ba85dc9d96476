// SPDX-License-Identifier: Apache-2.0
// Tests of the glint YAML scene reader: the tests/data/scene fixture field by field (origin,
// inline and file materials, emissivity default, primitives, OBJ with usemtl, static and
// dynamic instances, tags and ::IMPORTANT::), and
// and every bad input with its message, line and key path.
#include "glint/yaml/scene_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <string>
#include <string_view>

#include "glint/dirsig/read_options.h"
#include "glint/test/mesh_checks.h"
#include "glint/test/temp_dir.h"

namespace glint::yaml {
namespace scene_reader_test {

using dirsig::ReadOptions;

using glint::test::TempDir;
using ::testing::HasSubstr;
using Severity = Diagnostic::Severity;

const std::filesystem::path kData = std::filesystem::path(GLINT_TEST_DATA_DIR) / "scene";

std::string dump(const Diagnostics& diagnostics) {
    std::string out;
    for (const Diagnostic& d : diagnostics.items()) {
        out += (d.severity == Severity::error ? "error: " : "warning: ") + d.text() + "\n";
    }
    return out;
}

/// 1-based line of the first occurrence of `needle` in `text` (0 when absent).
int line_of(std::string_view text, std::string_view needle) {
    const std::size_t pos = text.find(needle);
    if (pos == std::string_view::npos) return 0;
    return 1 +
           static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(pos), '\n'));
}

struct Read {
    std::string file;
    std::string text;
    model::Scene scene;
    Diagnostics diagnostics;
};

/// Writes `text` as scene.yaml (plus extra files) in a temp dir and reads it.
Read read_text(const TempDir& dir, const std::string& text) {
    Read read;
    read.file = (dir / "scene.yaml").string();
    read.text = text;
    std::ofstream(read.file, std::ios::binary) << text;
    read.scene = read_yaml_scene(read.file, ReadOptions{}, read.diagnostics);
    return read;
}

void write(const TempDir& dir, const std::string& name, const std::string& text) {
    std::ofstream(dir / name, std::ios::binary) << text;
}

/// Asserts a diagnostic containing `part` at `line` (of `file`, default the scene) with the
/// key path `element`.
void expect_diagnostic(const Read& read, std::string_view part, int line, std::string_view element,
                       Severity severity = Severity::error, std::string file = {}) {
    for (const Diagnostic& d : read.diagnostics.items()) {
        if (d.severity != severity || d.message.find(part) == std::string::npos) continue;
        EXPECT_EQ(d.where.line, line) << d.text();
        EXPECT_EQ(d.where.element, element) << d.text();
        EXPECT_EQ(d.where.file, file.empty() ? read.file : file) << d.text();
        return;
    }
    ADD_FAILURE() << "no diagnostic \"" << part << "\" in:\n" << dump(read.diagnostics);
}

const std::string kMaterials = R"(materials:
  - id: 1
    name: grass
    reflectance: {wavelengths: [0.4, 0.7], values: [0.1, 0.2]}
)";

// ---- the fixture ----------------------------------------------------------------------------

class SceneReaderFixture : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        s_read = new Read;
        s_read->file = (kData / "scene.yaml").string();
        s_read->scene = read_yaml_scene(s_read->file, ReadOptions{}, s_read->diagnostics);
    }
    static void TearDownTestSuite() {
        delete s_read;
        s_read = nullptr;
    }
    static Read* s_read;
};
Read* SceneReaderFixture::s_read = nullptr;

TEST_F(SceneReaderFixture, ReadsWithoutDiagnostics) {
    EXPECT_EQ(s_read->diagnostics.items().size(), 0u) << dump(s_read->diagnostics);
}

TEST_F(SceneReaderFixture, Origin) {
    const auto& scene = s_read->scene;
    ASSERT_TRUE(scene.origin);
    EXPECT_DOUBLE_EQ(scene.origin->latitude_deg, 43.0);
    EXPECT_DOUBLE_EQ(scene.origin->longitude_deg, -77.6);
    EXPECT_DOUBLE_EQ(scene.origin->altitude_m, 150.0);
    EXPECT_EQ(scene.origin->where.line, 3);
}

TEST_F(SceneReaderFixture, Materials) {
    const auto& m = s_read->scene.materials;
    ASSERT_EQ(m.size(), 2u);
    EXPECT_EQ(m[0].id, "1");
    EXPECT_EQ(m[0].name, "grass");
    EXPECT_EQ(m[0].reflectance.wavelengths_um, (std::vector<double>{0.4, 0.7, 1.0}));
    EXPECT_EQ(m[0].reflectance.values, (std::vector<double>{0.05, 0.1, 0.4}));
    EXPECT_TRUE(m[0].reflectance.file.empty());
    EXPECT_DOUBLE_EQ(m[0].temperature_k, 295.0);
    EXPECT_DOUBLE_EQ(m[0].specular.fraction, 0.0);
    // Emissivity default: 1 - reflectance at the reflectance wavelengths.
    EXPECT_TRUE(m[0].emissivity_is_default);
    EXPECT_EQ(m[0].emissivity.wavelengths_um, m[0].reflectance.wavelengths_um);
    ASSERT_EQ(m[0].emissivity.values.size(), 3u);
    EXPECT_DOUBLE_EQ(m[0].emissivity.values[0], 0.95);
    EXPECT_DOUBLE_EQ(m[0].emissivity.values[2], 0.6);

    EXPECT_EQ(m[1].id, "paint");
    EXPECT_EQ(m[1].name, "paint");  // defaults to the id
    EXPECT_EQ(m[1].reflectance.file.resolved, kData / "paint.txt");
    ASSERT_EQ(m[1].reflectance.wavelengths_um.size(), 3u);  // nm from the header
    EXPECT_DOUBLE_EQ(m[1].reflectance.wavelengths_um[0], 0.4);
    EXPECT_DOUBLE_EQ(m[1].reflectance.wavelengths_um[2], 1.0);
    EXPECT_EQ(m[1].reflectance.values, (std::vector<double>{0.2, 0.5, 0.6}));
    EXPECT_DOUBLE_EQ(m[1].specular.fraction, 0.3);
    EXPECT_DOUBLE_EQ(m[1].specular.roughness, 0.1);
    EXPECT_FALSE(m[1].emissivity_is_default);
    ASSERT_EQ(m[1].emissivity.wavelengths_um.size(), 2u);
    EXPECT_DOUBLE_EQ(m[1].emissivity.wavelengths_um[0], 0.4);
    EXPECT_EQ(m[1].emissivity.values, (std::vector<double>{0.9, 0.8}));
    EXPECT_DOUBLE_EQ(m[1].temperature_k, model::kDefaultTemperature_k);
}

TEST_F(SceneReaderFixture, Objects) {
    const auto& o = s_read->scene.objects;
    ASSERT_EQ(o.size(), 4u);
    EXPECT_EQ(o[0].name, "ground");
    ASSERT_TRUE(o[0].primitive);
    EXPECT_EQ(o[0].primitive->kind, model::PrimitiveKind::ground_plane);
    EXPECT_DOUBLE_EQ(o[0].primitive->size_m, 200.0);
    EXPECT_EQ(o[0].mesh.triangles.size(), 2u);
    EXPECT_EQ(o[0].material_id, "1");
    EXPECT_EQ(o[1].primitive->kind, model::PrimitiveKind::box);
    EXPECT_EQ(o[1].mesh.triangles.size(), 12u);
    EXPECT_EQ(o[1].mesh.triangle_materials, std::vector<std::uint32_t>(12, 1));
    EXPECT_EQ(o[2].primitive->kind, model::PrimitiveKind::sphere);
    EXPECT_EQ(o[2].mesh.triangles.size(), 2u * 32 * 15);
    const test::Bounds b = test::bounds_of(o[2].mesh);
    EXPECT_FLOAT_EQ(b.lo[2], 3.0f);
    EXPECT_FLOAT_EQ(b.hi[2], 7.0f);
    // The OBJ: a quad (grass, fan-triangulated) and a triangle (paint).
    EXPECT_FALSE(o[3].primitive);
    EXPECT_EQ(o[3].obj_file.resolved, kData / "car.obj");
    EXPECT_EQ(o[3].mesh.vertices_m.size(), 5u);
    ASSERT_EQ(o[3].mesh.triangles.size(), 3u);
    EXPECT_EQ(o[3].mesh.triangle_materials, (std::vector<std::uint32_t>{0, 0, 1}));
    EXPECT_EQ(o[3].mesh.triangles[2], (std::array<std::uint32_t, 3>{0, 1, 4}));
}

TEST_F(SceneReaderFixture, Instances) {
    const auto& in = s_read->scene.instances;
    ASSERT_EQ(in.size(), 6u);
    // ground: no instances key -> one identity instance named after the object.
    EXPECT_EQ(in[0].object_index, 0u);
    EXPECT_EQ(in[0].name, "ground");
    EXPECT_FALSE(in[0].dynamic());
    EXPECT_EQ(in[0].transform.scale, (std::array<double, 3>{1, 1, 1}));

    EXPECT_EQ(in[1].object_index, 1u);
    EXPECT_EQ(in[1].name, "crate_a");
    EXPECT_EQ(in[1].tags, (std::vector<std::string>{"cargo", "::IMPORTANT::crate"}));
    EXPECT_TRUE(in[1].important);
    EXPECT_EQ(in[1].transform.translation_m, (std::array<double, 3>{10, 0, 0}));
    EXPECT_DOUBLE_EQ(in[1].transform.rotation_rad[2], std::numbers::pi / 2);
    EXPECT_EQ(in[1].transform.rotation_order, "zyx");
    EXPECT_EQ(in[1].transform.scale, (std::array<double, 3>{2, 2, 2}));
    EXPECT_FALSE(in[1].transform.matrix);

    EXPECT_EQ(in[2].name, "crate_b");
    EXPECT_FALSE(in[2].important);
    ASSERT_TRUE(in[2].transform.matrix);
    EXPECT_DOUBLE_EQ((*in[2].transform.matrix)[3], 5.0);
    EXPECT_DOUBLE_EQ((*in[2].transform.matrix)[11], 7.0);

    EXPECT_EQ(in[3].name, "ball");
    EXPECT_EQ(in[3].object_index, 2u);

    EXPECT_EQ(in[4].name, "::IMPORTANT::car");
    EXPECT_TRUE(in[4].important);
    ASSERT_TRUE(in[4].dynamic());
    EXPECT_EQ(in[4].motion_file.resolved, kData.parent_path() / "motion" / "straight.motion");
    ASSERT_TRUE(in[4].motion->flexible);
    EXPECT_EQ(in[4].motion->flexible->location.type, model::LocationEngineType::straight);

    EXPECT_EQ(in[5].name, "car_inline");
    ASSERT_TRUE(in[5].dynamic());
    EXPECT_TRUE(in[5].motion_file.empty());
    ASSERT_TRUE(in[5].motion->flexible);
    EXPECT_EQ(in[5].motion->flexible->location.type, model::LocationEngineType::fixed);
    EXPECT_EQ(in[5].motion->flexible->location.location.xyz_m, (std::array<double, 3>{1, 2, 3}));
}

// ---- bad inputs -----------------------------------------------------------------------------

TEST(SceneReaderErrors, BadYamlSyntax) {
    TempDir dir;
    const Read read = read_text(dir, "origin:\n  latitude: 1\n  longitude: [1, 2\nobjects: []\n");
    ASSERT_TRUE(read.diagnostics.has_errors());
    const Diagnostic& d = read.diagnostics.items()[0];
    EXPECT_THAT(d.message, HasSubstr("invalid YAML"));
    EXPECT_GE(d.where.line, 3);
    EXPECT_LE(d.where.line, 4);
}

TEST(SceneReaderErrors, NestingTooDeep) {
    // 5000 nested lists: yaml-cpp stops at 2000 levels with the message "bad file".
    TempDir dir;
    const Read read =
        read_text(dir, "objects: " + std::string(5000, '[') + std::string(5000, ']') + "\n");
    ASSERT_EQ(read.diagnostics.error_count(), 1u);
    const Diagnostic& d = read.diagnostics.items()[0];
    EXPECT_EQ(d.message,
              "invalid YAML: nested deeper than 2000 levels, expected a document a few levels "
              "deep");
    EXPECT_EQ(d.where.line, 1);
}

TEST(SceneReaderErrors, MissingFile) {
    Diagnostics diagnostics;
    read_yaml_scene(kData / "nope.yaml", ReadOptions{}, diagnostics);
    ASSERT_TRUE(diagnostics.has_errors());
}

TEST(SceneReaderErrors, UnknownKeyWarns) {
    TempDir dir;
    const Read read = read_text(dir, kMaterials + R"(objects:
  - primitive: disk
    material: 1
    radius: 1
    colour: red
unknown_top: 1
)");
    EXPECT_FALSE(read.diagnostics.has_errors()) << dump(read.diagnostics);
    expect_diagnostic(read, "unknown key \"colour\"", line_of(read.text, "colour"),
                      "objects[0].colour", Severity::warning);
    expect_diagnostic(read, "unknown key \"unknown_top\"", line_of(read.text, "unknown_top"),
                      "unknown_top", Severity::warning);
}

TEST(SceneReaderErrors, MissingRequiredKey) {
    TempDir dir;
    const Read read = read_text(dir, kMaterials + R"(objects:
  - primitive: sphere
    material: 1
  - primitive: box
    center: [0, 0, 0]
)");
    expect_diagnostic(read, "missing required key \"radius\"",
                      line_of(read.text, "- primitive: sphere"), "objects[0]");
    expect_diagnostic(read, "missing required key \"material\"",
                      line_of(read.text, "- primitive: box"), "objects[1]");
    expect_diagnostic(read, "missing required key \"lower\"",
                      line_of(read.text, "- primitive: box"), "objects[1]");
    expect_diagnostic(read, "unknown key \"center\"", line_of(read.text, "center"),
                      "objects[1].center", Severity::warning);
}

TEST(SceneReaderErrors, NonNumeric) {
    TempDir dir;
    const Read read = read_text(dir, R"(origin:
  latitude: north
  longitude: 2
materials:
  - id: 1
    reflectance: {wavelengths: [0.4, abc], values: [0.1, 0.2]}
objects: []
)");
    expect_diagnostic(read, "expected a finite number, got \"north\"", 2, "origin.latitude");
    expect_diagnostic(read, "expected a finite number, got \"abc\"", 6,
                      "materials[0].reflectance.wavelengths[1]");
}

TEST(SceneReaderErrors, ReflectanceOutOfRange) {
    TempDir dir;
    const Read read = read_text(dir, R"(materials:
  - id: 1
    reflectance:
      wavelengths: [0.4, 0.7]
      values: [0.5, 1.2]
objects: []
)");
    expect_diagnostic(read, "reflectance 1.2 is outside [0, 1]", 5,
                      "materials[0].reflectance.values[1]");
}

TEST(SceneReaderMaterials, ALeafsTransmittanceAndKirchhoffsEmissivity) {
    // A thin sheet: `transmittance` beside `reflectance`; the default emissivity is
    // 1 − ρ − τ at every wavelength of either curve.
    TempDir dir;
    const Read read = read_text(dir, R"(materials:
  - id: leaf
    reflectance: {wavelengths: [0.4, 0.7, 0.8], values: [0.1, 0.1, 0.5]}
    transmittance: {wavelengths: [0.4, 0.75, 0.8], values: [0.05, 0.1, 0.45]}
objects: []
)");
    EXPECT_EQ(read.diagnostics.items().size(), 0u) << dump(read.diagnostics);
    ASSERT_EQ(read.scene.materials.size(), 1u);
    const model::Material& leaf = read.scene.materials[0];
    EXPECT_EQ(leaf.transmittance.wavelengths_um, (std::vector<double>{0.4, 0.75, 0.8}));
    EXPECT_EQ(leaf.transmittance.values, (std::vector<double>{0.05, 0.1, 0.45}));
    EXPECT_TRUE(leaf.emissivity_is_default);
    EXPECT_EQ(leaf.emissivity.wavelengths_um, (std::vector<double>{0.4, 0.7, 0.75, 0.8}));
    ASSERT_EQ(leaf.emissivity.values.size(), 4u);
    EXPECT_DOUBLE_EQ(leaf.emissivity.values[0], 0.85);
    EXPECT_NEAR(leaf.emissivity.values[2], 1.0 - 0.3 - 0.1, 1e-12);  // ρ(0.75) = 0.3
    EXPECT_NEAR(leaf.emissivity.values[3], 0.05, 1e-12);

    const Read bad = read_text(dir, R"(materials:
  - id: leaf
    reflectance: {wavelengths: [0.4, 0.7], values: [0.1, 0.1]}
    transmittance: {wavelengths: [0.4, 0.7], values: [0.05, 1.3]}
objects: []
)");
    expect_diagnostic(bad, "transmittance 1.3 is outside [0, 1]", 4,
                      "materials[0].transmittance.values[1]");
}

TEST(SceneReaderMaterials, WardAndRossLiModels) {
    // `ward` replaces the reflectance (spectrally constant diffuse + specular); `ross_li`
    // shapes the reflectance curve (f_iso); alpha_y defaults to alpha_x.
    TempDir dir;
    const Read read = read_text(dir, R"(materials:
  - id: metal
    ward: {diffuse: 0.1, specular: 0.5, alpha_x: 0.2}
  - id: field
    reflectance: {wavelengths: [0.4, 0.8], values: [0.05, 0.4]}
    ross_li: {volumetric: 0.6, geometric: 0.12}
objects: []
)");
    EXPECT_EQ(read.diagnostics.items().size(), 0u) << dump(read.diagnostics);
    ASSERT_EQ(read.scene.materials.size(), 2u);
    const model::Material& metal = read.scene.materials[0];
    EXPECT_EQ(metal.model, model::ReflectionModel::ward);
    EXPECT_DOUBLE_EQ(metal.ward.alpha_y, 0.2);
    EXPECT_EQ(metal.reflectance.values, (std::vector<double>{0.6, 0.6}));
    EXPECT_TRUE(metal.emissivity_is_default);
    EXPECT_NEAR(metal.emissivity.values[0], 0.4, 1e-12);
    const model::Material& field = read.scene.materials[1];
    EXPECT_EQ(field.model, model::ReflectionModel::ross_li);
    EXPECT_DOUBLE_EQ(field.ross_li.volumetric, 0.6);
    EXPECT_DOUBLE_EQ(field.ross_li.geometric, 0.12);

    const Read both = read_text(dir, R"(materials:
  - id: metal
    ward: {diffuse: 0.1, specular: 0.5, alpha_x: 0.2}
    reflectance: {wavelengths: [0.4, 0.8], values: [0.05, 0.4]}
objects: []
)");
    expect_diagnostic(both,
                      "a Ward material's reflectance is its diffuse + specular weights; remove "
                      "\"reflectance\"",
                      4, "materials[0].reflectance");
    const Read lobe = read_text(dir, R"(materials:
  - id: field
    reflectance: {wavelengths: [0.4, 0.8], values: [0.05, 0.4]}
    ross_li: {volumetric: 0.6, geometric: 0.12}
    specular: {fraction: 0.2, roughness: 0.1}
objects: []
)");
    expect_diagnostic(lobe,
                      "\"specular\" is the Lambertian model's lobe; a \"ross_li\" material has "
                      "its own",
                      5, "materials[0].specular");
    const Read missing = read_text(dir, R"(materials:
  - id: metal
    ward: {diffuse: 0.1, alpha_x: 0.2}
objects: []
)");
    expect_diagnostic(missing, "missing required key \"specular\"", 3, "materials[0].ward");
}

TEST(SceneReaderMaterials, StraightTransmission) {
    TempDir dir;
    const Read read = read_text(dir, R"(materials:
  - id: pane
    reflectance: {wavelengths: [0.4, 0.8], values: [0.04, 0.04]}
    transmittance: {wavelengths: [0.4, 0.8], values: [0.9, 0.9]}
    transmission: straight
  - id: odd
    reflectance: {wavelengths: [0.4, 0.8], values: [0.04, 0.04]}
    transmission: sideways
objects: []
)");
    ASSERT_EQ(read.scene.materials.size(), 2u);
    EXPECT_TRUE(read.scene.materials[0].straight_transmission);
    expect_diagnostic(read, "transmission \"sideways\" is neither diffuse nor straight", 8,
                      "materials[1].transmission");
}

TEST(SceneReaderMaterials, DoubleSided) {
    TempDir dir;
    const Read read = read_text(dir, R"(materials:
  - {id: a, reflectance: {wavelengths: [0.4, 0.7], values: [0.1, 0.1]}}
  - {id: b, reflectance: {wavelengths: [0.4, 0.7], values: [0.1, 0.1]}, double_sided: false}
  - {id: c, reflectance: {wavelengths: [0.4, 0.7], values: [0.1, 0.1]}, double_sided: maybe}
objects: []
)");
    ASSERT_EQ(read.scene.materials.size(), 3u);
    EXPECT_TRUE(read.scene.materials[0].double_sided);
    EXPECT_FALSE(read.scene.materials[1].double_sided);
    expect_diagnostic(read, "expected true or false", 4, "materials[2].double_sided");
}

TEST(SceneReaderMaterials, ThermInSiUnitsAndItsErrorsAtTheirKeys) {
    TempDir dir;
    const Read read = read_text(dir, R"(materials:
  - id: asphalt
    reflectance: {wavelengths: [0.4, 0.7], values: [0.1, 0.1]}
    therm: {specific_heat_j_per_kg_k: 920, density_kg_per_m3: 2300, conductivity_w_per_m_k: 0.75,
            thickness_m: 0.1, exposed_area: 0.5, solar_absorptance: 0.9}
  - id: leaf
    reflectance: {wavelengths: [0.4, 0.7], values: [0.1, 0.1]}
    therm: {specific_heat_j_per_kg_k: 3500, density_kg_per_m3: 700, conductivity_w_per_m_k: 0,
            thickness_m: 0}
  - id: bad
    reflectance: {wavelengths: [0.4, 0.7], values: [0.1, 0.1]}
    therm: {specific_heat_j_per_kg_k: 0, density_kg_per_m3: 2300, conductivity_w_per_m_k: -1,
            exposed_area: 2, emissivity: 0.9}
objects: []
)");
    ASSERT_EQ(read.scene.materials.size(), 3u);
    const auto& asphalt = read.scene.materials[0].therm;
    ASSERT_TRUE(asphalt.has_value());
    EXPECT_DOUBLE_EQ(asphalt->specific_heat_j_per_kg_k, 920.0);
    EXPECT_DOUBLE_EQ(asphalt->density_kg_per_m3, 2300.0);
    EXPECT_DOUBLE_EQ(asphalt->conductivity_w_per_m_k, 0.75);
    EXPECT_DOUBLE_EQ(asphalt->thickness_m, 0.1);
    EXPECT_DOUBLE_EQ(asphalt->exposed_area, 0.5);
    EXPECT_EQ(asphalt->solar_absorptance, 0.9);
    EXPECT_FALSE(asphalt->thermal_emissivity.has_value());  // from the emissivity curve
    EXPECT_EQ(asphalt->where.line, 4);
    // A face without storage (a leaf): zero thickness and conductivity; all of it exposed.
    ASSERT_TRUE(read.scene.materials[1].therm.has_value());
    EXPECT_DOUBLE_EQ(read.scene.materials[1].therm->thickness_m, 0.0);
    EXPECT_DOUBLE_EQ(read.scene.materials[1].therm->exposed_area, 1.0);
    // Every bad key is reported at its own key, and the material keeps no THERM.
    EXPECT_FALSE(read.scene.materials[2].therm.has_value());
    expect_diagnostic(read, "specific_heat_j_per_kg_k 0 is not > 0", 12,
                      "materials[2].therm.specific_heat_j_per_kg_k");
    expect_diagnostic(read, "conductivity_w_per_m_k -1 is negative", 12,
                      "materials[2].therm.conductivity_w_per_m_k");
    expect_diagnostic(read, "exposed_area 2 is outside [0, 1]", 13,
                      "materials[2].therm.exposed_area");
    expect_diagnostic(read, "missing required key \"thickness_m\"", 12, "materials[2].therm");
    expect_diagnostic(read, "unknown key \"emissivity\" (ignored)", 13,
                      "materials[2].therm.emissivity", Severity::warning);
}

TEST(SceneReaderErrors, ReflectanceFileErrors) {
    TempDir dir;
    write(dir, "r.txt", "# units: um\n0.4 0.1\n0.5 x\n0.6 1.5\n");
    const Read read = read_text(dir, R"(materials:
  - id: 1
    reflectance: {file: r.txt}
objects: []
)");
    expect_diagnostic(read, "expected two numbers, got \"0.5\" and \"x\"", 3,
                      "materials[0].reflectance", Severity::error, (dir / "r.txt").string());
}

TEST(SceneReaderErrors, MaterialIds) {
    TempDir dir;
    const Read read = read_text(dir, kMaterials + R"(  - id: 1
    name: other
    reflectance: {wavelengths: [0.4], values: [0.1]}
objects:
  - primitive: disk
    material: 9
    radius: 1
)");
    expect_diagnostic(read, "duplicate material id \"1\"", 5, "materials[1].id");
    expect_diagnostic(read, "unknown material id \"9\"", line_of(read.text, "material: 9"),
                      "objects[0].material");
}

TEST(SceneReaderErrors, InstanceErrors) {
    TempDir dir;
    const Read read = read_text(dir, kMaterials + R"(objects:
  - primitive: disk
    material: 1
    radius: 1
    instances:
      - matrix: [1, 0, 0]
      - rotation_order: xyy
      - translation: [1, 2, 3]
        motion: a.motion
      - scale: 0
)");
    expect_diagnostic(read, "matrix has 3 values, expected 16", line_of(read.text, "matrix"),
                      "objects[0].instances[0].matrix");
    expect_diagnostic(read, "not a permutation of xyz", line_of(read.text, "rotation_order"),
                      "objects[0].instances[1].rotation_order");
    expect_diagnostic(read, "takes no static transform", line_of(read.text, "- translation"),
                      "objects[0].instances[2]");
    expect_diagnostic(read, "scale must be non-zero", line_of(read.text, "scale: 0"),
                      "objects[0].instances[3].scale");
}

TEST(SceneReaderErrors, InlineMotionErrorAtYamlLine) {
    TempDir dir;
    const Read read = read_text(dir, kMaterials + R"(objects:
  - primitive: disk
    material: 1
    radius: 1
    instances:
      - flex_motion: |
          <motion type="flexible">
            <locationengine type="warp"/>
            <orientationengine type="velocity"/>
          </motion>
)");
    ASSERT_TRUE(read.diagnostics.has_errors());
    const Diagnostic& d = read.diagnostics.items()[0];
    EXPECT_EQ(d.where.file, read.file);
    EXPECT_EQ(d.where.line, line_of(read.text, "warp")) << d.text();
    EXPECT_THAT(d.where.element, HasSubstr("objects[0].instances[0].flex_motion")) << d.text();
}

// ---- OBJ ------------------------------------------------------------------------------------

Read read_obj(const TempDir& dir, const std::string& obj) {
    write(dir, "m.obj", obj);
    return read_text(dir, kMaterials + "objects:\n  - obj: m.obj\n");
}

TEST(SceneObj, NanVertex) {
    TempDir dir;
    const Read read = read_obj(dir, "v 0 0 0\nv 1 nan 0\nv 0 1 0\nusemtl grass\nf 1 2 3\n");
    expect_diagnostic(read, "vertex y \"nan\" is not a finite number", 2, "v", Severity::error,
                      (dir / "m.obj").string());
}

TEST(SceneObj, IndexOutOfRange) {
    TempDir dir;
    const Read read = read_obj(dir, "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl grass\nf 1 2 9\n");
    expect_diagnostic(read, "vertex index 9 is out of range (3 vertices so far)", 5, "f",
                      Severity::error, (dir / "m.obj").string());
}

TEST(SceneObj, UnknownMaterial) {
    TempDir dir;
    const Read read = read_obj(dir, "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl steel\nf 1 2 3\n");
    expect_diagnostic(read, "unknown material \"steel\"", 4, "usemtl", Severity::error,
                      (dir / "m.obj").string());
}

TEST(SceneObj, NoMaterial) {
    TempDir dir;
    const Read read = read_obj(dir, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    expect_diagnostic(read, "face has no material", 4, "f", Severity::error,
                      (dir / "m.obj").string());
}

TEST(SceneObj, EmptyMesh) {
    TempDir dir;
    const Read read = read_obj(dir, "# nothing\nv 0 0 0\n");
    expect_diagnostic(read, "mesh has no triangles", 0, "", Severity::error,
                      (dir / "m.obj").string());
}

TEST(SceneObj, DefaultMaterialAndDegenerate) {
    TempDir dir;
    write(dir, "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 4\n");
    const Read read = read_text(dir, kMaterials + "objects:\n  - obj: m.obj\n    material: 1\n");
    EXPECT_FALSE(read.diagnostics.has_errors()) << dump(read.diagnostics);
    ASSERT_EQ(read.scene.objects.size(), 1u);
    EXPECT_EQ(read.scene.objects[0].mesh.triangles.size(), 1u);
    EXPECT_EQ(read.diagnostics.warning_count(), 1u);
}

}  // namespace scene_reader_test
}  // namespace glint::yaml
