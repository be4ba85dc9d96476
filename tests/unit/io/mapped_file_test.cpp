// SPDX-License-Identifier: Apache-2.0
// Tests of read-only file mappings (glint/io/mapped_file.h): the bytes at an offset, the map
// outliving the file's removal, and a file too short or missing refused naming it.
#include "glint/io/mapped_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "glint/core/error.h"
#include "glint/test/temp_dir.h"

namespace glint::io {
namespace mapped_file_test {

TEST(MappedFile, BytesAtAnOffsetOutliveTheFile) {
    test::TempDir dir;
    const auto path = dir.path() / "codes.bin";
    std::ofstream(path, std::ios::binary) << "HEADER\x01\x02\x03";
    const auto bytes = map_file_bytes(path, 6, 3);
    std::filesystem::remove(path);  // the mapping keeps the data
    EXPECT_EQ(bytes.get()[0], 1);
    EXPECT_EQ(bytes.get()[2], 3);
    const auto copy = bytes;  // shared: unmapped with the last copy
    EXPECT_EQ(copy.get(), bytes.get());
}

TEST(MappedFile, TooShortOrMissingIsRefused) {
    test::TempDir dir;
    const auto path = dir.path() / "short.bin";
    std::ofstream(path, std::ios::binary) << "abc";
    try {
        map_file_bytes(path, 2, 5);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_NE(e.message().find("holds 3 bytes, expected at least 7"), std::string::npos)
            << e.message();
    }
    try {
        map_file_bytes(dir.path() / "gone.bin", 0, 1);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::io);
        EXPECT_NE(e.message().find("cannot open"), std::string::npos) << e.message();
    }
}

}  // namespace mapped_file_test
}  // namespace glint::io
