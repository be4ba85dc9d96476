// SPDX-License-Identifier: Apache-2.0
// FolderLock: one holder per output folder, released with the object, no file left.
#include "glint/core/folder_lock.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "glint/core/error.h"
#include "glint/test/temp_dir.h"

namespace glint {
namespace folder_lock_test {

using ::testing::HasSubstr;

TEST(FolderLock, OneHolderAtATime) {
    test::TempDir dir;
    std::optional<FolderLock> first(std::in_place, dir.path());
    try {
        FolderLock second(dir.path());
        FAIL() << "a second lock on the same folder was granted";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::io);
        EXPECT_THAT(e.what(), HasSubstr("another glint run is writing into this output folder"));
        EXPECT_THAT(e.what(), HasSubstr(dir.path().string()));
    }
    first.reset();
    EXPECT_NO_THROW(FolderLock again(dir.path()));
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));  // nothing written into the folder
}

TEST(FolderLock, MissingFolderIsAnIoError) {
    test::TempDir dir;
    try {
        FolderLock lock(dir.path() / "nothing");
        FAIL() << "locked a folder that does not exist";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::io);
        EXPECT_THAT(e.what(), HasSubstr("cannot open the output folder"));
    }
}

}  // namespace folder_lock_test
}  // namespace glint
