// SPDX-License-Identifier: Apache-2.0
// not_a_regular_file and require_regular_file (glint/io/regular_file.h).
#include "glint/io/regular_file.h"

#include <sys/stat.h>

#include "glint/core/error.h"

namespace glint::io {

std::optional<std::string> not_a_regular_file(const std::filesystem::path& path) {
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0 || S_ISREG(info.st_mode)) return std::nullopt;
    if (S_ISDIR(info.st_mode)) return "is a folder";
    if (S_ISFIFO(info.st_mode)) return "is a FIFO (a named pipe)";
    if (S_ISSOCK(info.st_mode)) return "is a socket";
    if (S_ISCHR(info.st_mode) || S_ISBLK(info.st_mode)) return "is a device";
    return "is not a regular file";
}

void require_regular_file(const std::filesystem::path& path, const std::string& display_name,
                          std::string_view kind) {
    if (const std::optional<std::string> what = not_a_regular_file(path)) {
        throw io_error(*what + ", expected a " + std::string(kind),
                       display_name.empty() ? path.string() : display_name);
    }
}

}  // namespace glint::io
