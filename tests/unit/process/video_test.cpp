// SPDX-License-Identifier: Apache-2.0
// Tests of the ffmpeg wrapper: frame lists and patterns encode to a video with the right
// frame count (ffprobe counts them), failures leave no output and name the file, a missing
// ffmpeg gives the install hint. Skipped when ffmpeg or ffprobe is not installed.
#include "glint/process/video.h"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <fstream>

#include "glint/core/error.h"
#include "glint/process/process.h"

namespace glint::process {
namespace video_test {

namespace fs = std::filesystem;

class VideoTest : public ::testing::Test {
protected:
    void SetUp() override {
        std::string templ = (fs::temp_directory_path() / "glint-video-test-XXXXXX").string();
        ASSERT_NE(::mkdtemp(templ.data()), nullptr);
        m_dir = templ;
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(m_dir, ec);
    }

    /// Writes a binary PPM whose grey level depends on `index`.
    fs::path write_frame(const std::string& name, int index, int width = 16, int height = 12) {
        const fs::path path = m_dir / name;
        std::ofstream out(path, std::ios::binary);
        out << "P6\n" << width << " " << height << "\n255\n";
        for (int i = 0; i < width * height; ++i) {
            const char v = static_cast<char>(20 * index);
            out.put(v).put(v).put(v);
        }
        return path;
    }

    static bool have_ffmpeg() {
        return find_program("ffmpeg").has_value() && find_program("ffprobe").has_value();
    }

    static long count_frames(const fs::path& video) {
        ProcessOptions options;
        options.argv = {"ffprobe",
                        "-v",
                        "error",
                        "-count_frames",
                        "-select_streams",
                        "v:0",
                        "-show_entries",
                        "stream=nb_read_frames",
                        "-of",
                        "csv=p=0",
                        video.string()};
        options.stdout_mode = OutputMode::capture;
        const ProcessResult r = run_process(options);
        EXPECT_TRUE(r.success()) << r.stderr_text;
        return std::stol(r.stdout_text);
    }

    bool no_temporaries_left() const {
        for (const auto& entry : fs::directory_iterator(m_dir)) {
            if (entry.path().filename().string().find(".tmp-") != std::string::npos) {
                return false;
            }
        }
        return true;
    }

    fs::path m_dir;
    Context m_ctx;
};

TEST_F(VideoTest, FrameListEncodes) {
    if (!have_ffmpeg()) GTEST_SKIP() << "ffmpeg/ffprobe not installed";
    VideoOptions options;
    for (int i = 0; i < 4; ++i)
        options.frames.push_back(write_frame("in " + std::to_string(i) + ".ppm", i));
    options.framerate = 10;
    options.output = m_dir / "out.mp4";
    const VideoResult result = encode_video(options, m_ctx);
    EXPECT_EQ(result.frame_count, 4u);
    ASSERT_TRUE(fs::exists(options.output));
    EXPECT_EQ(count_frames(options.output), 4);
    EXPECT_TRUE(no_temporaries_left());
}

TEST_F(VideoTest, PatternEncodesFromFirstIndex) {
    if (!have_ffmpeg()) GTEST_SKIP() << "ffmpeg/ffprobe not installed";
    for (int i = 7; i < 10; ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "f%04d.ppm", i);
        write_frame(name, i, 15, 9);  // odd size: padded for yuv420p
    }
    write_frame("f12.ppm", 12);  // not matching %04d
    EXPECT_EQ(list_pattern_indices(m_dir / "f%04d.ppm"), (std::vector<long>{7, 8, 9}));
    VideoOptions options;
    options.frames = {m_dir / "f%04d.ppm"};
    options.output = m_dir / "out.mkv";
    const VideoResult result = encode_video(options, m_ctx);
    EXPECT_EQ(result.frame_count, 3u);
    EXPECT_EQ(count_frames(options.output), 3);
}

TEST_F(VideoTest, PatternMatchingNothingIsAnInputError) {
    VideoOptions options;
    options.frames = {m_dir / "none%03d.png"};
    options.output = m_dir / "out.mp4";
    if (!find_program("ffmpeg")) GTEST_SKIP() << "ffmpeg not installed";
    try {
        encode_video(options, m_ctx);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("no frames match"), std::string::npos);
    }
    EXPECT_FALSE(fs::exists(options.output));
}

TEST_F(VideoTest, FfmpegFailureNamesOutputAndLeavesNothing) {
    if (!have_ffmpeg()) GTEST_SKIP() << "ffmpeg/ffprobe not installed";
    const fs::path bad = m_dir / "bad.png";
    std::ofstream(bad) << "not a png\n";
    VideoOptions options;
    options.frames = {bad};
    options.output = m_dir / "out.mp4";
    try {
        encode_video(options, m_ctx);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("out.mp4"), std::string::npos) << what;
        EXPECT_NE(what.find("ffmpeg failed (exited with status"), std::string::npos) << what;
    }
    EXPECT_FALSE(fs::exists(options.output));
    EXPECT_TRUE(no_temporaries_left());
}

TEST_F(VideoTest, MissingFfmpegGivesInstallHint) {
    VideoOptions options;
    options.frames = {write_frame("a.ppm", 0)};
    options.output = m_dir / "out.mp4";
    options.ffmpeg_program = "glint-no-such-ffmpeg";
    try {
        encode_video(options, m_ctx);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "glint-no-such-ffmpeg not found on PATH; install it "
                  "(scripts/install-deps.sh installs it)");
    }
}

TEST_F(VideoTest, MissingFrameAndBadOptions) {
    VideoOptions options;
    options.output = m_dir / "out.mp4";
    if (!find_program("ffmpeg")) GTEST_SKIP() << "ffmpeg not installed";
    EXPECT_THROW(encode_video(options, m_ctx), Error);  // no frames
    options.frames = {m_dir / "missing.png"};
    try {
        encode_video(options, m_ctx);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("missing.png"), std::string::npos);
    }
    options.frames = {write_frame("a.ppm", 0)};
    options.framerate = 0;
    EXPECT_THROW(encode_video(options, m_ctx), Error);
    options.framerate = 10;
    options.output = options.frames.front();
    EXPECT_THROW(encode_video(options, m_ctx), Error);  // refuses to overwrite a frame
}

TEST(FramePattern, Detection) {
    EXPECT_TRUE(is_frame_pattern("frames/f%04d.png"));
    EXPECT_TRUE(is_frame_pattern("f%d.png"));
    EXPECT_FALSE(is_frame_pattern("f%%d.png"));
    EXPECT_FALSE(is_frame_pattern("frame1.png"));
    EXPECT_THROW(list_pattern_indices("a%d-%d.png"), Error);
}

}  // namespace video_test
}  // namespace glint::process
