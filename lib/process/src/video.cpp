// SPDX-License-Identifier: Apache-2.0
// encode_video(): builds the ffmpeg command line (frame pattern or a temporary folder of
// numbered symbolic links to the listed frames), runs it through run_process() and
// publishes the video atomically.
#include "glint/process/video.h"

#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <system_error>

#include "glint/core/atomic_file.h"
#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/process/process.h"

namespace glint::process {
namespace {

namespace fs = std::filesystem;

/// A file name pattern split around its one integer conversion.
struct Pattern {
    std::string prefix;
    std::string suffix;
    int width = 0;
    bool zero_pad = false;

    std::string format(long index) const {
        char digits[64];
        if (zero_pad) {
            std::snprintf(digits, sizeof digits, "%0*ld", width, index);
        } else {
            std::snprintf(digits, sizeof digits, "%*ld", width, index);
        }
        return prefix + digits + suffix;
    }
};

/// Splits a file name at its integer conversion; counts conversions in `conversions`.
Pattern parse_pattern(const std::string& name, int& conversions) {
    Pattern pattern;
    std::string* part = &pattern.prefix;
    conversions = 0;
    for (std::size_t i = 0; i < name.size(); ++i) {
        if (name[i] != '%') {
            *part += name[i];
            continue;
        }
        if (i + 1 < name.size() && name[i + 1] == '%') {
            *part += '%';
            ++i;
            continue;
        }
        std::size_t j = i + 1;
        const bool zero = j < name.size() && name[j] == '0';
        if (zero) ++j;
        int width = 0;
        while (j < name.size() && name[j] >= '0' && name[j] <= '9' && width < 100) {
            width = width * 10 + (name[j] - '0');
            ++j;
        }
        if (j < name.size() && name[j] == 'd') {
            ++conversions;
            pattern.zero_pad = zero;
            pattern.width = width;
            part = &pattern.suffix;
            i = j;
        } else {
            *part += name[i];
        }
    }
    return pattern;
}

bool uses_x264_by_default(const fs::path& output) {
    std::string ext = output.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".mp4" || ext == ".m4v" || ext == ".mov" || ext == ".mkv";
}

/// A temporary folder beside the output holding `frame000000.<ext>`, ... symbolic links to
/// the listed frames; removed with everything in it when destroyed.
class FrameLinks {
public:
    FrameLinks(const fs::path& output, const std::vector<fs::path>& frames) {
        fs::path folder = output.parent_path();
        if (folder.empty()) folder = ".";
        std::string templ =
            (folder / ("." + output.filename().string() + ".tmp-frames-XXXXXX")).string();
        if (::mkdtemp(templ.data()) == nullptr) {
            const int code = errno;
            throw io_error("cannot create a temporary folder: " + errno_text(code),
                           output.string());
        }
        m_folder = templ;
        m_extension = frames.front().extension().string();
        for (std::size_t i = 0; i < frames.size(); ++i) {
            char name[64];
            std::snprintf(name, sizeof name, "frame%06zu", i);
            std::error_code ec;
            fs::create_symlink(fs::absolute(frames[i]), m_folder / (name + m_extension), ec);
            if (ec) {
                throw io_error("cannot link frame into " + m_folder.string() + ": " + ec.message(),
                               frames[i].string());
            }
        }
    }
    ~FrameLinks() {
        std::error_code ec;
        fs::remove_all(m_folder, ec);
    }
    FrameLinks(const FrameLinks&) = delete;
    FrameLinks& operator=(const FrameLinks&) = delete;

    fs::path pattern() const { return m_folder / ("frame%06d" + m_extension); }

private:
    fs::path m_folder;
    std::string m_extension;
};

/// The last few non-empty lines of ffmpeg's stderr, joined into one line.
std::string stderr_summary(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t begin = 0;
    while (begin < text.size()) {
        std::size_t end = text.find('\n', begin);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(begin, end - begin);
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
        if (!line.empty()) lines.push_back(line);
        begin = end + 1;
    }
    const std::size_t keep = 4;
    std::string summary;
    for (std::size_t i = lines.size() > keep ? lines.size() - keep : 0; i < lines.size(); ++i) {
        if (!summary.empty()) summary += "; ";
        summary += lines[i];
    }
    return summary;
}

}  // namespace

bool is_frame_pattern(const fs::path& path) {
    int conversions = 0;
    parse_pattern(path.filename().string(), conversions);
    return conversions > 0;
}

std::vector<long> list_pattern_indices(const fs::path& pattern_path) {
    int conversions = 0;
    const Pattern pattern = parse_pattern(pattern_path.filename().string(), conversions);
    if (conversions != 1) {
        throw usage_error("frame pattern " + pattern_path.string() +
                          " must hold exactly one integer conversion such as %04d");
    }
    int folder_conversions = 0;
    parse_pattern(pattern_path.parent_path().string(), folder_conversions);
    if (folder_conversions != 0) {
        throw usage_error("frame pattern " + pattern_path.string() +
                          ": the conversion must be in the file name, not the folder");
    }
    fs::path folder = pattern_path.parent_path();
    if (folder.empty()) folder = ".";
    std::vector<long> indices;
    std::error_code ec;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.size() < pattern.prefix.size() + pattern.suffix.size() + 1) continue;
        if (name.compare(0, pattern.prefix.size(), pattern.prefix) != 0) continue;
        if (name.compare(name.size() - pattern.suffix.size(), pattern.suffix.size(),
                         pattern.suffix) != 0) {
            continue;
        }
        std::string middle = name.substr(
            pattern.prefix.size(), name.size() - pattern.prefix.size() - pattern.suffix.size());
        const std::size_t first = middle.find_first_not_of(' ');
        if (first == std::string::npos) continue;
        const std::string digits = middle.substr(first);
        if (digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) {
            continue;
        }
        const long index = std::stol(digits);
        if (pattern.format(index) == name) indices.push_back(index);
    }
    if (ec) throw io_error("cannot list folder: " + ec.message(), folder.string());
    std::sort(indices.begin(), indices.end());
    return indices;
}

VideoResult encode_video(const VideoOptions& options, const Context& ctx) {
    if (options.frames.empty()) throw usage_error("no frames to encode");
    if (options.output.empty()) throw usage_error("no output video named");
    if (!(options.framerate > 0) || options.framerate > 1e6) {
        throw usage_error("frame rate must be a positive number, got " +
                          format_ten_digits(options.framerate));
    }
    const auto ffmpeg = find_program(options.ffmpeg_program);
    if (!ffmpeg) {
        throw io_error(options.ffmpeg_program +
                       " not found on PATH; install it (scripts/install-deps.sh installs it)");
    }

    VideoResult result;
    std::vector<std::string> input_args;
    std::optional<FrameLinks> links;
    const bool pattern = options.frames.size() == 1 && is_frame_pattern(options.frames.front());
    if (pattern) {
        const auto indices = list_pattern_indices(options.frames.front());
        if (indices.empty()) {
            throw input_error("no frames match the pattern",
                              ErrorContext{options.frames.front().string(), 0, {}});
        }
        std::size_t run = 1;
        while (run < indices.size() && indices[run] == indices[run - 1] + 1) ++run;
        if (run < indices.size()) {
            ctx.log.warning("frames after index " + std::to_string(indices[run - 1]) + " of " +
                            options.frames.front().string() +
                            " are not encoded (gap in the numbering)");
        }
        result.frame_count = run;
        input_args = {"-start_number", std::to_string(indices.front()), "-i",
                      options.frames.front().string()};
    } else {
        const std::string extension = options.frames.front().extension().string();
        for (const auto& frame : options.frames) {
            std::error_code ec;
            if (!fs::is_regular_file(frame, ec)) {
                throw input_error("frame not found", ErrorContext{frame.string(), 0, {}});
            }
            if (frame.extension().string() != extension) {
                throw usage_error("frames must share one file extension: " + frame.string() +
                                  " differs from " + options.frames.front().string());
            }
        }
        result.frame_count = options.frames.size();
    }
    ensure_not_an_input(options.output, options.frames);

    AtomicFile video(options.output);
    video.release_for_external_writer();
    if (!pattern) {
        links.emplace(options.output, options.frames);
        input_args = {"-i", links->pattern().string()};
    }

    std::vector<std::string>& cmd = result.command;
    cmd = {ffmpeg->string(), "-nostdin", "-y",         "-hide_banner",
           "-loglevel",      "error",    "-framerate", format_ten_digits(options.framerate)};
    cmd.insert(cmd.end(), input_args.begin(), input_args.end());
    const bool x264 =
        options.codec.empty() ? uses_x264_by_default(options.output) : options.codec == "libx264";
    const std::string codec = options.codec.empty() && x264 ? "libx264" : options.codec;
    if (!codec.empty()) cmd.insert(cmd.end(), {"-c:v", codec});
    std::string pixel_format = options.pixel_format;
    if (pixel_format.empty() && x264) pixel_format = "yuv420p";
    if (!pixel_format.empty()) cmd.insert(cmd.end(), {"-pix_fmt", pixel_format});
    if (x264 && pixel_format == "yuv420p") {
        cmd.insert(cmd.end(), {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2"});
    }
    if (options.crf) cmd.insert(cmd.end(), {"-crf", std::to_string(*options.crf)});
    cmd.push_back(video.temp_path().string());

    ctx.log.info("encoding " + std::to_string(result.frame_count) + " frames at " +
                 format_ten_digits(options.framerate) + " fps into " + options.output.string());
    ctx.log.debug("running: " + format_command_line(cmd));

    ProcessOptions process;
    process.argv = cmd;
    process.timeout = options.timeout;
    process.cancel = ctx.cancel;
    const ProcessResult outcome = run_process(process);
    if (!outcome.success()) {
        std::string message = "ffmpeg failed (" + outcome.describe() + ")";
        const std::string detail = stderr_summary(outcome.stderr_text);
        if (!detail.empty()) message += ": " + detail;
        throw io_error(message, options.output.string());
    }
    video.commit();
    return result;
}

}  // namespace glint::process
