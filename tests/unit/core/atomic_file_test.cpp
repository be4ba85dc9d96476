// SPDX-License-Identifier: Apache-2.0
// AtomicFile: nothing under the final name until commit; temp files never left behind.
#include "glint/core/atomic_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "glint/core/error.h"
#include "glint/test/temp_dir.h"

namespace glint {
namespace {

std::string slurp(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(AtomicFile, NothingUnderFinalNameUntilCommit) {
    test::TempDir dir;
    AtomicFile file(dir / "out.img");
    file.write("hello ");
    file.write("world");
    EXPECT_FALSE(std::filesystem::exists(dir / "out.img"));
    EXPECT_EQ(file.temp_path().parent_path(), dir.path());
    EXPECT_EQ(file.temp_path().extension(), ".img");
    file.commit();
    EXPECT_EQ(slurp(dir / "out.img"), "hello world");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.img"});
    EXPECT_EQ(file.bytes_written(), 11u);
}

TEST(AtomicFile, DestroyedWithoutCommitLeavesNothing) {
    test::TempDir dir;
    {
        AtomicFile file(dir / "out.img");
        file.write("partial");
    }
    EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicFile, FailureKeepsTheOldFile) {
    test::TempDir dir;
    write_file_atomically(dir / "out.txt", "old");
    try {
        AtomicFile file(dir / "out.txt");
        file.write("new but unfinished");
        throw runtime_error("the computation failed");
    } catch (const Error&) {
    }
    EXPECT_EQ(slurp(dir / "out.txt"), "old");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.txt"});
}

TEST(AtomicFile, LargeWritesBypassTheBuffer) {
    test::TempDir dir;
    const std::string big(3 << 20, 'x');
    AtomicFile file(dir / "big.bin");
    file.write("a");
    file.write(big);
    file.write("b");
    file.commit();
    EXPECT_EQ(slurp(dir / "big.bin"), "a" + big + "b");
}

TEST(AtomicFile, ExternalWriterThenCommit) {
    test::TempDir dir;
    AtomicFile file(dir / "frame.png");
    file.release_for_external_writer();
    {
        std::ofstream other(file.temp_path(), std::ios::binary);
        other << "written by someone else";
    }
    file.commit();
    EXPECT_EQ(slurp(dir / "frame.png"), "written by someone else");
}

TEST(AtomicFile, MissingFolderIsAnIoError) {
    test::TempDir dir;
    try {
        AtomicFile file(dir / "no-such-folder" / "out.img");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::io);
        EXPECT_NE(std::string(e.what()).find("cannot create output"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("out.img"), std::string::npos);
    }
}

TEST(AtomicFile, RefusesToOverwriteAnInput) {
    test::TempDir dir;
    write_file_atomically(dir / "in.img", "data");
    const std::vector<std::filesystem::path> inputs{dir / "in.img"};
    try {
        ensure_not_an_input(dir.path() / "." / "in.img", inputs);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::usage);
        EXPECT_NE(std::string(e.what()).find("refusing to overwrite input"), std::string::npos);
    }
    EXPECT_NO_THROW(ensure_not_an_input(dir / "out.img", inputs));
}

}  // namespace
}  // namespace glint
