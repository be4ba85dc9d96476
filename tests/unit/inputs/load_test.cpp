// SPDX-License-Identifier: Apache-2.0
// inputs::load opens every file of a simulation exactly once: the demo (.sim, YAML scene, OBJ
// meshes, material tables, FlexMotion, YAML atmosphere, platform, .ppd, tasks), a DIRSIG
// classic scene (.scene, .glist, .mat, .atm), BasicPlatform entries that share a platform
// file, a platform whose mount jitter names a PSD file, and an external trigger file; the
// opens are counted through the reader layer (io::InputFiles), and logged at debug level.
#include "glint/inputs/load.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "glint/core/log.h"
#include "glint/dirsig/readers.h"
#include "glint/test/temp_dir.h"

namespace glint::inputs {
namespace load_test {

namespace fs = std::filesystem;

const fs::path kData = GLINT_TEST_DATA_DIR;
const fs::path kDemo = fs::path(GLINT_SOURCE_DIR) / "examples" / "demo" / "sim";

struct Loaded {
    model::SimulationInputs inputs;
    std::shared_ptr<io::InputFiles> files;
    std::vector<std::string> debug_lines;
};

Loaded load_counting(const fs::path& file) {
    Loaded loaded;
    const Log log(
        [&loaded](LogLevel level, const std::string& message) {
            if (level == LogLevel::debug && message.rfind("reading ", 0) == 0) {
                loaded.debug_lines.push_back(message);
            }
        },
        LogLevel::debug);
    loaded.files = std::make_shared<io::InputFiles>(log);
    LoadOptions options;
    options.read.files = loaded.files;
    Diagnostics diagnostics;
    loaded.inputs = load(file, options, log, diagnostics);
    return loaded;
}

/// How many times each file was opened.
std::map<fs::path, int> open_counts(const io::InputFiles& files) {
    std::map<fs::path, int> counts;
    for (const fs::path& path : files.opened()) ++counts[path];
    return counts;
}

void expect_each_opened_once(const io::InputFiles& files) {
    for (const auto& [path, count] : open_counts(files)) {
        EXPECT_EQ(count, 1) << path << " was opened " << count << " times";
    }
}

bool opened(const io::InputFiles& files, const fs::path& path) {
    return files.open_count(path) == 1;
}

TEST(InputsLoad, TheDemoOpensEachFileOnce) {
    const Loaded loaded = load_counting(kDemo / "demo.sim");
    expect_each_opened_once(*loaded.files);
    for (const char* name : {"demo.sim", "demo_scene.yaml", "car.obj", "house.obj", "car.motion",
                             "demo_atmosphere.yaml", "demo.platform", "demo.ppd", "demo.tasks"}) {
        EXPECT_TRUE(opened(*loaded.files, kDemo / name)) << name;
    }
    // Every open was logged at debug level ("-vv"), once.
    EXPECT_EQ(loaded.debug_lines.size(), loaded.files->opened().size());
    EXPECT_THAT(loaded.debug_lines, testing::Contains(testing::HasSubstr("demo.platform")));
    ASSERT_EQ(loaded.inputs.platforms.size(), 1u);
    EXPECT_FALSE(loaded.inputs.scene.objects.empty());
}

TEST(InputsLoad, ADirsigClassicSceneOpensEachFileOnce) {
    const Loaded loaded = load_counting(kData / "legacy" / "example.sim");
    expect_each_opened_once(*loaded.files);
    for (const char* name : {"example.sim", "site.scene", "ground.glist", "site.mat", "clear.atm",
                             "cam.platform", "hover.ppd"}) {
        EXPECT_TRUE(opened(*loaded.files, kData / "legacy" / name)) << name;
    }
}

TEST(InputsLoad, EntriesSharingAPlatformFileOpenItOnce) {
    // Two BasicPlatform entries name ../platform/two_instruments.platform; a third entry's
    // platform has mounts with PSD jitter files.
    const Loaded loaded = load_counting(kData / "poses" / "poses.jsim");
    expect_each_opened_once(*loaded.files);
    EXPECT_TRUE(opened(*loaded.files, kData / "platform" / "two_instruments.platform"));
    EXPECT_EQ(loaded.inputs.platforms.size(), 3u);
    // The two entries that share the file share its model (parsed, and reported, once).
    EXPECT_EQ(loaded.inputs.platforms[0].platform, loaded.inputs.platforms[1].platform);
}

TEST(InputsLoad, AFileTwoEntriesNameReportsItsWarningsOnce) {
    // aviris.platform has one warning (a channel centre outside the bandpass); two entries
    // name it: it is parsed once, so the warning is reported once.
    test::TempDir dir;
    const fs::path legacy = kData / "legacy";
    const std::string entry = R"({"name": "BasicPlatform", "inputs": {"platform_filename": ")" +
                              (kData / "platform" / "aviris.platform").string() +
                              R"(", "motion_filename": ")" + (legacy / "hover.ppd").string() +
                              R"(", "tasks_filename": ")" + (legacy / "one_frame.tasks").string() +
                              R"(", "output_prefix": "P"}})";
    std::string second = entry;
    second.replace(second.find("\"P\""), 3, "\"Q\"");
    std::ofstream(dir / "two.jsim")
        << "[{\"scene_list\": [], \"plugin_list\": [" << entry << ", " << second << "]}]";
    Diagnostics diagnostics;
    LoadOptions options;
    options.atmosphere = false;
    const model::SimulationInputs inputs = load(dir / "two.jsim", options, Log{}, diagnostics);
    ASSERT_EQ(inputs.platforms.size(), 2u);
    std::size_t warnings = 0;
    for (const Diagnostic& d : diagnostics.items()) {
        warnings += d.where.file.find("aviris.platform") != std::string::npos ? 1 : 0;
    }
    EXPECT_EQ(warnings, 1u);
}

TEST(InputsLoad, PsdFilesAreReadIntoTheModel) {
    // mounts.platform: a mount's across-track jitter names jitter_psd.txt.
    Diagnostics diagnostics;
    auto files = std::make_shared<io::InputFiles>();
    dirsig::ReadOptions options;
    options.files = files;
    model::Platform platform =
        dirsig::read_platform(kData / "platform" / "mounts.platform", options, diagnostics);
    read_psd_tables(platform, options, diagnostics);
    ASSERT_FALSE(diagnostics.has_errors());
    EXPECT_TRUE(opened(*files, kData / "platform" / "jitter_psd.txt"));
    expect_each_opened_once(*files);
    bool found = false;
    for (const model::InstrumentPath& path : model::list_instruments(platform)) {
        for (const model::Mount* mount : path.mounts) {
            for (const model::JitterSpec& axis : mount->deviates.axes) {
                if (axis.kind != model::JitterSpec::Kind::psd) continue;
                ASSERT_TRUE(axis.psd.has_value());
                EXPECT_GE(axis.psd->frequency_hz.size(), 2u);
                found = true;
            }
        }
    }
    EXPECT_TRUE(found);
}

TEST(InputsLoad, TriggerFilesAreReadOnceIntoTheClock) {
    const Loaded loaded = load_counting(kData / "schedule" / "clocks.jsim");
    expect_each_opened_once(*loaded.files);
    EXPECT_TRUE(opened(*loaded.files, kData / "schedule" / "triggers.txt"));
    bool found = false;
    for (const model::PlatformInputs& entry : loaded.inputs.platforms) {
        for (const model::InstrumentPath& path : model::list_instruments(*entry.platform)) {
            for (const model::FocalPlane& plane : path.instrument->focal_planes) {
                const model::Clock& clock = plane.detector_array.clock;
                if (clock.type != model::ClockType::external_trigger) continue;
                EXPECT_FALSE(clock.trigger_times_s.empty());
                found = true;
            }
        }
    }
    EXPECT_TRUE(found);
}

}  // namespace load_test
}  // namespace glint::inputs
