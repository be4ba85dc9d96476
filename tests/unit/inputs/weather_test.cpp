// SPDX-License-Identifier: Apache-2.0
// Tests of the simulation's weather history (glint/inputs/weather.h): the ThermWeather
// plugin's file relative to the .jsim, else the .atm's relative to the .atm; the plugin's
// winning over the .atm's with a warning; a missing file an error when a material uses THERM
// and a warning otherwise; a bad row an error at its line either way.
#include "glint/inputs/weather.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "glint/test/diagnostics.h"
#include "glint/test/temp_dir.h"

namespace glint::inputs {
namespace weather_test {

using glint::test::TempDir;
using ::testing::HasSubstr;

const std::string kTwoRows =
    "2 0.25\n0.00 10.00 1000.00  0.50  2.00   3.00     0.00     0.00 1.00  0  0   0.00 10.00\n"
    "0.25 11.00 1000.00  0.50  2.00   3.00     0.00     0.00 1.00  0  0   0.00 11.00\n";

model::Simulation with_plugin(const TempDir& dir, const std::string& inputs_json) {
    model::Simulation simulation;
    simulation.file = (dir.path() / "sim.jsim").string();
    model::Plugin plugin;
    plugin.name = "ThermWeather";
    plugin.inputs_json = inputs_json;
    plugin.where = ErrorContext{simulation.file, 7, "[0].plugin_list[2]"};
    simulation.plugins.push_back(plugin);
    return simulation;
}

model::Atmosphere atm_naming(const TempDir& dir, const std::string& file) {
    model::Atmosphere a;
    a.source = (dir.path() / "sub" / "site.atm").string();
    a.weather_file = file;
    a.weather_where = ErrorContext{a.source, 9, "uniformweather/classicdata/filename"};
    return a;
}

TEST(SimulationWeather, ThePluginsFileWinsOverTheAtms) {
    TempDir dir;
    std::ofstream(dir.path() / "day.wth") << kTwoRows;
    Diagnostics diagnostics;
    const model::Weather w =
        read_simulation_weather(with_plugin(dir, R"({"filename": "day.wth"})"),
                                atm_naming(dir, "other.wth"), {}, true, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors()) << test::diagnostics_text(diagnostics);
    ASSERT_EQ(w.records.size(), 2u);
    EXPECT_NEAR(w.records[1].air_temperature_k, 284.15, 1e-12);
    EXPECT_EQ(w.where.line, 7);
    ASSERT_EQ(diagnostics.warning_count(), 1u);
    EXPECT_THAT(test::diagnostics_text(diagnostics),
                HasSubstr("site.atm:9: uniformweather/classicdata/filename: weather file "
                          "other.wth is not read: the ThermWeather plugin's day.wth is"));
}

TEST(SimulationWeather, TheAtmsFileIsRelativeToTheAtm) {
    TempDir dir;
    std::filesystem::create_directories(dir.path() / "sub");
    std::ofstream(dir.path() / "sub" / "mls.wth") << kTwoRows;
    Diagnostics diagnostics;
    const model::Weather w = read_simulation_weather(
        model::Simulation{}, atm_naming(dir, "mls.wth"), {}, false, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors()) << test::diagnostics_text(diagnostics);
    EXPECT_EQ(w.records.size(), 2u);
    EXPECT_EQ(diagnostics.warning_count(), 0u) << test::diagnostics_text(diagnostics);
}

TEST(SimulationWeather, AMissingFileIsAnErrorOnlyWhenNeeded) {
    TempDir dir;
    for (bool needed : {true, false}) {
        Diagnostics diagnostics;
        const model::Weather w =
            read_simulation_weather(with_plugin(dir, R"({"filename": "none.wth"})"),
                                    model::Atmosphere{}, {}, needed, diagnostics);
        EXPECT_TRUE(w.empty());
        EXPECT_EQ(diagnostics.has_errors(), needed);
        EXPECT_THAT(test::diagnostics_text(diagnostics),
                    HasSubstr("sim.jsim:7: [0].plugin_list[2]: weather file "));
        EXPECT_THAT(test::diagnostics_text(diagnostics), HasSubstr("none.wth does not exist"));
    }
    Diagnostics extra;
    (void)read_simulation_weather(with_plugin(dir, R"({"filename": "none.wth", "year": 1992})"),
                                  model::Atmosphere{}, {}, false, extra);
    EXPECT_THAT(test::diagnostics_text(extra),
                HasSubstr("sim.jsim:7: [0].plugin_list[2]: unknown key \"year\" in ThermWeather "
                          "inputs ignored"));
    Diagnostics no_input;
    (void)read_simulation_weather(with_plugin(dir, "{}"), model::Atmosphere{}, {}, true, no_input);
    EXPECT_THAT(test::only_error(no_input).message,
                HasSubstr("plugin \"ThermWeather\" has no \"filename\" input"));
    // A bad row is an error whether or not the weather is needed.
    std::ofstream(dir.path() / "bad.wth")
        << "1 0.25\n0.00 10.00 1000.00 50.0 2.00 3.00 0 0 1 0 0 0 10\n";
    Diagnostics bad;
    (void)read_simulation_weather(with_plugin(dir, R"({"filename": "bad.wth"})"),
                                  model::Atmosphere{}, {}, false, bad);
    EXPECT_THAT(test::only_error(bad).message, HasSubstr("relative humidity 50 is not a fraction"));
    // Needed and none named: an error at the simulation.
    Diagnostics none;
    model::Simulation bare;
    bare.file = "bare.jsim";
    EXPECT_TRUE(read_simulation_weather(bare, model::Atmosphere{}, {}, true, none).empty());
    EXPECT_THAT(test::only_error(none).message, HasSubstr("names no weather"));
    Diagnostics unneeded;
    (void)read_simulation_weather(bare, model::Atmosphere{}, {}, false, unneeded);
    EXPECT_TRUE(unneeded.items().empty());
    model::Scene scene;
    EXPECT_FALSE(needs_weather(scene));
    scene.materials.emplace_back().therm = model::ThermProperties{};
    EXPECT_TRUE(needs_weather(scene));
}

}  // namespace weather_test
}  // namespace glint::inputs
