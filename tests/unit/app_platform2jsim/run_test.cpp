// SPDX-License-Identifier: Apache-2.0
// glint-platform2jsim's modes called in-process: .sim → .jsim conversion with relative path
// rewriting, building from parts, --append (constellations), --check, --dump-platform, and
// the failure cases (missing files, clashing prefixes, outputs naming inputs), each checked
// for its message, its status and that nothing was written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "glint/app_platform2jsim/inputs.h"
#include "glint/app_platform2jsim/platform2jsim.h"
#include "glint/core/error.h"
#include "glint/test/temp_dir.h"

namespace glint::app_platform2jsim {
namespace run_test {

namespace fs = std::filesystem;
using Json = nlohmann::json;

const fs::path kData = fs::path(GLINT_TEST_DATA_DIR) / "platform2jsim";

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

class Platform2JsimTest : public ::testing::Test {
protected:
    Platform2JsimTest() {
        m_ctx.log = Log(
            [this](LogLevel level, const std::string& message) {
                m_log.push_back(std::string(log_level_name(level)) + ": " + message);
            },
            LogLevel::debug);
    }

    /// Copies the test inputs into `folder` under the temporary folder; returns its path.
    fs::path copy_inputs(const std::string& folder) {
        const fs::path target = m_temp / folder;
        fs::create_directories(target);
        for (const char* name : {"demo.sim", "cam.platform", "hover.ppd", "other.ppd",
                                 "one_frame.tasks", "pass2.tasks", "site.scene", "clear.atm"}) {
            fs::copy_file(kData / name, target / name);
        }
        return target;
    }

    int run_mode(const Options& options) { return run(options, m_ctx, m_out); }

    bool logged(const std::string& needle) const {
        for (const std::string& line : m_log) {
            if (line.find(needle) != std::string::npos) return true;
        }
        return false;
    }

    /// The logged lines above debug level (debug has a "reading FILE" line per file opened).
    std::vector<std::string> problems() const {
        std::vector<std::string> lines;
        for (const std::string& line : m_log) {
            if (line.rfind("debug: ", 0) != 0) lines.push_back(line);
        }
        return lines;
    }

    std::string log_text() const {
        std::string text;
        for (const std::string& line : m_log) text += line + "\n";
        return text;
    }

    Options parts(const fs::path& in, const fs::path& output) const {
        Options o;
        o.mode = Mode::parts;
        o.platform = in / "cam.platform";
        o.motion = in / "hover.ppd";
        o.tasks = in / "one_frame.tasks";
        o.output = output.string();
        return o;
    }

    glint::test::TempDir m_temp;
    Context m_ctx;
    std::ostringstream m_out;
    std::vector<std::string> m_log;
};

TEST_F(Platform2JsimTest, ConvertsASimWithPathsRelativeToTheOutputFolder) {
    const fs::path in = copy_inputs("in");
    fs::create_directories(m_temp / "out");
    Options o;
    o.input = in / "demo.sim";
    o.output = (m_temp / "out" / "demo.jsim").string();
    ASSERT_EQ(run_mode(o), 0) << log_text();
    EXPECT_TRUE(m_log.empty()) << log_text();
    EXPECT_TRUE(m_out.str().empty());

    const Json j = Json::parse(read_text(o.output));
    ASSERT_TRUE(j.is_array());
    ASSERT_EQ(j.size(), 1u);
    EXPECT_EQ(j[0]["scene_list"], Json::parse(R"([{"inputs":"../in/site.scene"}])"));
    const Json& plugins = j[0]["plugin_list"];
    ASSERT_EQ(plugins.size(), 2u);
    EXPECT_EQ(plugins[0]["name"], "BasicAtmosphere");
    EXPECT_EQ(plugins[0]["inputs"]["atmosphere_filename"], "../in/clear.atm");
    EXPECT_EQ(plugins[1]["name"], "BasicPlatform");
    EXPECT_EQ(plugins[1]["inputs"]["platform_filename"], "../in/cam.platform");
    EXPECT_EQ(plugins[1]["inputs"]["motion_filename"], "../in/hover.ppd");
    EXPECT_EQ(plugins[1]["inputs"]["tasks_filename"], "../in/one_frame.tasks");
    EXPECT_FALSE(plugins[1]["inputs"]["split_channels"].get<bool>());
    EXPECT_FALSE(plugins[1]["inputs"].contains("output_prefix"));
    EXPECT_EQ(j[0]["medium_list"], Json::array());
    EXPECT_EQ(m_temp.entries(), (std::vector<std::string>{"in", "out"}));
}

TEST_F(Platform2JsimTest, ConvertBesideTheInputsGivesBareNames) {
    const fs::path in = copy_inputs("in");
    Options o;
    o.input = in / "demo.sim";
    o.output = (in / "demo.jsim").string();
    o.output_prefix = "run1_";
    o.output_folder = "images";
    o.split_channels = true;
    ASSERT_EQ(run_mode(o), 0) << log_text();
    const Json inputs = Json::parse(read_text(o.output))[0]["plugin_list"][1]["inputs"];
    EXPECT_EQ(inputs["platform_filename"], "cam.platform");
    EXPECT_EQ(inputs["output_prefix"], "run1_");
    EXPECT_EQ(inputs["output_folder"], "images");
    EXPECT_TRUE(inputs["split_channels"].get<bool>());
}

TEST_F(Platform2JsimTest, DashWritesTheJsimToTheStream) {
    Options o;
    o.input = kData / "demo.sim";
    o.output = "-";
    ASSERT_EQ(run_mode(o), 0) << log_text();
    const Json j = Json::parse(m_out.str());
    EXPECT_EQ(j[0]["plugin_list"][1]["name"], "BasicPlatform");
    EXPECT_TRUE(m_temp.entries().empty());
}

TEST_F(Platform2JsimTest, AMissingReferencedFileFailsAndWritesNothing) {
    Options o;
    o.input = kData / "missing_motion.sim";
    o.output = (m_temp / "x.jsim").string();
    EXPECT_EQ(run_mode(o), 1);
    EXPECT_TRUE(logged("error: " + o.input.string() + ":6: simulation/platformmotion:"))
        << log_text();
    EXPECT_TRUE(logged("no_such_motion.ppd")) << log_text();
    EXPECT_TRUE(logged("error: nothing written: 1 error")) << log_text();
    EXPECT_TRUE(m_temp.entries().empty());
}

TEST_F(Platform2JsimTest, ReportsEveryErrorOfEveryReferencedFile) {
    Options o;
    o.input = kData / "bad" / "broken.sim";
    o.output = (m_temp / "x.jsim").string();
    EXPECT_EQ(run_mode(o), 1);
    EXPECT_TRUE(logged("missing.ppd")) << log_text();
    EXPECT_TRUE(logged("broken.platform:14:")) << log_text();  // focallength -50
    EXPECT_TRUE(logged("missing required element <xelementcount>")) << log_text();
    EXPECT_TRUE(logged("broken.tasks:6:")) << log_text();  // stop before start
    EXPECT_TRUE(m_temp.entries().empty());
}

TEST_F(Platform2JsimTest, BuildsAJsimFromParts) {
    const fs::path in = copy_inputs("in");
    Options o = parts(in, m_temp / "built.jsim");
    o.scene = in / "site.scene";
    o.atmosphere = in / "clear.atm";
    o.output_prefix = "a_";
    ASSERT_EQ(run_mode(o), 0) << log_text();
    const Json j = Json::parse(read_text(o.output));
    EXPECT_EQ(j[0]["scene_list"][0]["inputs"], "in/site.scene");
    EXPECT_EQ(j[0]["plugin_list"][0]["inputs"]["atmosphere_filename"], "in/clear.atm");
    const Json& platform = j[0]["plugin_list"][1]["inputs"];
    EXPECT_EQ(platform["platform_filename"], "in/cam.platform");
    EXPECT_EQ(platform["motion_filename"], "in/hover.ppd");
    EXPECT_EQ(platform["tasks_filename"], "in/one_frame.tasks");
    EXPECT_EQ(platform["output_prefix"], "a_");
}

TEST_F(Platform2JsimTest, PartsWithoutSceneOrAtmosphereGiveOnlyTheBasicPlatform) {
    const fs::path in = copy_inputs("in");
    const Options o = parts(in, m_temp / "built.jsim");
    ASSERT_EQ(run_mode(o), 0) << log_text();
    const Json j = Json::parse(read_text(o.output));
    EXPECT_TRUE(j[0]["scene_list"].empty());
    ASSERT_EQ(j[0]["plugin_list"].size(), 1u);
    EXPECT_EQ(j[0]["plugin_list"][0]["name"], "BasicPlatform");
}

TEST_F(Platform2JsimTest, PartsNeedEveryPartAndAnOutput) {
    const fs::path in = copy_inputs("in");
    Options o = parts(in, m_temp / "built.jsim");
    o.tasks.clear();
    EXPECT_THROW(run_mode(o), Error);
    o = parts(in, "");
    try {
        run_mode(o);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::usage);
    }
    EXPECT_FALSE(fs::exists(m_temp / "built.jsim"));
}

TEST_F(Platform2JsimTest, AMissingPartIsReportedAgainstItsFlag) {
    const fs::path in = copy_inputs("in");
    Options o = parts(in, m_temp / "built.jsim");
    o.motion = in / "nowhere.ppd";
    EXPECT_EQ(run_mode(o), 1);
    EXPECT_TRUE(logged("error: --motion: motion file does not exist: ")) << log_text();
    EXPECT_FALSE(fs::exists(m_temp / "built.jsim"));
}

TEST_F(Platform2JsimTest, AppendAddsAConstellationMember) {
    const fs::path in = copy_inputs("in");
    Options o;
    o.input = in / "demo.sim";
    o.output = (m_temp / "c.jsim").string();
    ASSERT_EQ(run_mode(o), 0) << log_text();

    Options a = parts(in, m_temp / "c.jsim");
    a.mode = Mode::append;
    a.motion = in / "other.ppd";
    a.tasks = in / "pass2.tasks";
    a.output_prefix = "sat2_";
    ASSERT_EQ(run_mode(a), 0) << log_text();
    const Json j = Json::parse(read_text(m_temp / "c.jsim"));
    const Json& plugins = j[0]["plugin_list"];
    ASSERT_EQ(plugins.size(), 3u);
    EXPECT_EQ(plugins[1]["inputs"]["platform_filename"], "in/cam.platform");
    EXPECT_EQ(plugins[2]["name"], "BasicPlatform");
    EXPECT_EQ(plugins[2]["inputs"]["platform_filename"], "in/cam.platform");
    EXPECT_EQ(plugins[2]["inputs"]["motion_filename"], "in/other.ppd");
    EXPECT_EQ(plugins[2]["inputs"]["tasks_filename"], "in/pass2.tasks");
    EXPECT_EQ(plugins[2]["inputs"]["output_prefix"], "sat2_");
    EXPECT_EQ(j[0]["scene_list"][0]["inputs"], "in/site.scene");

    // The same prefix again: refused, the file unchanged.
    const std::string before = read_text(m_temp / "c.jsim");
    EXPECT_EQ(run_mode(a), 1);
    EXPECT_TRUE(logged("already writes with output_folder '' and output_prefix 'sat2_'"))
        << log_text();
    EXPECT_EQ(read_text(m_temp / "c.jsim"), before);
    // No prefix clashes with the first entry (which has none) too.
    a.output_prefix.reset();
    EXPECT_EQ(run_mode(a), 1);
    EXPECT_EQ(read_text(m_temp / "c.jsim"), before);
    EXPECT_EQ(m_temp.entries(), (std::vector<std::string>{"c.jsim", "in"}));
}

TEST_F(Platform2JsimTest, AppendNeedsAnExistingJsim) {
    const fs::path in = copy_inputs("in");
    Options a = parts(in, m_temp / "none.jsim");
    a.mode = Mode::append;
    EXPECT_THROW(run_mode(a), Error);
    a.output = "-";
    EXPECT_THROW(run_mode(a), Error);
    EXPECT_FALSE(fs::exists(m_temp / "none.jsim"));
}

TEST_F(Platform2JsimTest, RefusesToOverwriteAnInput) {
    const fs::path in = copy_inputs("in");
    const std::string sim_before = read_text(in / "demo.sim");
    Options o;
    o.input = in / "demo.sim";
    o.output = (in / "demo.sim").string();
    try {
        run_mode(o);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::usage);
        EXPECT_NE(std::string(e.what()).find("refusing to overwrite input"), std::string::npos);
    }
    EXPECT_EQ(read_text(in / "demo.sim"), sim_before);
    const std::string tasks_before = read_text(in / "one_frame.tasks");
    EXPECT_THROW(run_mode(parts(in, in / "one_frame.tasks")), Error);
    EXPECT_EQ(read_text(in / "one_frame.tasks"), tasks_before);
}

TEST_F(Platform2JsimTest, CheckPrintsASummaryAndExitsZeroOnGoodInputs) {
    Options o;
    o.mode = Mode::check;
    o.check_files = {kData / "demo.sim"};
    EXPECT_EQ(run_mode(o), 0) << log_text();
    EXPECT_EQ(m_out.str(), "scene " + (kData / "site.scene").string() +
                               ": 1 material, 1 object, 1 instance, 2 triangles\n"
                               "atmosphere " +
                               (kData / "clear.atm").string() +
                               ": simple, sky at 260 K\n"
                               "check: 0 errors, 0 warnings in 9 files\n");
    EXPECT_TRUE(problems().empty()) << log_text();
}

TEST_F(Platform2JsimTest, CheckListsEveryProblem) {
    Options o;
    o.mode = Mode::check;
    o.check_files = {kData / "bad" / "broken.sim"};
    EXPECT_EQ(run_mode(o), 1);
    EXPECT_THAT(m_out.str(), ::testing::EndsWith("check: 4 errors, 0 warnings in 8 files\n"));
    EXPECT_EQ(problems().size(), 4u) << log_text();
    EXPECT_FALSE(logged("nothing written"));
}

TEST_F(Platform2JsimTest, CheckTakesPlatformAndTasksFilesAlone) {
    Options o;
    o.mode = Mode::check;
    o.check_files = {kData / "cam.platform", kData / "bad" / "broken.tasks",
                     kData / "cam.platform"};
    EXPECT_EQ(run_mode(o), 1);
    EXPECT_EQ(m_out.str(), "check: 1 error, 0 warnings in 2 files\n");
}

// Two entries writing the same files: a render refuses them (the schedule's own check), so
// --check does too, besides the warning that their output names are the same.
TEST_F(Platform2JsimTest, CheckRefusesEntriesThatWriteTheSameFilesAsARenderDoes) {
    const fs::path in = copy_inputs("in");
    std::ofstream(in / "twice.jsim") << R"([{"scene_list": [], "plugin_list": [
        {"name": "BasicPlatform", "inputs": {"platform_filename": "cam.platform",
         "motion_filename": "hover.ppd", "tasks_filename": "one_frame.tasks"}},
        {"name": "BasicPlatform", "inputs": {"platform_filename": "cam.platform",
         "motion_filename": "other.ppd", "tasks_filename": "pass2.tasks"}}]}])";
    Options o;
    o.mode = Mode::check;
    o.check_files = {in / "twice.jsim"};
    EXPECT_EQ(run_mode(o), 1) << log_text();
    EXPECT_TRUE(logged("error: " + (in / "twice.jsim").string() +
                       ":4: [0].plugin_list[1]: output file \"rgb-t0000-c0000.img\" of "
                       "plugin_list[1] (instrument \"Cam\" focal plane \"RGB\") is also "
                       "written by plugin_list[0]"))
        << log_text();
    EXPECT_TRUE(logged("warning: ")) << log_text();
    EXPECT_TRUE(
        logged("plugin_list[1] (BasicPlatform) has the same output_folder '' and "
               "output_prefix ''"))
        << log_text();
    EXPECT_EQ(m_out.str(),
              "atmosphere (default: " + (in / "twice.jsim").string() +
                  " names none): parametric, aerosol optical depth 0.1 at 0.55 "
                  "um, gases (water 2.924 cm, ozone 0.332 atm-cm), multiple "
                  "scattering over ground albedo 0.2, air us_standard_1976 at 288.15 K\n"
                  "check: 2 errors, 1 warning in 6 files\n");
}

TEST_F(Platform2JsimTest, CheckReadsScenesAndAtmospheres) {
    const fs::path in = copy_inputs("in");
    std::ofstream(in / "bad.yaml") << "materials: []\nobjects:\n  - primitive: box\n"
                                      "    material: 1\n    lower: [0, 0, x]\n";
    std::ofstream(in / "sky.yaml") << "model: parametric\naerosol_optical_depth_550: -1\n";
    std::ofstream(in / "two.jsim") << R"([{"scene_list": [{"inputs": "bad.yaml"}],
        "plugin_list": [{"name": "BasicAtmosphere", "inputs": {"atmosphere_filename": "sky.yaml"}},
        {"name": "BasicPlatform", "inputs": {"platform_filename": "cam.platform",
         "motion_filename": "hover.ppd", "tasks_filename": "one_frame.tasks"}}]}])";
    Options o;
    o.mode = Mode::check;
    o.check_files = {in / "two.jsim"};
    EXPECT_EQ(run_mode(o), 1) << log_text();
    EXPECT_TRUE(logged("error: " + (in / "bad.yaml").string() +
                       ":5: objects[0].lower[2]: expected a finite number, got \"x\""))
        << log_text();
    EXPECT_TRUE(logged("error: " + (in / "sky.yaml").string() +
                       ":2: aerosol_optical_depth_550: value -1 out of range"))
        << log_text();
    EXPECT_EQ(m_out.str(), "scene " + (in / "bad.yaml").string() +
                               ": not usable, 3 errors\n"
                               "atmosphere " +
                               (in / "sky.yaml").string() +
                               ": not usable, 1 error\n"
                               "check: 4 errors, 0 warnings in 6 files\n");
}

TEST_F(Platform2JsimTest, DumpsAPlatformToTheStreamOrAFile) {
    Options o;
    o.mode = Mode::dump_platform;
    o.input = kData / "cam.platform";
    ASSERT_EQ(run_mode(o), 0) << log_text();
    const Json j = Json::parse(m_out.str());
    EXPECT_EQ(j["format"], "glint-platform");
    EXPECT_EQ(j["instruments"][0]["name"], "Cam");
    EXPECT_EQ(m_out.str().back(), '\n');

    o.output = (m_temp / "cam.json").string();
    m_out.str("");
    ASSERT_EQ(run_mode(o), 0) << log_text();
    EXPECT_TRUE(m_out.str().empty());
    EXPECT_EQ(Json::parse(read_text(o.output)), j);
}

TEST_F(Platform2JsimTest, DumpsEachBasicPlatformOfASimulation) {
    Options o;
    o.mode = Mode::dump_platform;
    o.input = kData / "demo.sim";
    ASSERT_EQ(run_mode(o), 0) << log_text();
    const Json j = Json::parse(m_out.str());
    ASSERT_TRUE(j.is_array());
    ASSERT_EQ(j.size(), 1u);
    EXPECT_EQ(j[0]["format"], "glint-platform");
    EXPECT_EQ(j[0]["instruments"][0]["focal_planes"][0]["name"], "RGB");
}

TEST_F(Platform2JsimTest, DumpOfABrokenPlatformFailsWithItsErrors) {
    Options o;
    o.mode = Mode::dump_platform;
    o.input = kData / "bad" / "broken.platform";
    o.output = (m_temp / "broken.json").string();
    EXPECT_EQ(run_mode(o), 1);
    EXPECT_TRUE(logged("expected a number > 0")) << log_text();
    EXPECT_TRUE(m_out.str().empty());
    EXPECT_TRUE(m_temp.entries().empty());
}

TEST(Platform2JsimSummary, UsesSingularForOne) {
    EXPECT_EQ(summary_text(2, 3, 4), "2 errors, 3 warnings in 4 files");
    EXPECT_EQ(summary_text(1, 1, 1), "1 error, 1 warning in 1 file");
    EXPECT_EQ(summary_text(0, 0, 0), "0 errors, 0 warnings in 0 files");
}

}  // namespace run_test
}  // namespace glint::app_platform2jsim
