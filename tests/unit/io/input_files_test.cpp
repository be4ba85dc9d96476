// SPDX-License-Identifier: Apache-2.0
// Tests of the whole-file input read (io::read_input_file) and io::InputFiles: regular files
// are read; FIFOs, devices (/dev/zero) and folders are refused at once, unopened; the byte cap
// counts the bytes actually read (a /proc file reports no size); ENVI headers have their own,
// smaller cap; InputFiles reads through a source handed in.
#include "glint/io/input_files.h"

#include <fcntl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <string>

#include "glint/core/error.h"
#include "glint/io/envi.h"
#include "glint/test/temp_dir.h"

namespace glint::io {
namespace input_files_test {

using test::TempDir;
using ::testing::HasSubstr;

/// The glint::Error `read` throws ("" when it throws none).
template <typename Read>
std::string error_of(Read&& read) {
    try {
        read();
    } catch (const Error& error) {
        return error.what();
    }
    return {};
}

TEST(ReadInputFile, RegularFileAndFifo) {
    TempDir dir;
    std::ofstream(dir / "a.txt") << "hello\n";
    EXPECT_EQ(read_input_file(dir / "a.txt"), "hello\n");
    std::ofstream(dir / "empty.txt").close();
    EXPECT_EQ(read_input_file(dir / "empty.txt"), "");

    // A FIFO is refused by its type, without opening it: no writer is needed for the answer
    // (opening would block until one came).
    ASSERT_EQ(::mkfifo((dir / "in.fifo").c_str(), 0600), 0);
    EXPECT_EQ(error_of([&] { read_input_file(dir / "in.fifo", "in.fifo"); }),
              "in.fifo: is a FIFO (a named pipe), expected a file");
    // A link to a regular file is read.
    std::filesystem::create_symlink(dir / "a.txt", dir / "link.txt");
    EXPECT_EQ(read_input_file(dir / "link.txt"), "hello\n");
}

TEST(ReadInputFile, DevicesAndFoldersAreRefusedAtOnce) {
    for (const char* device : {"/dev/zero", "/dev/urandom"}) {
        if (!std::filesystem::exists(device)) continue;
        EXPECT_EQ(error_of([&] { read_input_file(device); }),
                  std::string(device) + ": is a device, expected a file");
        EXPECT_EQ(error_of([&] { read_input_file(device, "scene.tasks"); }),
                  "scene.tasks: is a device, expected a file");
    }
    TempDir dir;
    EXPECT_EQ(error_of([&] { read_input_file(dir.path(), "d"); }),
              "d: is a folder, expected a file");
    EXPECT_EQ(error_of([&] { read_input_file(dir / "none.txt", "none.txt"); }),
              "none.txt: cannot open file: No such file or directory");
}

TEST(ReadInputFile, CapCountsTheBytesRead) {
    TempDir dir;
    std::ofstream(dir / "exact.txt") << std::string(1024, 'x');
    EXPECT_EQ(read_input_file(dir / "exact.txt", "exact.txt", 1024).size(), 1024u);
    std::ofstream(dir / "big.txt") << std::string(1025, 'x');
    EXPECT_EQ(error_of([&] { read_input_file(dir / "big.txt", "big.txt", 1024); }),
              "big.txt: larger than 1024 bytes (a device or not a text file?)");

    // A /proc file reports no size: the cap stops the read itself.
    if (std::filesystem::exists("/proc/self/status")) {
        try {
            read_input_file("/proc/self/status", "status", 16);
            ADD_FAILURE() << "no error";
        } catch (const Error& error) {
            EXPECT_EQ(error.category(), ErrorCategory::input);
            EXPECT_EQ(error.context().file, "status");
            EXPECT_EQ(error.message(), "larger than 16 bytes (a device or not a text file?)");
        }
    }
}

TEST(InputFiles, ReadsThroughTheSourceGiven) {
    int calls = 0;
    InputFiles files({}, [&calls](const std::filesystem::path& path, const std::string& name) {
        ++calls;
        if (path == "/virtual/a.txt") return std::string("in memory");
        throw io_error("cannot open file: No such file or directory", name);
    });
    EXPECT_EQ(files.text("/virtual/a.txt", "a.txt"), "in memory");
    EXPECT_EQ(files.text("/virtual/./a.txt", "a.txt"), "in memory");  // kept, not read again
    EXPECT_EQ(calls, 1);
    EXPECT_EQ(files.open_count("/virtual/a.txt"), 1u);
    EXPECT_EQ(error_of([&] { files.text("/virtual/b.txt", "b.txt"); }),
              "b.txt: cannot open file: No such file or directory");
}

TEST(EnviHeaderRead, DeviceAndOversizedHeadersAreRefused) {
    TempDir dir;
    std::ofstream(dir / "x.img") << std::string(4, '\0');
    std::filesystem::create_symlink("/dev/zero", dir / "x.img.hdr");
    EXPECT_EQ(error_of([&] { EnviReader reader(dir / "x.img"); }),
              (dir / "x.img.hdr").string() + ": is a device, expected a file");

    std::ofstream(dir / "y.img") << std::string(4, '\0');
    std::ofstream(dir / "y.img.hdr") << "ENVI\n" << std::string(16u << 20, ' ');
    EXPECT_EQ(error_of([&] { EnviReader reader(dir / "y.img"); }),
              (dir / "y.img.hdr").string() +
                  ": larger than 16777216 bytes (a device or not a text file?)");
}

}  // namespace input_files_test
}  // namespace glint::io
