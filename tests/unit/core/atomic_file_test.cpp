// SPDX-License-Identifier: Apache-2.0
// AtomicFile: nothing under the final name until commit; temp files never left behind.
#include "glint/core/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "glint/core/error.h"
#include "glint/test/temp_dir.h"

namespace glint {
namespace atomic_file_test {

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

// ---- targets that are not plain files (never renamed over) --------------------------------

/// The file names in `folder`.
std::vector<std::string> names_in(const std::filesystem::path& folder) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

TEST(AtomicFile, AFifoIsWrittenStraightAndStaysAFifo) {
    // A FIFO stands for every target that is not a regular file (/dev/null, /dev/stdout's
    // pipe or terminal): the bytes reach its reader and the FIFO is not replaced.
    test::TempDir dir;
    const std::filesystem::path fifo = dir / "out.fifo";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::string received;
    std::thread reader([&] { received = slurp(fifo); });
    {
        AtomicFile file(fifo);
        EXPECT_TRUE(file.direct());
        EXPECT_EQ(file.temp_path(), fifo);
        file.write("through the pipe");
        file.commit();
    }
    reader.join();
    EXPECT_EQ(received, "through the pipe");
    struct stat info {};
    ASSERT_EQ(::lstat(fifo.c_str(), &info), 0);
    EXPECT_TRUE(S_ISFIFO(info.st_mode));
    EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"out.fifo"});  // no temporary
}

TEST(AtomicFile, ASymlinkIsPublishedAtItsTargetAndStaysALink) {
    test::TempDir dir;
    std::filesystem::create_directory(dir / "real");
    write_file_atomically(dir / "real" / "data.txt", "old");
    std::filesystem::create_symlink("real/data.txt", dir / "link.txt");
    {
        AtomicFile file(dir / "link.txt");
        EXPECT_FALSE(file.direct());
        EXPECT_EQ(file.temp_path().parent_path(), dir / "real");  // beside the file it names
        file.write("new");
        file.commit();
    }
    EXPECT_TRUE(std::filesystem::is_symlink(dir / "link.txt"));
    EXPECT_EQ(slurp(dir / "real" / "data.txt"), "new");
    EXPECT_EQ(names_in(dir / "real"), std::vector<std::string>{"data.txt"});
    // A link to a file that does not exist yet creates that file.
    std::filesystem::create_symlink("real/later.txt", dir / "dangling.txt");
    write_file_atomically(dir / "dangling.txt", "created");
    EXPECT_TRUE(std::filesystem::is_symlink(dir / "dangling.txt"));
    EXPECT_EQ(slurp(dir / "real" / "later.txt"), "created");
}

TEST(AtomicFile, AFolderIsRefused) {
    test::TempDir dir;
    std::filesystem::create_directory(dir / "sub");
    try {
        AtomicFile file(dir / "sub");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::io);
        EXPECT_NE(std::string(e.what()).find("is a folder"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(std::filesystem::is_directory(dir / "sub"));
}

}  // namespace atomic_file_test
}  // namespace glint
