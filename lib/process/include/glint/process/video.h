// SPDX-License-Identifier: Apache-2.0
// The ffmpeg wrapper: encodes a sequence of image frames into a video by running the ffmpeg
// executable through run_process() (`ffmpeg -nostdin -y -hide_banner -loglevel error ...`).
// The video is written atomically: ffmpeg writes a temporary file beside the output (with
// the output's extension, so that ffmpeg picks the container from it) and glint renames it
// into place only when ffmpeg exited with status 0.
#pragma once

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/context.h"

namespace glint::process {

/// What to encode and how.
struct VideoOptions {
    /// The frames in display order, or a single printf-style pattern such as
    /// `frames/f%04d.png` (ffmpeg image2 syntax; the run starts at the lowest existing index
    /// and stops at the first gap). Listed frames must share one file extension.
    std::vector<std::filesystem::path> frames;
    double framerate = 15.0;  ///< frames per second, > 0
    std::filesystem::path output;
    /// Video codec; empty = libx264 for .mp4/.m4v/.mov/.mkv, otherwise ffmpeg's default
    /// for the container.
    std::string codec;
    /// Pixel format; empty = yuv420p with libx264 (the one every player decodes; odd frame
    /// sizes are padded by one pixel), otherwise ffmpeg's choice.
    std::string pixel_format;
    std::optional<int> crf;  ///< constant rate factor for libx264 (0-51), ffmpeg's default if unset
    std::optional<std::chrono::milliseconds> timeout;  ///< kill ffmpeg after this long
    std::string ffmpeg_program = "ffmpeg";             ///< name (PATH lookup) or path
};

/// What encode_video() did.
struct VideoResult {
    std::size_t frame_count = 0;
    std::vector<std::string> command;  ///< the ffmpeg argv that ran
};

/// True when `path` contains a printf integer conversion (`%d`, `%04d`, ...).
bool is_frame_pattern(const std::filesystem::path& path);

/// The indices `pattern` matches in its folder, ascending. Throws glint::Error (usage) when
/// the pattern has no or several integer conversions.
std::vector<long> list_pattern_indices(const std::filesystem::path& pattern);

/// Encodes the frames into `options.output`. Throws glint::Error: (io) "ffmpeg not found on
/// PATH; install it (scripts/install-deps.sh installs it)" when ffmpeg is missing; (input)
/// naming a missing frame; (io) naming the output with ffmpeg's exit status and the end of
/// its stderr when it fails; (cancelled) when ctx.cancel is raised meanwhile.
VideoResult encode_video(const VideoOptions& options, const Context& ctx);

}  // namespace glint::process
