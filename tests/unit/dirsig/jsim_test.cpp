// SPDX-License-Identifier: Apache-2.0
// Unit tests of the `.jsim` reader and writer: the format notes' example, a single object,
// other plugins and medium_list kept verbatim, every bad input with its message, line and JSON
// path (syntax errors, missing keys, wrong types, unknown keys, undefined variables), and the
// writer's path rewriting (same folder, another folder, Windows and unresolved paths kept)
// with round trips .sim -> format_jsim -> read_jsim and .jsim -> format_jsim -> read_jsim.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "glint/dirsig/readers.h"
#include "glint/test/diagnostics.h"
#include "glint/test/temp_dir.h"

namespace glint::dirsig {
namespace jsim_test {

using glint::test::TempDir;
using ::testing::HasSubstr;
using ::testing::Not;

const std::filesystem::path kData =
    (std::filesystem::path(GLINT_TEST_DATA_DIR) / "legacy").lexically_normal();

std::vector<model::Simulation> read_text(const TempDir& dir, const std::string& text,
                                         Diagnostics& diagnostics,
                                         const std::string& name = "a.jsim") {
    std::ofstream(dir / name) << text;
    ReadOptions options;
    options.paths.environment = [](const std::string& variable) -> std::optional<std::string> {
        if (variable == "DATA") return "/data";
        return std::nullopt;
    };
    return read_jsim(dir / name, options, diagnostics);
}

using glint::test::only_error;

/// Every field of two simulations that a rewrite must keep (resolved paths, not their text).
void expect_same(const model::Simulation& a, const model::Simulation& b) {
    ASSERT_EQ(a.scenes.size(), b.scenes.size());
    for (std::size_t i = 0; i < a.scenes.size(); ++i) {
        EXPECT_EQ(a.scenes[i].file.resolved, b.scenes[i].file.resolved);
        EXPECT_EQ(a.scenes[i].offset, b.scenes[i].offset);
    }
    ASSERT_EQ(a.plugins.size(), b.plugins.size());
    for (std::size_t i = 0; i < a.plugins.size(); ++i) {
        const model::Plugin& p = a.plugins[i];
        const model::Plugin& q = b.plugins[i];
        EXPECT_EQ(p.name, q.name);
        ASSERT_EQ(p.basic_platform.has_value(), q.basic_platform.has_value());
        ASSERT_EQ(p.basic_atmosphere.has_value(), q.basic_atmosphere.has_value());
        if (p.basic_platform) {
            EXPECT_EQ(p.basic_platform->platform_file.resolved,
                      q.basic_platform->platform_file.resolved);
            EXPECT_EQ(p.basic_platform->motion_file.resolved,
                      q.basic_platform->motion_file.resolved);
            EXPECT_EQ(p.basic_platform->tasks_file.resolved, q.basic_platform->tasks_file.resolved);
            EXPECT_EQ(p.basic_platform->output_folder, q.basic_platform->output_folder);
            EXPECT_EQ(p.basic_platform->output_prefix, q.basic_platform->output_prefix);
            EXPECT_EQ(p.basic_platform->split_channels.value_or(false),
                      q.basic_platform->split_channels.value_or(false));
        } else if (p.basic_atmosphere) {
            EXPECT_EQ(p.basic_atmosphere->atmosphere_file.resolved,
                      q.basic_atmosphere->atmosphere_file.resolved);
        } else {
            EXPECT_EQ(p.inputs_json, q.inputs_json);
        }
    }
    EXPECT_EQ(a.medium_list_json, b.medium_list_json);
}

/// format_jsim into `folder`/out.jsim, then read_jsim of it.
std::vector<model::Simulation> round_trip(const std::vector<model::Simulation>& simulations,
                                          const std::filesystem::path& folder,
                                          std::string* text = nullptr) {
    const std::string written = format_jsim(simulations, folder);
    if (text) *text = written;
    std::ofstream(folder / "out.jsim") << written;
    Diagnostics diagnostics;
    auto back = read_jsim(folder / "out.jsim", ReadOptions{}, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors()) << diagnostics.items().at(0).text();
    return back;
}

TEST(JsimReader, ReadsTheFormatNotesExample) {
    Diagnostics diagnostics;
    const auto sims = read_jsim(kData / "example.jsim", ReadOptions{}, diagnostics);
    EXPECT_TRUE(diagnostics.items().empty()) << diagnostics.items().at(0).text();
    ASSERT_EQ(sims.size(), 1u);
    const model::Simulation& sim = sims[0];
    EXPECT_EQ(sim.file, (kData / "example.jsim").string());
    ASSERT_EQ(sim.scenes.size(), 1u);
    EXPECT_EQ(sim.scenes[0].file.resolved, kData / "site.scene");
    EXPECT_EQ(sim.scenes[0].file.where.line, 2);
    EXPECT_EQ(sim.scenes[0].file.where.element, "[0].scene_list[0].inputs");
    ASSERT_EQ(sim.plugins.size(), 2u);
    ASSERT_NE(sim.atmosphere(), nullptr);
    EXPECT_EQ(sim.atmosphere()->atmosphere_file.resolved, kData / "clear.atm");
    EXPECT_EQ(sim.basic_platform_indices(), std::vector<std::size_t>{1});
    const model::Plugin& plugin = sim.plugins[1];
    EXPECT_EQ(plugin.where.line, 5);
    EXPECT_EQ(plugin.where.element, "[0].plugin_list[1]");
    const model::BasicPlatformInputs& in = *plugin.basic_platform;
    EXPECT_EQ(in.platform_file.text, "./cam.platform");
    EXPECT_EQ(in.platform_file.resolved, kData / "cam.platform");
    EXPECT_EQ(in.platform_file.where.line, 6);
    EXPECT_EQ(in.platform_file.where.element, "[0].plugin_list[1].inputs.platform_filename");
    EXPECT_EQ(in.motion_file.resolved, kData / "hover.ppd");
    EXPECT_EQ(in.tasks_file.resolved, kData / "one_frame.tasks");
    EXPECT_EQ(in.tasks_file.where.line, 8);
    EXPECT_EQ(in.output_folder, "out");
    EXPECT_EQ(in.output_prefix, "run1_");
    EXPECT_EQ(in.split_channels, std::optional<bool>(false));
    EXPECT_EQ(sim.medium_list_json, "[]");
}

TEST(JsimReader, SingleObjectOtherPluginsAndMediumList) {
    TempDir dir;
    Diagnostics diagnostics;
    const auto sims = read_text(dir,
                                R"({
  "scene_list": [{"inputs": "$DATA/s.scene", "offset": "1,2,3"}],
  "plugin_list": [
    {"inputs": {"hdf_filename": "a.hdf", "info": {"name": "x", "author": "y"}},
     "name": "NewAtmosphere"},
    {"name": "SpiceEphemeris", "inputs": {}},
    {"name": "ThermWeather"},
    {"name": "BasicPlatform",
     "inputs": {"platform_filename": "p/a.platform", "motion_filename": "m.motion",
                "tasks_filename": "/abs/t.tasks", "split_channels": "TRUE"}}
  ],
  "medium_list": [{"name": "water", "k": [1, 2]}]
})",
                                diagnostics);
    // Each plugin glint does not run and the non-empty medium_list: one warning each, at its
    // entry (the scene offset is warned about where the scene is loaded). ThermWeather is run
    // (its weather drives THERM; its file is checked where the inputs are loaded).
    std::vector<std::string> warned;
    for (const Diagnostic& item : diagnostics.items()) {
        EXPECT_EQ(item.severity, Diagnostic::Severity::warning) << item.text();
        EXPECT_NE(item.message.find(" not "), std::string::npos) << item.text();
        EXPECT_NE(item.message.find("(kept in a rewritten .jsim)"), std::string::npos)
            << item.text();
        warned.push_back(item.where.element);
    }
    EXPECT_EQ(warned,
              (std::vector<std::string>{"plugin_list[0]", "plugin_list[1]", "medium_list"}));
    ASSERT_EQ(sims.size(), 1u);
    const model::Simulation& sim = sims[0];
    EXPECT_EQ(sim.scenes[0].file.resolved, std::filesystem::path("/data/s.scene"));
    EXPECT_EQ(sim.scenes[0].offset, "1,2,3");
    ASSERT_EQ(sim.plugins.size(), 4u);
    EXPECT_EQ(sim.plugins[0].name, "NewAtmosphere");
    EXPECT_EQ(sim.plugins[0].inputs_json,
              R"({"hdf_filename":"a.hdf","info":{"author":"y","name":"x"}})");
    EXPECT_FALSE(sim.plugins[0].basic_platform.has_value());
    EXPECT_FALSE(sim.plugins[0].basic_atmosphere.has_value());
    EXPECT_EQ(sim.plugins[1].inputs_json, "{}");
    EXPECT_EQ(sim.plugins[2].inputs_json, "{}");
    EXPECT_EQ(sim.atmosphere(), nullptr);
    EXPECT_EQ(sim.basic_platform_indices(), std::vector<std::size_t>{3});
    const model::BasicPlatformInputs& in = *sim.plugins[3].basic_platform;
    EXPECT_EQ(in.platform_file.resolved, dir / "p/a.platform");
    EXPECT_EQ(in.tasks_file.resolved, std::filesystem::path("/abs/t.tasks"));
    EXPECT_EQ(in.platform_file.where.element, "plugin_list[3].inputs.platform_filename");
    EXPECT_EQ(in.platform_file.where.line, 9);
    EXPECT_EQ(in.split_channels, std::optional<bool>(true));
    EXPECT_FALSE(in.output_folder.has_value());
    EXPECT_EQ(sim.medium_list_json, R"([{"k":[1,2],"name":"water"}])");
}

TEST(JsimReader, ReferencedFilesAreNotCheckedHere) {
    TempDir dir;
    Diagnostics diagnostics;
    const auto sims = read_text(dir,
                                R"([{"plugin_list": [{"name": "BasicPlatform", "inputs": {
    "platform_filename": "C:\\sims\\a.platform", "motion_filename": "none.ppd",
    "tasks_filename": "none.tasks"}}]}])",
                                diagnostics);
    EXPECT_TRUE(diagnostics.items().empty());
    ASSERT_EQ(sims.size(), 1u);
    EXPECT_EQ(sims[0].plugins[0].basic_platform->platform_file.resolved.string(),
              "C:/sims/a.platform");
    EXPECT_EQ(sims[0].plugins[0].basic_platform->motion_file.resolved, dir / "none.ppd");
}

TEST(JsimReaderErrors, SyntaxErrorNamesTheLine) {
    TempDir dir;
    Diagnostics diagnostics;
    const auto sims = read_text(dir,
                                "[{\n  \"scene_list\": [],\n  \"plugin_list\": [\n"
                                "    {\"name\": \"BasicPlatform\",}\n  ]\n}]\n",
                                diagnostics);
    EXPECT_TRUE(sims.empty());
    const Diagnostic error = only_error(diagnostics);
    EXPECT_EQ(error.where.file, (dir / "a.jsim").string());
    EXPECT_EQ(error.where.line, 4);
    EXPECT_THAT(error.message, HasSubstr("malformed JSON at column 30: syntax error"));
    EXPECT_THAT(error.message, Not(HasSubstr("json.exception")));

    Diagnostics empty;
    EXPECT_TRUE(read_text(dir, "", empty, "b.jsim").empty());
    EXPECT_EQ(only_error(empty).where.line, 1);
    EXPECT_THAT(only_error(empty).message, HasSubstr("malformed JSON"));

    Diagnostics missing;
    read_jsim(dir / "none.jsim", ReadOptions{}, missing);
    EXPECT_THAT(only_error(missing).text(), HasSubstr("none.jsim: cannot open file"));
}

TEST(JsimReaderErrors, MissingKeys) {
    TempDir dir;
    Diagnostics diagnostics;
    read_text(dir,
              "[\n  {\"scene_list\": [{\"offset\": \"0,0,0\"}]},\n"
              "  {\"plugin_list\": [\n    {\"name\": \"BasicPlatform\",\n"
              "     \"inputs\": {\"platform_filename\": \"a\", \"tasks_filename\": \"t\"}},\n"
              "    {\"inputs\": {}}\n  ]}\n]\n",
              diagnostics);
    ASSERT_EQ(diagnostics.error_count(), 4u);
    EXPECT_EQ(diagnostics.items()[0].where.element, "[0].scene_list[0]");
    EXPECT_EQ(diagnostics.items()[0].where.line, 2);
    EXPECT_EQ(diagnostics.items()[0].message, "missing required key \"inputs\"");
    EXPECT_EQ(diagnostics.items()[1].where.element, "[0]");
    EXPECT_EQ(diagnostics.items()[1].message, "missing required key \"plugin_list\"");
    EXPECT_EQ(diagnostics.items()[2].text(),
              (dir / "a.jsim").string() +
                  ":5: [1].plugin_list[0].inputs: missing required key \"motion_filename\"");
    EXPECT_EQ(diagnostics.items()[3].where.element, "[1].plugin_list[1]");
    EXPECT_EQ(diagnostics.items()[3].where.line, 6);
    EXPECT_EQ(diagnostics.items()[3].message, "missing required key \"name\"");
}

TEST(JsimReaderErrors, WrongTypes) {
    TempDir dir;
    Diagnostics diagnostics;
    read_text(dir,
              "[{\n"
              "  \"scene_list\": {\"inputs\": \"s.scene\"},\n"
              "  \"plugin_list\": [\n"
              "    {\"name\": \"BasicPlatform\", \"inputs\": {\n"
              "      \"platform_filename\": 42,\n"
              "      \"motion_filename\": \"m.ppd\", \"tasks_filename\": [\"t.tasks\"],\n"
              "      \"output_prefix\": null,\n"
              "      \"split_channels\": \"maybe\"}},\n"
              "    {\"name\": \"BasicAtmosphere\", \"inputs\": \"clear.atm\"},\n"
              "    7\n"
              "  ],\n"
              "  \"medium_list\": {}\n"
              "}]\n",
              diagnostics);
    ASSERT_EQ(diagnostics.error_count(), 9u);
    const auto& items = diagnostics.items();
    EXPECT_EQ(items[0].text(), (dir / "a.jsim").string() +
                                   ":2: [0].scene_list: expected an array of scenes, got object");
    EXPECT_EQ(items[1].where.line, 5);
    EXPECT_EQ(items[1].where.element, "[0].plugin_list[0].inputs.platform_filename");
    EXPECT_EQ(items[1].message, "expected a string, got number 42");
    EXPECT_EQ(items[2].where.line, 6);
    EXPECT_EQ(items[2].where.element, "[0].plugin_list[0].inputs.tasks_filename");
    EXPECT_EQ(items[2].message, "expected a string, got array");
    EXPECT_EQ(items[3].where.line, 7);
    EXPECT_EQ(items[3].message, "expected a string, got null null");
    EXPECT_EQ(items[4].where.line, 8);
    EXPECT_EQ(items[4].where.element, "[0].plugin_list[0].inputs.split_channels");
    EXPECT_EQ(items[4].message, "expected true or false, got string \"maybe\"");
    EXPECT_EQ(items[5].where.line, 9);
    EXPECT_EQ(items[5].where.element, "[0].plugin_list[1].inputs");
    EXPECT_EQ(items[5].message, "expected an object, got string \"clear.atm\"");
    EXPECT_EQ(items[6].where.element, "[0].plugin_list[1].inputs");
    EXPECT_EQ(items[6].message, "missing required key \"atmosphere_filename\"");
    EXPECT_EQ(items[7].where.line, 10);
    EXPECT_EQ(items[7].where.element, "[0].plugin_list[2]");
    EXPECT_EQ(items[7].message, "expected a plugin object, got number 7");
    EXPECT_EQ(items[8].where.line, 12);
    EXPECT_EQ(items[8].message, "expected an array, got object");
}

TEST(JsimReaderErrors, TopLevelShape) {
    TempDir dir;
    Diagnostics diagnostics;
    EXPECT_TRUE(read_text(dir, "\"x\"", diagnostics).empty());
    EXPECT_EQ(only_error(diagnostics).message,
              "expected an array of simulation objects, got string");
    Diagnostics empty;
    EXPECT_TRUE(read_text(dir, "[ ]", empty).empty());
    EXPECT_EQ(only_error(empty).message,
              "expected at least one simulation object, got an empty array");
    Diagnostics not_object;
    EXPECT_EQ(read_text(dir, "[\n[]\n]", not_object).size(), 1u);
    EXPECT_EQ(only_error(not_object).where.line, 2);
    EXPECT_EQ(only_error(not_object).text(),
              (dir / "a.jsim").string() + ":2: [0]: expected a simulation object, got array");
}

TEST(JsimReaderErrors, UnknownKeysAreWarnings) {
    TempDir dir;
    Diagnostics diagnostics;
    const auto sims = read_text(dir,
                                "[{\"plugin_list\": [\n"
                                "  {\"name\": \"BasicAtmosphere\", \"inputs\": {\n"
                                "    \"atmosphere_filename\": \"a.atm\", \"extra\": 1}},\n"
                                "  {\"name\": \"BasicPlatform\", \"inputs\": {\n"
                                "    \"platform_filename\": \"a\", \"motion_filename\": \"b\",\n"
                                "    \"tasks_filename\": \"c\", \"scale_resolution\": 2}}],\n"
                                " \"comment\": \"x\"}]\n",
                                diagnostics);
    EXPECT_FALSE(diagnostics.has_errors());
    ASSERT_EQ(diagnostics.warning_count(), 3u);
    EXPECT_EQ(diagnostics.items()[0].text(),
              (dir / "a.jsim").string() + ":7: [0].comment: unknown key \"comment\" ignored");
    EXPECT_EQ(diagnostics.items()[1].where.line, 3);
    EXPECT_EQ(diagnostics.items()[1].message,
              "unknown key \"extra\" in BasicAtmosphere inputs ignored");
    EXPECT_EQ(diagnostics.items()[2].where.line, 6);
    EXPECT_EQ(diagnostics.items()[2].where.element, "[0].plugin_list[1].inputs.scale_resolution");
    EXPECT_EQ(diagnostics.items()[2].message,
              "unknown key \"scale_resolution\" in BasicPlatform inputs ignored");
    ASSERT_EQ(sims.size(), 1u);
}

TEST(JsimReaderErrors, OutputPrefixThatCouldLeaveTheOutputFolder) {
    TempDir dir;
    Diagnostics diagnostics;
    const auto sims =
        read_text(dir,
                  "[{\"plugin_list\": [{\"name\": \"BasicPlatform\", \"inputs\": {\n"
                  "  \"platform_filename\": \"a.platform\",\n"
                  "  \"motion_filename\": \"a.ppd\", \"tasks_filename\": \"a.tasks\",\n"
                  "  \"output_prefix\": \"../../escaped_\"}}]}]\n",
                  diagnostics);
    const Diagnostic error = only_error(diagnostics);
    EXPECT_EQ(error.where.line, 4);
    EXPECT_EQ(error.where.element, "[0].plugin_list[0].inputs.output_prefix");
    EXPECT_EQ(error.message,
              "output_prefix \"../../escaped_\" contains '/', expected a file name without "
              "folder separators (the output folder says where files go)");
    ASSERT_EQ(sims.size(), 1u);
    EXPECT_FALSE(sims[0].plugins[0].basic_platform->output_prefix.has_value());
}

TEST(JsimReaderErrors, UndefinedVariable) {
    TempDir dir;
    Diagnostics diagnostics;
    const auto sims = read_text(dir,
                                "[{\"plugin_list\": [{\"name\": \"BasicAtmosphere\",\n"
                                "  \"inputs\": {\"atmosphere_filename\": \"$DIRSIG_HOME/a.atm\"}}"
                                "]}]\n",
                                diagnostics);
    const Diagnostic error = only_error(diagnostics);
    EXPECT_EQ(error.where.line, 2);
    EXPECT_EQ(error.where.element, "[0].plugin_list[0].inputs.atmosphere_filename");
    EXPECT_EQ(error.message, "undefined variable $DIRSIG_HOME in path \"$DIRSIG_HOME/a.atm\"");
    ASSERT_EQ(sims.size(), 1u);
    EXPECT_TRUE(sims[0].atmosphere()->atmosphere_file.resolved.empty());
}

TEST(FormatJsim, SameFolderGivesPlainRelativePaths) {
    Diagnostics diagnostics;
    const auto sims = read_jsim(kData / "example.jsim", ReadOptions{}, diagnostics);
    EXPECT_EQ(format_jsim(sims, kData),
              R"([
  {
    "scene_list": [
      {
        "inputs": "site.scene"
      }
    ],
    "plugin_list": [
      {
        "name": "BasicAtmosphere",
        "inputs": {
          "atmosphere_filename": "clear.atm"
        }
      },
      {
        "name": "BasicPlatform",
        "inputs": {
          "platform_filename": "cam.platform",
          "motion_filename": "hover.ppd",
          "tasks_filename": "one_frame.tasks",
          "output_folder": "out",
          "output_prefix": "run1_",
          "split_channels": false
        }
      }
    ],
    "medium_list": []
  }
]
)");
}

TEST(FormatJsim, SimToJsimRoundTripInAnotherFolder) {
    Diagnostics diagnostics;
    const model::Simulation sim = read_sim(kData / "example.sim", ReadOptions{}, diagnostics);
    ASSERT_FALSE(diagnostics.has_errors());
    TempDir dir;
    std::string text;
    const auto back = round_trip({sim}, dir.path(), &text);
    ASSERT_EQ(back.size(), 1u);
    expect_same(sim, back[0]);
    // Absolute when the temporary folder and the source tree share only "/", else relative
    // (the clone may live under the temporary folder itself).
    const std::filesystem::path platform = kData / "cam.platform";
    const auto first_step = [](const std::filesystem::path& p) {
        const std::filesystem::path normal = p.lexically_normal();
        auto it = normal.begin();
        return it == normal.end() ? std::string() : (++it)->string();
    };
    const bool share_only_root = first_step(platform) != first_step(dir.path());
    const std::string expected =
        share_only_root
            ? platform.generic_string()
            : platform.lexically_normal().lexically_relative(dir.path()).generic_string();
    EXPECT_THAT(text, HasSubstr("\"platform_filename\": \"" + expected + "\""));
}

TEST(FormatJsim, RelativePathsAcrossFolders) {
    TempDir dir;
    std::filesystem::create_directories(dir / "in/sub");
    std::filesystem::create_directories(dir / "out/deep");
    Diagnostics diagnostics;
    const auto sims = read_text(dir,
                                R"([{"scene_list": [{"inputs": "sub/s.scene"}],
 "plugin_list": [{"name": "BasicPlatform", "inputs": {
   "platform_filename": "../in/sub/a.platform", "motion_filename": "C:\\m\\b.ppd",
   "tasks_filename": "/opt/t.tasks", "output_folder": "o", "split_channels": true,
   "future_key": [1]}}],
 "medium_list": [{"a": 1}]}])",
                                diagnostics, "in/x.jsim");
    ASSERT_FALSE(diagnostics.has_errors());
    std::string text;
    const auto back = round_trip(sims, dir / "out/deep", &text);
    ASSERT_EQ(back.size(), 1u);
    expect_same(sims[0], back[0]);
    EXPECT_THAT(text, HasSubstr("\"inputs\": \"../../in/sub/s.scene\""));
    EXPECT_THAT(text, HasSubstr("\"platform_filename\": \"../../in/sub/a.platform\""));
    EXPECT_THAT(text, HasSubstr(R"("motion_filename": "C:\\m\\b.ppd")"));
    EXPECT_THAT(text, HasSubstr("\"tasks_filename\": \"/opt/t.tasks\""));
    EXPECT_THAT(text, HasSubstr("\"future_key\": [\n"));
    EXPECT_THAT(text, HasSubstr("\"output_folder\": \"o\""));
    EXPECT_EQ(back[0].medium_list_json, R"([{"a":1}])");
}

TEST(FormatJsim, UnresolvedPathsAndOtherPluginsVerbatim) {
    model::Simulation sim;
    model::Plugin other;
    other.name = "NewAtmosphere";
    other.inputs_json = R"({"b":1,"a":{"c":[true]}})";
    sim.plugins.push_back(other);
    model::Plugin atmosphere;
    atmosphere.name = "BasicAtmosphere";
    atmosphere.basic_atmosphere = model::BasicAtmosphereInputs{};
    atmosphere.basic_atmosphere->atmosphere_file.text = "$DIRSIG_HOME/a.atm";  // unresolved
    sim.plugins.push_back(atmosphere);
    const std::string text = format_jsim({sim}, "/tmp");
    EXPECT_THAT(text, HasSubstr(R"("atmosphere_filename": "$DIRSIG_HOME/a.atm")"));
    EXPECT_THAT(text, HasSubstr("\"b\": 1,\n          \"a\": {"));
    EXPECT_THAT(text, HasSubstr("\"scene_list\": []"));

    model::Simulation broken;
    model::Plugin bad;
    bad.name = "X";
    bad.inputs_json = "{not json";
    broken.plugins.push_back(bad);
    EXPECT_THROW(format_jsim({broken}, "/tmp"), Error);
}

TEST(FormatJsim, OtherPluginsRelativePathsAreRewritten) {
    TempDir dir;
    std::filesystem::create_directories(dir / "in/sub");
    std::filesystem::create_directories(dir / "out");
    std::ofstream(dir / "in/sub/k.tls") << "kernel\n";
    Diagnostics diagnostics;
    std::vector<model::Simulation> sims = read_text(dir,
                                                    R"([{"plugin_list": [
  {"name": "SpiceEphemeris", "inputs": {"kernels": ["sub/k.tls", "absent.tls"],
    "Weather_Filename": "w.wth", "table_files": ["a.txt", 3], "mode": "sub",
    "abs_file": "/x/y.txt", "var_file": "$DATA/v.txt", "nested": {"lut_file": "l.bin"}}}
]}])",
                                                    diagnostics, "in/a.jsim");
    ASSERT_EQ(sims.size(), 1u);
    sims[0].file = (dir / "in/a.jsim").string();
    const std::string text = format_jsim(sims, dir / "out");
    const nlohmann::json inputs = nlohmann::json::parse(text)[0]["plugin_list"][0]["inputs"];
    // An existing file, and the values of path keys (any case, arrays, nested objects).
    EXPECT_EQ(inputs["kernels"][0], "../in/sub/k.tls");
    EXPECT_EQ(inputs["kernels"][1], "absent.tls");  // not a path key, names no file
    EXPECT_EQ(inputs["Weather_Filename"], "../in/w.wth");
    EXPECT_EQ(inputs["table_files"][0], "../in/a.txt");
    EXPECT_EQ(inputs["table_files"][1], 3);
    EXPECT_EQ(inputs["nested"]["lut_file"], "../in/l.bin");
    // Kept: other values, absolute paths, variables.
    EXPECT_EQ(inputs["mode"], "sub");
    EXPECT_EQ(inputs["abs_file"], "/x/y.txt");
    EXPECT_EQ(inputs["var_file"], "$DATA/v.txt");

    // Written back into the .jsim's own folder, the paths are as they were.
    const nlohmann::json same =
        nlohmann::json::parse(format_jsim(sims, dir / "in"))[0]["plugin_list"][0]["inputs"];
    EXPECT_EQ(same["kernels"][0], "sub/k.tls");
    EXPECT_EQ(same["Weather_Filename"], "w.wth");
}

TEST(JsimPlugins, KindsByNameAndWhatGlintDoesInstead) {
    EXPECT_EQ(plugin_kind("BasicPlatform"), PluginKind::basic_platform);
    EXPECT_EQ(plugin_kind("BasicAtmosphere"), PluginKind::basic_atmosphere);
    EXPECT_EQ(plugin_kind("NewAtmosphere"), PluginKind::atmosphere);
    EXPECT_EQ(plugin_kind("SpiceEphemeris"), PluginKind::ephemeris);
    EXPECT_EQ(plugin_kind("ThermWeather"), PluginKind::thermal);
    EXPECT_EQ(plugin_kind("TemperatureSolver"), PluginKind::thermal);
    EXPECT_EQ(plugin_kind("Clouds"), PluginKind::other);
    EXPECT_EQ(unsupported_plugin_fallback("NewAtmosphere", false),
              "glint's default atmosphere is used (--atmosphere picks another)");
    EXPECT_EQ(unsupported_plugin_fallback("NewAtmosphere", true),
              "the BasicAtmosphere entry's atmosphere is used");
    EXPECT_EQ(unsupported_plugin_fallback("SpiceEphemeris", false),
              "glint places the sun and moon itself");
    EXPECT_EQ(unsupported_plugin_fallback("TemperatureSolver", false),
              "materials keep their own temperatures (a ThermWeather plugin's weather drives "
              "THERM)");
    EXPECT_EQ(unsupported_plugin_fallback("Clouds", false), "it has no effect");
}

/// Peak resident memory of this process so far, in MiB.
double peak_rss_mib() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

TEST(JsimReaderLimits, DeepNestingIsRefusedAtItsLineInBoundedMemory) {
    // 100,000 nested arrays, one per line: the line recorder kept every value's whole JSON
    // path, so memory grew with the square of the depth (over 9 GB here).
    TempDir dir;
    std::string text;
    for (int i = 0; i < 100'000; ++i) text += "[\n";
    for (int i = 0; i < 100'000; ++i) text += "]";
    const double before_mib = peak_rss_mib();
    Diagnostics diagnostics;
    EXPECT_TRUE(read_text(dir, text, diagnostics).empty());
    const Diagnostic error = only_error(diagnostics);
    EXPECT_EQ(error.text(), (dir / "a.jsim").string() + ":65: JSON nesting deeper than 64 levels");
    EXPECT_LT(peak_rss_mib() - before_mib, 200.0);

    Diagnostics at_limit;  // 64 levels are read (and are not simulations)
    read_text(dir, std::string(64, '[') + std::string(64, ']'), at_limit, "b.jsim");
    EXPECT_EQ(only_error(at_limit).message, "expected a simulation object, got array");
}

TEST(JsimReaderLimits, LineRecordIsLinearInTheText) {
    // A 1 MB key holding 100,000 values: recording every value by its whole path took
    // 100,000 copies of the key (100 GB); the record is now one node per value.
    TempDir dir;
    const std::string key(1 << 20, 'k');
    std::string text = "[{\"plugin_list\": [],\n\"" + key + "\": [0";
    for (int i = 1; i < 100'000; ++i) text += ",0";
    text += "],\n\"extra\": 1}]\n";
    const double before_mib = peak_rss_mib();
    Diagnostics diagnostics;
    const auto sims = read_text(dir, text, diagnostics);
    EXPECT_LT(peak_rss_mib() - before_mib, 200.0);
    ASSERT_EQ(sims.size(), 1u);
    EXPECT_FALSE(diagnostics.has_errors());
    ASSERT_EQ(diagnostics.warning_count(), 2u);  // in key order
    EXPECT_EQ(diagnostics.items()[0].text(),
              (dir / "a.jsim").string() + ":3: [0].extra: unknown key \"extra\" ignored");
    EXPECT_EQ(diagnostics.items()[1].where.line, 2);
    // The megabyte key is not echoed whole: the element path and the key are cut.
    EXPECT_EQ(diagnostics.items()[1].where.element, "[0]." + key.substr(0, 196) + "...");
    EXPECT_LT(diagnostics.items()[1].text().size(), 600u);
}

TEST(JsimReaderErrors, NumberTooLargeForADouble) {
    // nlohmann throws out_of_range (406), not parse_error, for it: found by fuzz/jsim_fuzz
    // (fuzz/crashes/jsim/crash-c2ed3b91e95ac01df2c3c5f5776b8a6aebb31779), it escaped the reader.
    TempDir dir;
    Diagnostics diagnostics;
    EXPECT_TRUE(
        read_text(dir, "[{\"plugin_list\": [],\n  \"x\": 55e55555}]\n", diagnostics).empty());
    EXPECT_EQ(only_error(diagnostics).text(),
              (dir / "a.jsim").string() +
                  ":2: malformed JSON at column 15: number overflow parsing '55e55555'");

    Diagnostics long_number;  // a 5000-digit number is not echoed whole
    read_text(dir, "[{\"plugin_list\": [], \"x\": 1" + std::string(5000, '0') + "}]", long_number);
    EXPECT_THAT(only_error(long_number).message,
                HasSubstr("malformed JSON at column 5027: number overflow parsing '1000"));
    EXPECT_LT(only_error(long_number).message.size(), 300u);
}

}  // namespace jsim_test
}  // namespace glint::dirsig
