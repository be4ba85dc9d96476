// SPDX-License-Identifier: Apache-2.0
// Unit tests of the DIRSIG4 `.sim` reader and of read_simulation's content sniffing: the
// format notes' example, referenced files that are missing (Windows paths included), missing
// and duplicated elements, the unused <options>, unknown elements and malformed XML, each
// with its message, line and element path.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "glint/dirsig/readers.h"
#include "glint/test/diagnostics.h"
#include "glint/test/temp_dir.h"

namespace glint::dirsig {
namespace sim_test {

using glint::test::TempDir;
using ::testing::HasSubstr;

const std::filesystem::path kData =
    (std::filesystem::path(GLINT_TEST_DATA_DIR) / "legacy").lexically_normal();

/// A folder holding every file example.sim names (empty files) plus `sim_text` as a.sim.
std::filesystem::path write_sim(const TempDir& dir, const std::string& sim_text) {
    for (const char* name :
         {"site.scene", "clear.atm", "cam.platform", "hover.ppd", "one_frame.tasks"}) {
        std::ofstream(dir / name) << "<x/>\n";
    }
    std::ofstream(dir / "a.sim") << sim_text;
    return dir / "a.sim";
}

using glint::test::only_error;

TEST(SimReader, ReadsTheFormatNotesExample) {
    Diagnostics diagnostics;
    const model::Simulation sim = read_sim(kData / "example.sim", ReadOptions{}, diagnostics);
    EXPECT_TRUE(diagnostics.items().empty()) << diagnostics.items().at(0).text();
    EXPECT_EQ(sim.file, (kData / "example.sim").string());
    ASSERT_EQ(sim.scenes.size(), 1u);
    EXPECT_EQ(sim.scenes[0].file.text, "./site.scene");
    EXPECT_EQ(sim.scenes[0].file.resolved, kData / "site.scene");
    EXPECT_EQ(sim.scenes[0].file.where.line, 2);
    EXPECT_EQ(sim.scenes[0].file.where.element, "simulation/scene");
    EXPECT_EQ(sim.scenes[0].offset, "");

    ASSERT_EQ(sim.plugins.size(), 2u);
    EXPECT_EQ(sim.plugins[0].name, "BasicAtmosphere");
    ASSERT_NE(sim.atmosphere(), nullptr);
    EXPECT_EQ(sim.atmosphere()->atmosphere_file.resolved, kData / "clear.atm");
    EXPECT_EQ(sim.plugins[0].inputs_json, R"({"atmosphere_filename":"./clear.atm"})");

    EXPECT_EQ(sim.basic_platform_indices(), std::vector<std::size_t>{1});
    const model::Plugin& platform = sim.plugins[1];
    EXPECT_EQ(platform.name, "BasicPlatform");
    EXPECT_EQ(platform.where.line, 4);
    ASSERT_TRUE(platform.basic_platform.has_value());
    EXPECT_EQ(platform.basic_platform->platform_file.resolved, kData / "cam.platform");
    EXPECT_EQ(platform.basic_platform->motion_file.resolved, kData / "hover.ppd");
    EXPECT_EQ(platform.basic_platform->tasks_file.resolved, kData / "one_frame.tasks");
    EXPECT_EQ(platform.basic_platform->tasks_file.where.element, "simulation/tasklist");
    EXPECT_FALSE(platform.basic_platform->output_folder.has_value());
    EXPECT_FALSE(platform.basic_platform->output_prefix.has_value());
    EXPECT_FALSE(platform.basic_platform->split_channels.has_value());  // a .sim has none
    EXPECT_EQ(sim.medium_list_json, "[]");
}

TEST(SimReader, AtmosphereAndSceneAreOptional) {
    TempDir dir;
    const auto sim_path = write_sim(dir,
                                    "<simulation>\n"
                                    "  <platform externalfile=\"cam.platform\"/>\n"
                                    "  <platformmotion externalfile=\"hover.ppd\"/>\n"
                                    "  <tasklist externalfile=\"one_frame.tasks\"/>\n"
                                    "</simulation>\n");
    Diagnostics diagnostics;
    const model::Simulation sim = read_sim(sim_path, ReadOptions{}, diagnostics);
    EXPECT_TRUE(diagnostics.items().empty());
    EXPECT_TRUE(sim.scenes.empty());
    EXPECT_EQ(sim.atmosphere(), nullptr);
    ASSERT_EQ(sim.plugins.size(), 1u);
    EXPECT_EQ(sim.basic_platform_indices(), std::vector<std::size_t>{0});
}

TEST(SimReaderErrors, MissingReferencedFile) {
    TempDir dir;
    const auto sim_path = write_sim(dir,
                                    "<simulation>\n"
                                    "  <scene externalfile=\"./site.scene\"/>\n"
                                    "  <platform externalfile=\"./sub/gone.platform\"/>\n"
                                    "  <platformmotion externalfile=\"hover.ppd\"/>\n"
                                    "  <tasklist externalfile=\"one_frame.tasks\"/>\n"
                                    "</simulation>\n");
    Diagnostics diagnostics;
    read_sim(sim_path, ReadOptions{}, diagnostics);
    EXPECT_EQ(only_error(diagnostics).text(),
              sim_path.string() + ":3: simulation/platform: referenced file does not exist: " +
                  (dir / "sub/gone.platform").string());
}

TEST(SimReaderErrors, WindowsPathsDoNotExistHere) {
    TempDir dir;
    const auto sim_path = write_sim(dir,
                                    "<simulation>\n"
                                    "  <platform externalfile=\"cam.platform\"/>\n"
                                    "  <platformmotion externalfile=\"hover.ppd\"/>\n"
                                    "  <tasklist externalfile=\"C:\\sims\\task.tasks\"/>\n"
                                    "</simulation>\n");
    Diagnostics diagnostics;
    const model::Simulation sim = read_sim(sim_path, ReadOptions{}, diagnostics);
    const Diagnostic error = only_error(diagnostics);
    EXPECT_EQ(error.where.line, 4);
    EXPECT_EQ(error.where.element, "simulation/tasklist");
    EXPECT_EQ(error.message, "referenced file does not exist: C:/sims/task.tasks");
    ASSERT_EQ(sim.plugins.size(), 1u);
    EXPECT_EQ(sim.plugins[0].basic_platform->tasks_file.text, "C:\\sims\\task.tasks");
}

TEST(SimReaderErrors, UndefinedVariableAndFolder) {
    TempDir dir;
    std::filesystem::create_directory(dir / "folder.ppd");
    const auto sim_path = write_sim(dir,
                                    "<simulation>\n"
                                    "  <platform externalfile=\"$NO_SUCH_VAR/cam.platform\"/>\n"
                                    "  <platformmotion externalfile=\"folder.ppd\"/>\n"
                                    "  <tasklist externalfile=\"one_frame.tasks\"/>\n"
                                    "</simulation>\n");
    ReadOptions options;
    options.paths.environment = [](const std::string&) { return std::nullopt; };
    Diagnostics diagnostics;
    read_sim(sim_path, options, diagnostics);
    ASSERT_EQ(diagnostics.error_count(), 2u);
    EXPECT_EQ(diagnostics.items()[0].where.line, 2);
    EXPECT_EQ(diagnostics.items()[0].where.element, "simulation/platform");
    EXPECT_EQ(diagnostics.items()[0].message,
              "undefined variable $NO_SUCH_VAR in path \"$NO_SUCH_VAR/cam.platform\"");
    EXPECT_EQ(diagnostics.items()[1].where.line, 3);
    EXPECT_THAT(diagnostics.items()[1].message,
                HasSubstr("referenced path is a folder, expected a file"));
}

TEST(SimReaderErrors, MissingElementsAndAttribute) {
    TempDir dir;
    const auto sim_path = write_sim(dir,
                                    "<simulation>\n"
                                    "  <scene/>\n"
                                    "  <platformmotion externalfile=\"hover.ppd\"/>\n"
                                    "</simulation>\n");
    Diagnostics diagnostics;
    const model::Simulation sim = read_sim(sim_path, ReadOptions{}, diagnostics);
    ASSERT_EQ(diagnostics.error_count(), 3u);
    EXPECT_EQ(diagnostics.items()[0].text(),
              sim_path.string() + ":2: simulation/scene: missing required attribute externalfile");
    EXPECT_EQ(diagnostics.items()[1].text(),
              sim_path.string() + ":1: simulation: missing required element <platform>");
    EXPECT_EQ(diagnostics.items()[2].text(),
              sim_path.string() + ":1: simulation: missing required element <tasklist>");
    EXPECT_TRUE(sim.plugins.empty());
}

TEST(SimReaderErrors, DuplicatedElement) {
    TempDir dir;
    const auto sim_path = write_sim(dir,
                                    "<simulation>\n"
                                    "  <platform externalfile=\"cam.platform\"/>\n"
                                    "  <platformmotion externalfile=\"hover.ppd\"/>\n"
                                    "  <tasklist externalfile=\"one_frame.tasks\"/>\n"
                                    "  <platform externalfile=\"cam.platform\"/>\n"
                                    "</simulation>\n");
    Diagnostics diagnostics;
    read_sim(sim_path, ReadOptions{}, diagnostics);
    const Diagnostic error = only_error(diagnostics);
    EXPECT_EQ(error.where.line, 5);
    EXPECT_EQ(error.where.element, "simulation/platform");
    EXPECT_EQ(error.message, "element <platform> given more than once (first at line 2)");
}

TEST(SimReaderErrors, OptionsAndUnknownElementsAreWarnings) {
    TempDir dir;
    const auto sim_path = write_sim(dir,
                                    "<simulation>\n"
                                    "  <options externalfile=\"run.options\"/>\n"
                                    "  <platform externalfile=\"cam.platform\"/>\n"
                                    "  <platformmotion externalfile=\"hover.ppd\"/>\n"
                                    "  <tasklist externalfile=\"one_frame.tasks\"/>\n"
                                    "  <weather externalfile=\"x.wth\"/>\n"
                                    "</simulation>\n");
    Diagnostics diagnostics;
    read_sim(sim_path, ReadOptions{}, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors());
    ASSERT_EQ(diagnostics.warning_count(), 2u);
    EXPECT_EQ(diagnostics.items()[0].where.line, 2);
    EXPECT_EQ(diagnostics.items()[0].where.element, "simulation/options");
    EXPECT_THAT(diagnostics.items()[0].message, HasSubstr("element <options> ignored"));
    EXPECT_EQ(diagnostics.items()[1].where.line, 6);
    EXPECT_EQ(diagnostics.items()[1].message, "unknown element <weather> ignored");
}

TEST(SimReaderErrors, MalformedXmlAndWrongRoot) {
    TempDir dir;
    const auto sim_path = write_sim(dir, "<simulation>\n  <platform externalfile=\"a\">\n");
    Diagnostics diagnostics;
    read_sim(sim_path, ReadOptions{}, diagnostics);
    const Diagnostic error = only_error(diagnostics);
    EXPECT_GE(error.where.line, 1);
    EXPECT_THAT(error.text(), HasSubstr(sim_path.string() + ":"));
    EXPECT_THAT(error.message, HasSubstr("malformed XML"));

    std::ofstream(dir / "b.sim") << "<tasklist/>";
    Diagnostics wrong_root;
    read_sim(dir / "b.sim", ReadOptions{}, wrong_root);
    EXPECT_EQ(only_error(wrong_root).message, "expected root element <simulation>, got <tasklist>");
}

TEST(ReadSimulation, TellsSimFromJsimByContent) {
    Diagnostics diagnostics;
    const auto from_sim = read_simulation(kData / "example.sim", ReadOptions{}, diagnostics);
    const auto from_jsim = read_simulation(kData / "example.jsim", ReadOptions{}, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors());
    ASSERT_EQ(from_sim.size(), 1u);
    ASSERT_EQ(from_jsim.size(), 1u);
    EXPECT_EQ(from_sim[0].plugins.size(), 2u);
    EXPECT_EQ(from_jsim[0].plugins.size(), 2u);

    TempDir dir;
    std::ofstream(dir / "x.sim") << "\xEF\xBB\xBF  \n[{\"plugin_list\": []}]";
    EXPECT_EQ(read_simulation(dir / "x.sim", ReadOptions{}, diagnostics).size(), 1u);
    EXPECT_FALSE(diagnostics.has_errors());

    std::ofstream(dir / "y.sim") << "\n  simulation = 1\n";
    EXPECT_TRUE(read_simulation(dir / "y.sim", ReadOptions{}, diagnostics).empty());
    const Diagnostic error = only_error(diagnostics);
    EXPECT_EQ(error.where.line, 1);
    EXPECT_THAT(error.message, HasSubstr("cannot tell whether this is a .jsim (JSON) or a .sim"));
}

}  // namespace sim_test
}  // namespace glint::dirsig
