// SPDX-License-Identifier: Apache-2.0
// glint-detect's entry point in-process: identical bytes for any thread count and block
// layout, the capture map from the header (and its errors), and nothing left behind when
// a line fails half-way.
#include "glint/app_detect/detect_tool.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "glint/core/error.h"
#include "glint/io/envi.h"
#include "glint/test/temp_dir.h"

namespace glint::app_detect {
namespace detect_tool_test {

using ::testing::HasSubstr;

const std::filesystem::path kPlatform =
    std::filesystem::path(GLINT_TEST_DATA_DIR) / "detect" / "cam.platform";

class DetectToolTest : public ::testing::Test {
protected:
    /// A float64 Photons/cm2 cube whose pixel (x, y) holds `base` × (1 + (x + 3y) % 17).
    std::filesystem::path cube(const std::string& name, std::size_t samples, std::size_t lines,
                               double base, io::EnviHeader header = {}) {
        header.samples = samples;
        header.lines = lines;
        header.bands = 1;
        header.data_units = "Photons/cm2";
        const auto path = m_temp / name;
        io::EnviWriter writer(path, header);
        std::vector<double> line(samples);
        for (std::size_t y = 0; y < lines; ++y) {
            for (std::size_t x = 0; x < samples; ++x) {
                line[x] = base * static_cast<double>(1 + (x + 3 * y) % 17);
            }
            writer.write_line(line);
        }
        writer.commit();
        return path;
    }

    Options options(const std::filesystem::path& input, const std::string& output) {
        Options o;
        o.input = input;
        o.output = m_temp / output;
        o.platform = kPlatform;
        o.focal_plane = "Frame";
        return o;
    }

    static std::string bytes(const std::filesystem::path& path) {
        std::ifstream in(path, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), {}};
    }

    glint::test::TempDir m_temp;
    Context m_ctx;
};

TEST_F(DetectToolTest, SameBytesForAnyThreadCount) {
    // 300 lines: several blocks of 32 lines per thread, the last one partial.
    const auto input = cube("in.img", 37, 300, 1e9);
    std::string reference;
    for (unsigned threads : {1u, 2u, 3u, 8u}) {
        m_ctx.threads = threads;
        const std::string name = "t" + std::to_string(threads) + ".img";
        const Result r = detect_file(options(input, name), m_ctx);
        EXPECT_EQ(r.lines, 300u);
        EXPECT_EQ(r.settings.seed, kDefaultSeed);
        const std::string data = bytes(m_temp / name);
        ASSERT_EQ(data.size(), 37u * 300u * 2u) << "uint16 counts";
        if (reference.empty()) {
            reference = data;
        } else {
            EXPECT_EQ(data, reference) << threads << " threads";
        }
    }
    Options other = options(input, "seed.img");
    other.seed = 2;
    detect_file(other, m_ctx);
    EXPECT_NE(bytes(m_temp / "seed.img"), reference);
}

TEST_F(DetectToolTest, CapturesFromTheHeader) {
    io::EnviHeader h;
    h.set_extra("glint lines per capture", "6");
    h.set_extra("glint capture indices", "{4, 9}");
    const auto input = cube("in.img", 8, 12, 1e9, h);
    const Result r = detect_file(options(input, "dc.img"), m_ctx);
    EXPECT_EQ(r.captures, 2u);
    EXPECT_EQ(r.lines_per_capture, 6u);
    // The same pixels labelled captures 4 and 10: the first capture's counts are the same,
    // the second's differ (its random streams are keyed by its global index).
    io::EnviHeader swapped;
    swapped.set_extra("glint lines per capture", "6");
    swapped.set_extra("glint capture indices", "{4, 10}");
    detect_file(options(cube("in2.img", 8, 12, 1e9, swapped), "dc2.img"), m_ctx);
    const std::string a = bytes(m_temp / "dc.img");
    const std::string b = bytes(m_temp / "dc2.img");
    EXPECT_EQ(a.substr(0, a.size() / 2), b.substr(0, b.size() / 2)) << "capture 4 alike";
    EXPECT_NE(a.substr(a.size() / 2), b.substr(b.size() / 2)) << "captures 9 and 10 differ";

    io::EnviHeader bad;
    bad.set_extra("glint lines per capture", "6");
    bad.set_extra("glint capture indices", "{1, 2, 3}");
    try {
        detect_file(options(cube("bad.img", 8, 12, 1e9, bad), "bad_out.img"), m_ctx);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("glint capture indices: 3 capture indices for 2 captures"));
    }
    EXPECT_FALSE(std::filesystem::exists(m_temp / "bad_out.img"));
}

TEST_F(DetectToolTest, AFailingLineLeavesNothing) {
    const auto input = cube("in.img", 8, 100, 1e9);
    {
        // Make line 70 negative by rewriting the cube with a bad value there.
        io::EnviHeader h;
        h.samples = 8;
        h.lines = 100;
        h.bands = 1;
        h.data_units = "Photons/cm2";
        io::EnviWriter writer(m_temp / "bad.img", h);
        std::vector<double> line(8, 1e9);
        for (std::size_t y = 0; y < 100; ++y) {
            line[3] = y == 70 ? -2.0 : 1e9;
            writer.write_line(line);
        }
        writer.commit();
    }
    m_ctx.threads = 2;
    try {
        detect_file(options(m_temp / "bad.img", "dc.img"), m_ctx);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_THAT(e.what(), HasSubstr("bad.img: line 70, sample 3, band 0: photon fluence -2"));
    }
    std::vector<std::string> left;
    for (const auto& entry : std::filesystem::directory_iterator(m_temp.path())) {
        left.push_back(entry.path().filename().string());
    }
    EXPECT_THAT(left,
                ::testing::UnorderedElementsAre("in.img", "in.img.hdr", "bad.img", "bad.img.hdr"));
}

}  // namespace detect_tool_test
}  // namespace glint::app_detect
