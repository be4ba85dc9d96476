// SPDX-License-Identifier: Apache-2.0
// glint::Error: message formatting with and without location, context added at boundaries.
#include "glint/core/error.h"

#include <gtest/gtest.h>

namespace glint {
namespace error_test {

TEST(Error, FormatsFileLineElementAndMessage) {
    const Error e = input_error("matrix has 15 values, expected 16",
                                ErrorContext{"scene.glist", 42, "<instance>"});
    EXPECT_STREQ(e.what(), "scene.glist:42: <instance>: matrix has 15 values, expected 16");
    EXPECT_EQ(e.message(), "matrix has 15 values, expected 16");
    EXPECT_EQ(e.category(), ErrorCategory::input);
}

TEST(Error, LeavesOutUnknownParts) {
    EXPECT_STREQ(input_error("bad").what(), "bad");
    EXPECT_STREQ(input_error("bad", ErrorContext{"a.hdr", 0, {}}).what(), "a.hdr: bad");
    EXPECT_STREQ(input_error("bad", ErrorContext{{}, 0, "samples"}).what(), "samples: bad");
}

TEST(Error, WithFileFillsOnlyMissingContext) {
    const Error inner = input_error("unknown key", ErrorContext{{}, 0, "fluxunits"});
    const Error outer = inner.with_file("cam.platform", 7);
    EXPECT_STREQ(outer.what(), "cam.platform:7: fluxunits: unknown key");
    const Error kept = outer.with_file("other.platform", 9);
    EXPECT_STREQ(kept.what(), "cam.platform:7: fluxunits: unknown key");
}

TEST(Error, CategoriesOfShorthands) {
    EXPECT_EQ(usage_error("x").category(), ErrorCategory::usage);
    EXPECT_EQ(io_error("x", "f").category(), ErrorCategory::io);
    EXPECT_STREQ(io_error("cannot open", "f.img").what(), "f.img: cannot open");
    EXPECT_EQ(runtime_error("x").category(), ErrorCategory::runtime);
    EXPECT_STREQ(internal_error("oops").what(), "internal error: oops");
}

}  // namespace error_test
}  // namespace glint
