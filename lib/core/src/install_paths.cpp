// SPDX-License-Identifier: Apache-2.0
// The installed layout's paths (glint/core/install_paths.h).
#include "glint/core/install_paths.h"

#include <system_error>

namespace glint {

std::filesystem::path executable_path() {
    std::error_code error;
    std::filesystem::path path = std::filesystem::read_symlink("/proc/self/exe", error);
    if (error) return {};
    return path;
}

std::filesystem::path installed_data_dir(const std::filesystem::path& executable) {
    if (executable.empty()) return {};
    return (executable.parent_path() / ".." / "share" / "glint").lexically_normal();
}

std::filesystem::path data_dir_lookup(const DataDirCandidates& candidates) {
    if (!candidates.environment.empty()) return std::filesystem::path(candidates.environment);
    const std::filesystem::path installed = installed_data_dir(candidates.executable);
    if (!installed.empty()) {
        std::error_code error;
        if (std::filesystem::is_regular_file(installed / candidates.marker, error)) {
            // lexically_normal keeps a trailing separator; drop it for messages.
            return installed.has_filename() ? installed : installed.parent_path();
        }
    }
    return candidates.built_in;
}

}  // namespace glint
