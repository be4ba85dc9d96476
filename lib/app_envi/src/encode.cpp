// SPDX-License-Identifier: Apache-2.0
// `glint-envi encode`: option checks, then the ffmpeg wrapper.
#include "glint/app_envi/encode.h"

#include <cmath>

#include "glint/core/error.h"
#include "source.h"

namespace glint::app_envi {

process::VideoResult encode_frames(const EncodeOptions& options, Context& ctx) {
    if (options.frames.empty()) throw usage_error("no frames to encode");
    if (options.output.empty()) throw usage_error("no output video named (--output)");
    if (options.crf && (*options.crf < 0 || *options.crf > 51)) {
        throw usage_error("--crf must be in [0, 51], got " + std::to_string(*options.crf));
    }
    process::VideoOptions video;
    video.frames = options.frames;
    video.framerate = options.framerate;
    video.output = options.output;
    video.codec = options.codec;
    video.pixel_format = options.pixel_format;
    video.crf = options.crf;
    if (options.timeout_s) {
        if (!(*options.timeout_s > 0) || !std::isfinite(*options.timeout_s)) {
            throw usage_error("--timeout must be a positive number of seconds, got " +
                              internal::format_number(*options.timeout_s));
        }
        video.timeout = std::chrono::milliseconds(
            static_cast<long long>(std::ceil(*options.timeout_s * 1000.0)));
    }
    return process::encode_video(video, ctx);
}

}  // namespace glint::app_envi
