// SPDX-License-Identifier: Apache-2.0
// The DIRSIG5 `.jsim` plugin and key names that the reader (jsim.cpp) and the writer
// (jsim_writer.cpp) share.
#pragma once

#include <string_view>

namespace glint::dirsig {

inline constexpr std::string_view kBasicPlatform = "BasicPlatform";
inline constexpr std::string_view kBasicAtmosphere = "BasicAtmosphere";

inline constexpr const char* kPlatformFilename = "platform_filename";
inline constexpr const char* kMotionFilename = "motion_filename";
inline constexpr const char* kTasksFilename = "tasks_filename";
inline constexpr const char* kOutputFolder = "output_folder";
inline constexpr const char* kOutputPrefix = "output_prefix";
inline constexpr const char* kSplitChannels = "split_channels";
inline constexpr const char* kAtmosphereFilename = "atmosphere_filename";

}  // namespace glint::dirsig
