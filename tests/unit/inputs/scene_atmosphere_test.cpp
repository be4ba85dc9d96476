// SPDX-License-Identifier: Apache-2.0
// Tests of a simulation's atmosphere and merged scene (glint/inputs/scene_atmosphere.h):
// the BasicAtmosphere file (YAML and .atm), the embedded parametric default when none is
// named, missing files and extra plugins; scenes merged in scene_list order (materials by
// id with their triangles remapped, objects, instances, origin), duplicate ids naming both
// files, a shared .mat merged once, a differing origin, offsets and missing files; and a
// .jsim read end to end.
#include "glint/inputs/scene_atmosphere.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "glint/dirsig/readers.h"
#include "glint/test/diagnostics.h"
#include "glint/test/temp_dir.h"

namespace glint::inputs {
namespace scene_atmosphere_test {

namespace fs = std::filesystem;
using glint::test::diagnostics_text;
using glint::test::only_error;
using glint::test::TempDir;
using ::testing::HasSubstr;

const fs::path kData = fs::path(GLINT_TEST_DATA_DIR);

void write(const fs::path& path, const std::string& text) {
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

model::FileRef ref_to(const fs::path& path, const std::string& key) {
    return model::FileRef{path.string(), path, ErrorContext{"sim.jsim", 3, key}};
}

model::Plugin atmosphere_plugin(const fs::path& path) {
    model::Plugin plugin;
    plugin.name = "BasicAtmosphere";
    plugin.basic_atmosphere =
        model::BasicAtmosphereInputs{ref_to(path, "plugin_list[0].inputs.atmosphere_filename")};
    plugin.where = ErrorContext{"sim.jsim", 2, "plugin_list[0]"};
    return plugin;
}

model::Simulation with_scenes(const std::vector<fs::path>& files) {
    model::Simulation simulation;
    simulation.file = "sim.jsim";
    for (std::size_t i = 0; i < files.size(); ++i) {
        simulation.scenes.push_back(model::SceneEntry{
            ref_to(files[i], "scene_list[" + std::to_string(i) + "].inputs"), {}, {}});
    }
    return simulation;
}

/// A YAML scene of one material `id` and a box of it; `origin` is inserted as given.
std::string yaml_scene(const std::string& id, const std::string& origin = {}) {
    return origin + "materials:\n  - id: " + id +
           "\n    reflectance: {wavelengths: [0.4, 0.7], values: [0.1, 0.2]}\n"
           "objects:\n  - name: box_" +
           id + "\n    primitive: box\n    material: " + id +
           "\n    lower: [0, 0, 0]\n    upper: [1, 1, 1]\n";
}

const std::string kOrigin = "origin: {latitude: 43, longitude: -77.6, altitude: 150}\n";

// ---- atmosphere -----------------------------------------------------------------------------

TEST(SimulationAtmosphere, ReadsTheBasicAtmosphereFile) {
    model::Simulation simulation;
    simulation.plugins.push_back(atmosphere_plugin(kData / "atmosphere" / "parametric.yaml"));
    Diagnostics diagnostics;
    const model::Atmosphere a = read_simulation_atmosphere(simulation, {}, diagnostics);
    EXPECT_TRUE(diagnostics.items().empty()) << diagnostics_text(diagnostics);
    EXPECT_EQ(a.kind, model::AtmosphereKind::parametric);
    EXPECT_DOUBLE_EQ(a.parametric.aerosol_optical_depth_550, 0.2);
    EXPECT_EQ(a.where.file, (kData / "atmosphere" / "parametric.yaml").string());

    simulation.plugins[0] = atmosphere_plugin(kData / "atmosphere" / "simple.atm");
    Diagnostics d2;
    const model::Atmosphere atm = read_simulation_atmosphere(simulation, {}, d2);
    EXPECT_FALSE(d2.has_errors()) << diagnostics_text(d2);
    EXPECT_EQ(atm.kind, model::AtmosphereKind::simple);
    EXPECT_DOUBLE_EQ(atm.simple.apparent_sky_temperature_k, 260.0);

    simulation.plugins[0] = atmosphere_plugin(kData / "atmosphere" / "tabulated.yaml");
    Diagnostics d3;
    const model::Atmosphere table = read_simulation_atmosphere(simulation, {}, d3);
    EXPECT_TRUE(d3.items().empty()) << diagnostics_text(d3);
    EXPECT_EQ(table.kind, model::AtmosphereKind::tabulated);
    EXPECT_EQ(table.tabulated.wavelengths_um.size(), 4u);
}

TEST(SimulationAtmosphere, DefaultsToParametricWithADebugMessageOnly) {
    model::Simulation simulation;
    simulation.file = "plain.jsim";
    std::vector<std::string> messages;
    const Log log(
        [&messages](LogLevel level, const std::string& message) {
            messages.push_back(std::string(log_level_name(level)) + ": " + message);
        },
        LogLevel::debug);
    Diagnostics diagnostics;
    const model::Atmosphere a = read_simulation_atmosphere(simulation, {}, diagnostics, log);
    EXPECT_TRUE(diagnostics.items().empty()) << diagnostics_text(diagnostics);
    EXPECT_EQ(a.kind, model::AtmosphereKind::parametric);
    const model::ParametricAtmosphere defaults;
    EXPECT_EQ(a.parametric.aerosol_optical_depth_550, defaults.aerosol_optical_depth_550);
    EXPECT_EQ(a.parametric.sea_level_pressure_hpa, defaults.sea_level_pressure_hpa);
    EXPECT_EQ(a.parametric.air_temperature_k, defaults.air_temperature_k);
    EXPECT_EQ(a.where.file, "plain.jsim");
    EXPECT_EQ(a.source, "default");  // the outputs' "glint atmosphere source"
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_THAT(messages[0], HasSubstr("debug: plain.jsim: no BasicAtmosphere plugin: using the "
                                       "default atmosphere (parametric"));

    const model::Atmosphere d = default_atmosphere();
    EXPECT_EQ(d.kind, model::AtmosphereKind::parametric);
    EXPECT_EQ(d.parametric.angstrom_exponent, defaults.angstrom_exponent);
}

TEST(SimulationAtmosphere, AnAtmospherePluginGlintDoesNotRunIsNamedAsTheReason) {
    model::Simulation simulation;
    simulation.file = "plain.jsim";
    EXPECT_EQ(default_atmosphere_reason(simulation), "plain.jsim names none");
    EXPECT_EQ(unsupported_atmosphere_plugin(simulation), nullptr);
    model::Plugin ephemeris;
    ephemeris.name = "SpiceEphemeris";
    model::Plugin atmosphere;
    atmosphere.name = "NewAtmosphere";
    simulation.plugins = {ephemeris, atmosphere};
    EXPECT_EQ(unsupported_atmosphere_plugin(simulation), &simulation.plugins[1]);
    EXPECT_EQ(default_atmosphere_reason(simulation),
              "plain.jsim's NewAtmosphere plugin is not supported");

    std::vector<std::string> messages;
    const Log log(
        [&messages](LogLevel, const std::string& message) { messages.push_back(message); },
        LogLevel::debug);
    Diagnostics diagnostics;
    EXPECT_EQ(read_simulation_atmosphere(simulation, {}, diagnostics, log).kind,
              model::AtmosphereKind::parametric);
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_THAT(messages[0], HasSubstr("plain.jsim: no BasicAtmosphere plugin (its NewAtmosphere "
                                       "plugin is not supported): using the default atmosphere"));
}

TEST(AtmosphereOverride, ParsesNoneParametricAndFiles) {
    EXPECT_EQ(parse_atmosphere_override("none").kind, AtmosphereOverride::Kind::none);
    EXPECT_EQ(parse_atmosphere_override("parametric").kind, AtmosphereOverride::Kind::parametric);
    const AtmosphereOverride file = parse_atmosphere_override("./none");
    EXPECT_EQ(file.kind, AtmosphereOverride::Kind::file);
    EXPECT_EQ(file.file, fs::path("./none"));
    for (const char* bad : {"", "-"}) {
        try {
            (void)parse_atmosphere_override(bad);
            ADD_FAILURE() << "accepted " << bad;
        } catch (const Error& error) {
            EXPECT_EQ(error.category(), ErrorCategory::usage);
            EXPECT_THAT(error.message(), HasSubstr("--atmosphere: expected none, parametric or an "
                                                   "atmosphere file"));
        }
    }
}

TEST(AtmosphereOverride, GivesNoneTheDefaultOrTheFile) {
    Diagnostics diagnostics;
    const model::Atmosphere none =
        read_atmosphere_override({AtmosphereOverride::Kind::none, {}}, {}, diagnostics);
    EXPECT_EQ(none.kind, model::AtmosphereKind::none);
    const model::Atmosphere parametric =
        read_atmosphere_override({AtmosphereOverride::Kind::parametric, {}}, {}, diagnostics);
    EXPECT_EQ(parametric.kind, model::AtmosphereKind::parametric);
    EXPECT_EQ(parametric.parametric.aerosol_optical_depth_550,
              model::ParametricAtmosphere{}.aerosol_optical_depth_550);
    EXPECT_TRUE(diagnostics.items().empty()) << diagnostics_text(diagnostics);

    TempDir dir;
    write(dir / "clear.yaml", "model: parametric\naerosol_optical_depth_550: 0.3\n");
    const model::Atmosphere file = read_atmosphere_override(
        {AtmosphereOverride::Kind::file, dir / "clear.yaml"}, {}, diagnostics);
    EXPECT_TRUE(diagnostics.items().empty()) << diagnostics_text(diagnostics);
    EXPECT_EQ(file.kind, model::AtmosphereKind::parametric);
    EXPECT_EQ(file.parametric.aerosol_optical_depth_550, 0.3);

    (void)read_atmosphere_override({AtmosphereOverride::Kind::file, dir / "nothere.yaml"}, {},
                                   diagnostics);
    const Diagnostic missing = only_error(diagnostics);
    EXPECT_EQ(missing.where.file, "--atmosphere");
    EXPECT_EQ(missing.message,
              "atmosphere file does not exist: " + (dir / "nothere.yaml").string());
}

TEST(SimulationAtmosphere, MissingFileIsAnErrorAtItsKey) {
    TempDir dir;
    model::Simulation simulation;
    simulation.plugins.push_back(atmosphere_plugin(dir / "nope.atm"));
    Diagnostics diagnostics;
    const model::Atmosphere a = read_simulation_atmosphere(simulation, {}, diagnostics);
    const Diagnostic e = only_error(diagnostics);
    EXPECT_EQ(e.message, "atmosphere file does not exist: " + (dir / "nope.atm").string());
    EXPECT_EQ(e.where.file, "sim.jsim");
    EXPECT_EQ(e.where.line, 3);
    EXPECT_EQ(e.where.element, "plugin_list[0].inputs.atmosphere_filename");
    EXPECT_EQ(a.kind, model::AtmosphereKind::parametric);

    simulation.plugins[0] = atmosphere_plugin(dir.path());
    Diagnostics d2;
    read_simulation_atmosphere(simulation, {}, d2);
    EXPECT_THAT(only_error(d2).message, HasSubstr("atmosphere path is a folder"));
}

TEST(SimulationAtmosphere, ReaderErrorsAndASecondPlugin) {
    TempDir dir;
    write(dir / "bad.yaml", "model: cloudy\n");
    model::Simulation simulation;
    simulation.plugins.push_back(atmosphere_plugin(dir / "bad.yaml"));
    simulation.plugins.push_back(atmosphere_plugin(kData / "atmosphere" / "none.yaml"));
    simulation.plugins[1].where = ErrorContext{"sim.jsim", 7, "plugin_list[1]"};
    Diagnostics diagnostics;
    read_simulation_atmosphere(simulation, {}, diagnostics);
    const Diagnostic e = only_error(diagnostics);
    EXPECT_THAT(e.message, HasSubstr("unknown atmosphere model 'cloudy'"));
    EXPECT_EQ(e.where.file, (dir / "bad.yaml").string());
    EXPECT_EQ(e.where.line, 1);
    ASSERT_EQ(diagnostics.warning_count(), 1u);
    const Diagnostic& w = diagnostics.items().front().severity == Diagnostic::Severity::warning
                              ? diagnostics.items().front()
                              : diagnostics.items().back();
    EXPECT_EQ(w.where.line, 7);
    EXPECT_THAT(w.message, HasSubstr("plugin_list[1] is another BasicAtmosphere"));
}

// ---- scenes ---------------------------------------------------------------------------------

TEST(SimulationScene, MergesScenesInOrder) {
    TempDir dir;
    write(dir / "a.yaml", kOrigin + yaml_scene("a"));
    write(dir / "b.yaml", yaml_scene("b"));
    Diagnostics diagnostics;
    const model::Scene scene =
        read_simulation_scene(with_scenes({dir / "a.yaml", dir / "b.yaml"}), {}, diagnostics);
    EXPECT_TRUE(diagnostics.items().empty()) << diagnostics_text(diagnostics);
    EXPECT_EQ(scene.file, (dir / "a.yaml").string());
    ASSERT_TRUE(scene.origin);
    EXPECT_DOUBLE_EQ(scene.origin->latitude_deg, 43.0);
    ASSERT_EQ(scene.materials.size(), 2u);
    EXPECT_EQ(scene.materials[1].id, "b");
    ASSERT_EQ(scene.objects.size(), 2u);
    EXPECT_EQ(scene.objects[1].name, "box_b");
    EXPECT_EQ(scene.objects[1].mesh.triangle_materials, std::vector<std::uint32_t>(12, 1u));
    ASSERT_EQ(scene.instances.size(), 2u);
    EXPECT_EQ(scene.instances[1].object_index, 1u);
}

TEST(SimulationScene, YamlAndDirsigScenesMerge) {
    TempDir dir;
    write(dir / "extra.yaml", yaml_scene("paint"));
    Diagnostics diagnostics;
    const model::Scene scene = read_simulation_scene(
        with_scenes({kData / "dirsig_scene" / "site.scene", dir / "extra.yaml"}), {}, diagnostics);
    EXPECT_TRUE(diagnostics.items().empty()) << diagnostics_text(diagnostics);
    ASSERT_EQ(scene.materials.size(), 3u);
    ASSERT_EQ(scene.objects.size(), 5u);
    EXPECT_EQ(scene.objects[4].mesh.triangle_materials[0], 2u);
    EXPECT_EQ(scene.instances.size(), 7u);
    EXPECT_EQ(scene.instances.back().object_index, 4u);
}

TEST(SimulationScene, DuplicateMaterialIdNamesBothFiles) {
    TempDir dir;
    write(dir / "a.yaml", yaml_scene("1"));
    write(dir / "b.yaml", "# second\n" + yaml_scene("1"));
    Diagnostics diagnostics;
    const model::Scene scene =
        read_simulation_scene(with_scenes({dir / "a.yaml", dir / "b.yaml"}), {}, diagnostics);
    const Diagnostic e = only_error(diagnostics);
    EXPECT_EQ(e.message,
              "material id \"1\" is already defined at " + (dir / "a.yaml").string() + ":2");
    EXPECT_EQ(e.where.file, (dir / "b.yaml").string());
    EXPECT_EQ(e.where.line, 3);
    EXPECT_EQ(e.where.element, "materials[0]");
    ASSERT_EQ(scene.materials.size(), 1u);
    ASSERT_EQ(scene.objects.size(), 2u);
    EXPECT_EQ(scene.objects[1].mesh.triangle_materials[0], 0u);  // bound to the first
}

TEST(SimulationScene, SharedMaterialFileIsMergedOnce) {
    Diagnostics diagnostics;
    const fs::path site = kData / "dirsig_scene" / "site.scene";
    const model::Scene scene = read_simulation_scene(with_scenes({site, site}), {}, diagnostics);
    EXPECT_TRUE(diagnostics.items().empty()) << diagnostics_text(diagnostics);
    EXPECT_EQ(scene.materials.size(), 2u);
    EXPECT_EQ(scene.objects.size(), 8u);
    EXPECT_EQ(scene.instances.size(), 12u);
    EXPECT_EQ(scene.instances.back().object_index, 7u);
}

TEST(SimulationScene, LaterDifferentOriginIsAWarning) {
    TempDir dir;
    write(dir / "a.yaml", kOrigin + yaml_scene("a"));
    write(dir / "b.yaml", "origin: {latitude: 44, longitude: -77.6}\n" + yaml_scene("b"));
    write(dir / "c.yaml", kOrigin + yaml_scene("c"));
    Diagnostics diagnostics;
    const model::Scene scene = read_simulation_scene(
        with_scenes({dir / "a.yaml", dir / "b.yaml", dir / "c.yaml"}), {}, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors()) << diagnostics_text(diagnostics);
    ASSERT_EQ(diagnostics.warning_count(), 1u) << diagnostics_text(diagnostics);
    const Diagnostic& w = diagnostics.items().front();
    EXPECT_EQ(w.where.file, (dir / "b.yaml").string());
    EXPECT_EQ(w.where.line, 1);
    EXPECT_THAT(w.message, HasSubstr("scene origin (latitude 44 deg, longitude -77.6 deg, "
                                     "altitude 0 m) differs from the origin set by " +
                                     (dir / "a.yaml").string() + ":1"));
    ASSERT_TRUE(scene.origin);
    EXPECT_DOUBLE_EQ(scene.origin->latitude_deg, 43.0);
    EXPECT_EQ(scene.objects.size(), 3u);
}

TEST(SimulationScene, MissingFilesOffsetsAndEmptyList) {
    TempDir dir;
    write(dir / "a.yaml", yaml_scene("a"));
    model::Simulation simulation = with_scenes({dir / "nope.scene", dir / "a.yaml"});
    Diagnostics diagnostics;
    const model::Scene scene = read_simulation_scene(simulation, {}, diagnostics);
    const Diagnostic e = only_error(diagnostics);
    EXPECT_EQ(e.message, "scene file does not exist: " + (dir / "nope.scene").string());
    EXPECT_EQ(e.where.element, "scene_list[0].inputs");
    EXPECT_EQ(scene.objects.size(), 1u);  // the others are still read

    simulation = with_scenes({dir / "a.yaml", dir / "a.yaml"});
    simulation.scenes[0].offset = "0, 0,0";
    simulation.scenes[1].offset = "10,0,0";
    Diagnostics d2;
    read_simulation_scene(simulation, {}, d2);
    ASSERT_EQ(d2.warning_count(), 1u) << diagnostics_text(d2);
    EXPECT_EQ(d2.items().front().message,
              "scene offset \"10,0,0\" is read, not applied: the scene is placed at its own "
              "origin");
    EXPECT_EQ(d2.items().front().where.element, "scene_list[1].inputs");  // no key position
    // Read from a .jsim, the warning is at the offset's own key.
    simulation.scenes[1].offset_where = ErrorContext{"sim.jsim", 3, "[0].scene_list[1].offset"};
    Diagnostics d2b;
    read_simulation_scene(simulation, {}, d2b);
    ASSERT_EQ(d2b.warning_count(), 1u) << diagnostics_text(d2b);
    EXPECT_EQ(d2b.items().front().where.element, "[0].scene_list[1].offset");
    EXPECT_EQ(d2b.items().front().where.line, 3);
    EXPECT_EQ(d2.error_count(), 0u);  // material "a" twice: the same definition

    Diagnostics d3;
    const model::Scene none = read_simulation_scene(model::Simulation{}, {}, d3);
    EXPECT_TRUE(d3.items().empty());
    EXPECT_FALSE(none.origin);
    EXPECT_TRUE(none.objects.empty());
}

TEST(SimulationInputs, ReadFromAJsim) {
    TempDir dir;
    write(dir / "scene.yaml", kOrigin + yaml_scene("a"));
    write(dir / "sky.yaml", "model: none\n");
    write(dir / "run.jsim",
          R"([{"scene_list": [{"inputs": "scene.yaml"}],
  "plugin_list": [{"name": "BasicAtmosphere", "inputs": {"atmosphere_filename": "sky.yaml"}}]}])");
    Diagnostics diagnostics;
    const std::vector<model::Simulation> sims =
        dirsig::read_jsim(dir / "run.jsim", {}, diagnostics);
    ASSERT_EQ(sims.size(), 1u) << diagnostics_text(diagnostics);
    const model::Atmosphere a = read_simulation_atmosphere(sims[0], {}, diagnostics);
    const model::Scene scene = read_simulation_scene(sims[0], {}, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors()) << diagnostics_text(diagnostics);
    EXPECT_EQ(a.kind, model::AtmosphereKind::none);
    EXPECT_EQ(scene.objects.size(), 1u);
    EXPECT_TRUE(scene.origin);
}

}  // namespace scene_atmosphere_test
}  // namespace glint::inputs
