// SPDX-License-Identifier: Apache-2.0
// "-", the conventional name of standard input and output. Tools that stream text (headers,
// JSON, schedules) accept it; tools whose inputs or outputs are ENVI pairs or images cannot
// (an ENVI product is two files read by offset, an image is written through a temporary
// file), and refuse it rather than create a file named "-".
#pragma once

#include <filesystem>
#include <string>

#include "glint/core/error.h"

namespace glint {

/// True when `path` is "-".
inline bool is_stdio_name(const std::filesystem::path& path) { return path == "-"; }

/// Which standard stream "-" would name.
enum class StdioRole { input, output };

/// Throws a usage error when `path` is "-": `what` names it ("the output of glint-envi
/// convert"), `why` says why a file is needed.
inline void refuse_stdio_name(const std::filesystem::path& path, StdioRole role,
                              const std::string& what, const std::string& why) {
    if (is_stdio_name(path)) {
        throw usage_error(what + " cannot be '-' (standard " +
                          (role == StdioRole::input ? "input" : "output") + "): " + why +
                          "; give a file name");
    }
}

/// Why an image input cannot come from standard input.
inline constexpr const char* kImageInputNeedsFile =
    "an ENVI image is two files (data and header) read by offset";
/// Why an image output cannot go to standard output.
inline constexpr const char* kOutputNeedsFile =
    "outputs are written through a temporary file and renamed when complete";

/// Refuses "-" as the image input or the output of `tool` ("glint-detect").
inline void refuse_stdio_image_files(const std::filesystem::path& input,
                                     const std::filesystem::path& output,
                                     const std::string& tool) {
    refuse_stdio_name(input, StdioRole::input, "the input of " + tool, kImageInputNeedsFile);
    refuse_stdio_name(output, StdioRole::output, "the output of " + tool, kOutputNeedsFile);
}

/// Why a simulation (or a file it is made of) cannot come from standard input.
inline constexpr const char* kSimulationNeedsFile =
    "a simulation's files name each other relative to their own folders";

}  // namespace glint
