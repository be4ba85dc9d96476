// SPDX-License-Identifier: Apache-2.0
// The installed data folder lookup (glint/core/install_paths.h): $GLINT_DATA_DIR, then
// <exe dir>/../share/glint when it holds the marker file, then the built-in folder.
#include "glint/core/install_paths.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace glint {
namespace install_paths_test {

namespace fs = std::filesystem;

class InstallPathsTest : public ::testing::Test {
protected:
    void SetUp() override {
        root = fs::temp_directory_path() /
               ("glint_install_paths_" +
                std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(root);
        fs::create_directories(root / "bin");
    }
    void TearDown() override { fs::remove_all(root); }
    void install_marker() {
        fs::create_directories(root / "share" / "glint" / "solar");
        std::ofstream(root / "share" / "glint" / "solar" / "astm_g173.csv") << "x\n";
    }
    fs::path root;
};

TEST_F(InstallPathsTest, ExecutablePathIsThisTest) {
    const fs::path exe = executable_path();
    ASSERT_FALSE(exe.empty());
    EXPECT_TRUE(exe.is_absolute());
    EXPECT_TRUE(fs::exists(exe));
}

TEST_F(InstallPathsTest, InstalledDataDirIsShareGlintBesideBin) {
    EXPECT_EQ(installed_data_dir("/opt/glint/bin/glint-render"),
              fs::path("/opt/glint/share/glint"));
    EXPECT_TRUE(installed_data_dir({}).empty());
}

TEST_F(InstallPathsTest, EnvironmentComesFirst) {
    install_marker();
    DataDirCandidates c;
    c.environment = "/somewhere/else";
    c.executable = root / "bin" / "glint-render";
    c.built_in = "/source/data";
    EXPECT_EQ(data_dir_lookup(c), fs::path("/somewhere/else"));
}

TEST_F(InstallPathsTest, InstalledFolderWhenItHoldsTheMarker) {
    install_marker();
    DataDirCandidates c;
    c.executable = root / "bin" / "glint-render";
    c.built_in = "/source/data";
    EXPECT_EQ(data_dir_lookup(c), (root / "share" / "glint").lexically_normal());
}

TEST_F(InstallPathsTest, BuiltInWhenNotInstalled) {
    fs::create_directories(root / "share" / "glint");  // no marker: not an install
    DataDirCandidates c;
    c.executable = root / "bin" / "glint-render";
    c.built_in = "/source/data";
    EXPECT_EQ(data_dir_lookup(c), fs::path("/source/data"));
    c.executable.clear();
    EXPECT_EQ(data_dir_lookup(c), fs::path("/source/data"));
}

}  // namespace install_paths_test
}  // namespace glint
