// SPDX-License-Identifier: Apache-2.0
// Whole-file reads of inputs and the record of one load (glint/io/input_files.h).
#include "glint/io/input_files.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <system_error>
#include <utility>

#include "glint/core/error.h"
#include "glint/io/regular_file.h"

namespace glint::io {
namespace {

/// Bytes asked of read(2) at a time.
constexpr std::size_t kChunkBytes = std::size_t{1} << 16;

/// Closes a file descriptor when it goes out of scope.
class FileDescriptor {
public:
    explicit FileDescriptor(int fd) noexcept : m_fd(fd) {}
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;
    ~FileDescriptor() {
        if (m_fd >= 0) ::close(m_fd);
    }
    int get() const noexcept { return m_fd; }

private:
    int m_fd;
};

Error too_large(std::size_t max_bytes, const std::string& name) {
    return input_error(
        "larger than " + std::to_string(max_bytes) + " bytes (a device or not a text file?)",
        ErrorContext{name, 0, {}});
}

/// Reads `fd` to its end, at most `max_bytes` bytes; `reserve` bytes are expected.
std::string read_all(int fd, std::size_t reserve, const std::string& name, std::size_t max_bytes,
                     std::string_view kind) {
    std::string text;
    if (reserve > 0) text.reserve(reserve + kChunkBytes);  // no growth at the end
    // One byte more than the cap is asked for, to tell "exactly max_bytes" from "more".
    while (text.size() <= max_bytes) {
        const std::size_t old_size = text.size();
        const std::size_t want = std::min(kChunkBytes, max_bytes + 1 - old_size);
        text.resize(old_size + want);
        const ssize_t n = ::read(fd, text.data() + old_size, want);
        if (n < 0) {
            const int code = errno;
            text.resize(old_size);
            if (code == EINTR) continue;
            throw io_error("cannot read " + std::string(kind) + ": " + errno_text(code), name);
        }
        text.resize(old_size + static_cast<std::size_t>(n));
        if (n == 0) return text;
    }
    throw too_large(max_bytes, name);
}

}  // namespace

std::string read_standard_input(std::size_t max_bytes, std::string_view kind) {
    return read_all(STDIN_FILENO, 0, kStandardInputName, max_bytes, kind);
}

std::string read_input_file(const std::filesystem::path& path, const std::string& display_name,
                            std::size_t max_bytes, std::string_view kind) {
    const std::string& name = display_name.empty() ? path.string() : display_name;
    // Checked before opening: opening a FIFO blocks until it has a writer, and a device can
    // block, never end or have side effects.
    require_regular_file(path, name);
    const FileDescriptor fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK));
    if (fd.get() < 0) {
        const int code = errno;
        throw io_error("cannot open " + std::string(kind) + ": " + errno_text(code), name);
    }
    std::size_t reserve = 0;
    struct stat info {};
    if (::fstat(fd.get(), &info) == 0 && !S_ISREG(info.st_mode)) {  // replaced since checked
        throw io_error("is not a regular file, expected a file", name);
    }
    if (::fstat(fd.get(), &info) == 0 && S_ISREG(info.st_mode) && info.st_size > 0) {
        const auto size = static_cast<std::uintmax_t>(info.st_size);
        if (size > max_bytes) throw too_large(max_bytes, name);
        reserve = static_cast<std::size_t>(size);
    }
    return read_all(fd.get(), reserve, name, max_bytes, kind);
}

std::filesystem::path InputFiles::key(const std::filesystem::path& path) {
    std::error_code ec;
    std::filesystem::path canonical = std::filesystem::weakly_canonical(path, ec);
    return ec ? path.lexically_normal() : canonical;
}

const std::string& InputFiles::text(const std::filesystem::path& path,
                                    const std::string& display_name) {
    const std::filesystem::path k = key(path);
    if (const auto found = m_texts.find(k); found != m_texts.end()) return found->second;
    m_opened.push_back(k);
    m_log.debug("reading " + (display_name.empty() ? path.string() : display_name));
    std::string text =
        m_source ? m_source(path, display_name) : read_input_file(path, display_name);
    return m_texts.emplace(k, std::move(text)).first->second;
}

std::size_t InputFiles::open_count(const std::filesystem::path& path) const {
    const std::filesystem::path k = key(path);
    std::size_t count = 0;
    for (const std::filesystem::path& opened : m_opened) count += opened == k ? 1 : 0;
    return count;
}

}  // namespace glint::io
