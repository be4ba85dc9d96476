// SPDX-License-Identifier: Apache-2.0
// `glint-envi encode --framerate F --output video.mp4 FRAME...`: image frames (PNG, JPEG,
// PPM, TIFF, ... as ffmpeg reads them) into a video through the ffmpeg executable
// (process::encode_video). FRAME is either the list of frames in display order or one
// printf-style pattern such as `frames/f%04d.png`.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/context.h"
#include "glint/process/video.h"

namespace glint::app_envi {

/// Options of `encode`.
struct EncodeOptions {
    std::vector<std::filesystem::path> frames;
    double framerate = 15.0;
    std::filesystem::path output;
    std::string codec;         ///< empty = libx264 for .mp4/.m4v/.mov/.mkv
    std::string pixel_format;  ///< empty = yuv420p with libx264
    std::optional<int> crf;
    std::optional<double> timeout_s;  ///< kill ffmpeg after this many seconds
};

/// Encodes; throws glint::Error (see process::encode_video).
process::VideoResult encode_frames(const EncodeOptions& options, Context& ctx);

}  // namespace glint::app_envi
