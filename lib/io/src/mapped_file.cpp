// SPDX-License-Identifier: Apache-2.0
// Read-only file mappings (glint/io/mapped_file.h).
#include "glint/io/mapped_file.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <string>

#include "glint/core/error.h"

namespace glint::io {

std::shared_ptr<const std::uint8_t> map_file_bytes(const std::filesystem::path& path,
                                                   std::size_t offset, std::size_t length) {
    const ErrorContext where{path.string(), 0, {}};
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw io_error("cannot open: " + errno_text(errno), path.string());
    struct stat info {};
    if (::fstat(fd, &info) != 0) {
        const int e = errno;
        ::close(fd);
        throw io_error("cannot stat: " + errno_text(e), path.string());
    }
    const auto size = static_cast<std::size_t>(info.st_size);
    if (offset > size || length > size - offset) {
        ::close(fd);
        throw input_error("holds " + std::to_string(size) + " bytes, expected at least " +
                              std::to_string(offset + length),
                          where);
    }
    const std::size_t mapped = offset + length;
    void* base = mapped == 0 ? nullptr : ::mmap(nullptr, mapped, PROT_READ, MAP_PRIVATE, fd, 0);
    const int e = errno;
    ::close(fd);  // the mapping keeps the file
    if (base == MAP_FAILED) throw io_error("cannot map: " + errno_text(e), path.string());
    // Texels are read in no order: no read-ahead.
    if (base != nullptr) ::madvise(base, mapped, MADV_RANDOM);
    const std::shared_ptr<const std::uint8_t> owner(
        static_cast<const std::uint8_t*>(base), [mapped](const std::uint8_t* p) {
            if (p != nullptr) ::munmap(const_cast<std::uint8_t*>(p), mapped);
        });
    return {owner, owner.get() + offset};
}

}  // namespace glint::io
