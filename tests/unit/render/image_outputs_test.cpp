// SPDX-License-Identifier: Apache-2.0
// ImageOutputs (glint/render/image_outputs.h), the ENVI files of a render: a planned file is
// created at its first capture, receives each capture's lines in order, and is published —
// under its final name, with `lines` = captures × lines per capture and the `glint capture`
// keys — only when its last capture is in; a file still incomplete when the object goes
// away leaves nothing; planning a path twice adds captures (same shape) or is a usage error
// (another shape); writes to an unplanned path or of the wrong size are internal errors.
#include "glint/render/image_outputs.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "glint/core/error.h"
#include "glint/io/envi.h"
#include "glint/test/temp_dir.h"

namespace glint::render {
namespace image_outputs_test {

namespace fs = std::filesystem;

/// A 2-sample, 1-band header (float64: values compare exactly).
io::EnviHeader small_header() {
    io::EnviHeader h;
    h.description = "image outputs test";
    h.samples = 2;
    h.bands = 1;
    h.data_type = io::EnviDataType::float64;
    return h;
}

/// Capture `capture` of task 0 over [t0, t0 + 0.25 s] (sums exact in binary).
CaptureStamp stamp(std::uint64_t capture, double t0_s) {
    return {0, capture, t0_s, t0_s + 0.25, "2020-06-21T16:00:00Z", capture};
}

/// Capture `k`'s 3 lines × 2 samples: values 10k + 0..5.
std::vector<double> capture_values(int k) {
    std::vector<double> v(6);
    for (int i = 0; i < 6; ++i) v[static_cast<std::size_t>(i)] = 10.0 * k + i;
    return v;
}

TEST(ImageOutputs, PublishedOnlyWhenTheLastCaptureIsIn) {
    const test::TempDir dir;
    const fs::path file = dir / "out" / "frame.img";  // the folder is created at need
    ImageOutputs outputs;
    outputs.plan(file, small_header(), 3, 2);
    EXPECT_EQ(outputs.planned(), std::vector<fs::path>{file});
    EXPECT_FALSE(fs::exists(dir / "out")) << "nothing is created when planned";

    outputs.write_capture(file, capture_values(0), stamp(0, 0.0));
    EXPECT_TRUE(outputs.published().empty());
    EXPECT_FALSE(fs::exists(file));
    EXPECT_FALSE(fs::exists(io::envi_header_path_for(file)));

    outputs.write_capture(file, capture_values(1), stamp(1, 0.5));
    EXPECT_EQ(outputs.published(), std::vector<fs::path>{file});
    io::EnviHeader header;
    const std::vector<double> values = io::read_envi_bip(file, &header);
    EXPECT_EQ(header.samples, 2u);
    EXPECT_EQ(header.lines, 6u);  // 2 captures × 3 lines
    EXPECT_EQ(header.bands, 1u);
    EXPECT_EQ(header.find_extra("glint captures"), "2");
    EXPECT_EQ(header.find_extra("glint lines per capture"), "3");
    EXPECT_EQ(header.find_extra("glint capture ids"), "{t0c0, t0c1}");
    EXPECT_EQ(header.find_extra("glint capture indices"), "{0, 1}");
    EXPECT_EQ(header.find_extra("glint capture windows s"), "{0 0.25, 0.5 0.75}");
    std::vector<double> expected = capture_values(0);
    const std::vector<double> second = capture_values(1);
    expected.insert(expected.end(), second.begin(), second.end());
    EXPECT_EQ(values, expected) << "captures appended along the line axis, in order";
}

TEST(ImageOutputs, FilesArePublishedInCompletionOrder) {
    const test::TempDir dir;
    ImageOutputs outputs;
    outputs.plan(dir / "a.img", small_header(), 3, 2);
    outputs.plan(dir / "b.img", small_header(), 3, 1);
    outputs.write_capture(dir / "a.img", capture_values(0), stamp(0, 0.0));
    outputs.write_capture(dir / "b.img", capture_values(1), stamp(1, 0.0));
    outputs.write_capture(dir / "a.img", capture_values(2), stamp(2, 0.5));
    EXPECT_EQ(outputs.planned(), (std::vector<fs::path>{dir / "a.img", dir / "b.img"}));
    EXPECT_EQ(outputs.published(), (std::vector<fs::path>{dir / "b.img", dir / "a.img"}));
}

TEST(ImageOutputs, IncompleteFileLeavesNothing) {
    const test::TempDir dir;
    {
        ImageOutputs outputs;
        outputs.plan(dir / "frame.img", small_header(), 3, 2);
        outputs.write_capture(dir / "frame.img", capture_values(0), stamp(0, 0.0));
    }
    EXPECT_EQ(dir.entries(), std::vector<std::string>{}) << "no final name, no temporary file";
}

TEST(ImageOutputs, PlanningAPathTwiceAddsCapturesOfTheSameShape) {
    const test::TempDir dir;
    ImageOutputs outputs;
    outputs.plan(dir / "frame.img", small_header(), 3, 1);
    outputs.plan(dir / "frame.img", small_header(), 3, 1);
    EXPECT_EQ(outputs.planned().size(), 1u);
    outputs.write_capture(dir / "frame.img", capture_values(0), stamp(0, 0.0));
    EXPECT_TRUE(outputs.published().empty());
    outputs.write_capture(dir / "frame.img", capture_values(1), stamp(1, 0.5));
    io::EnviHeader header;
    io::read_envi_bip(dir / "frame.img", &header);
    EXPECT_EQ(header.lines, 6u);

    io::EnviHeader wider = small_header();
    wider.samples = 3;
    try {
        outputs.plan(dir / "frame.img", wider, 3, 1);
        FAIL() << "expected a usage error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::usage);
        EXPECT_EQ(e.message(), "output " + (dir / "frame.img").string() +
                                   " is written by two focal planes of different shapes");
    }
}

TEST(ImageOutputs, WrongWritesAreInternalErrors) {
    const test::TempDir dir;
    ImageOutputs outputs;
    outputs.plan(dir / "frame.img", small_header(), 3, 1);
    auto category_of = [](auto&& write) {
        try {
            write();
        } catch (const Error& e) {
            return e.category();
        }
        ADD_FAILURE() << "expected an error";
        return ErrorCategory::runtime;
    };
    EXPECT_EQ(category_of([&] {
                  outputs.write_capture(dir / "other.img", capture_values(0), stamp(0, 0.0));
              }),
              ErrorCategory::internal);
    EXPECT_EQ(category_of([&] {
                  outputs.write_capture(dir / "frame.img", std::vector<double>(5, 0.0),
                                        stamp(0, 0.0));
              }),
              ErrorCategory::internal);
    outputs.write_capture(dir / "frame.img", capture_values(0), stamp(0, 0.0));
    EXPECT_EQ(category_of([&] {
                  outputs.write_capture(dir / "frame.img", capture_values(1), stamp(1, 0.5));
              }),
              ErrorCategory::internal);
}

}  // namespace image_outputs_test
}  // namespace glint::render
