// SPDX-License-Identifier: Apache-2.0
// AtomicFile: temporary file beside the target, fsync, rename.
#include "glint/core/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include "glint/core/error.h"
#include "glint/core/temporary_files.h"

namespace glint {
namespace {

constexpr std::size_t kBufferBytes = 1 << 20;

std::filesystem::path folder_of(const std::filesystem::path& target) {
    auto folder = target.parent_path();
    return folder.empty() ? std::filesystem::path(".") : folder;
}

void fsync_folder(const std::filesystem::path& folder) {
    int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;  // best effort: some file systems do not allow opening folders
    ::fsync(fd);
    ::close(fd);
}

/// The path a chain of symbolic links ends at (the path itself when it is none); relative link
/// texts are taken from the link's folder. More than 40 links is an error (a loop).
std::filesystem::path follow_links(std::filesystem::path path) {
    for (int hops = 0; hops < 40; ++hops) {
        std::error_code ec;
        if (!std::filesystem::is_symlink(path, ec)) return path;
        const std::filesystem::path next = std::filesystem::read_symlink(path, ec);
        if (ec) return path;
        path = next.is_absolute() ? next : path.parent_path() / next;
    }
    throw io_error("cannot create output: too many levels of symbolic links", path.string());
}

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path target) : m_target(std::move(target)) {
    // What the name stands for, following links: /dev/stdout names a pipe or terminal.
    struct stat info {};
    if (::stat(m_target.c_str(), &info) == 0 && !S_ISREG(info.st_mode)) {
        if (S_ISDIR(info.st_mode)) {
            throw io_error("cannot create output: is a folder", m_target.string());
        }
        m_fd = ::open(m_target.c_str(), O_WRONLY | O_CLOEXEC);
        if (m_fd < 0) {
            const int code = errno;
            throw io_error("cannot open output: " + errno_text(code), m_target.string());
        }
        m_direct = true;
        m_temp = m_target;
        m_buffer.reserve(kBufferBytes);
        return;
    }
    // A link to a file (existing or not) is published at that file, keeping the link.
    const std::filesystem::path publish = follow_links(m_target);
    const std::string extension = m_target.extension().string();
    std::string pattern =
        (folder_of(publish) / ("." + publish.filename().string() + ".tmp-XXXXXX")).string() +
        extension;
    m_publish = publish;
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    m_fd = ::mkostemps(name.data(), static_cast<int>(extension.size()), O_CLOEXEC);
    if (m_fd < 0) {
        const int code = errno;
        throw io_error("cannot create output: " + errno_text(code), m_target.string());
    }
    m_temp = std::filesystem::path(name.data());
    m_slot = temporary_files::add(m_temp);
    // mkstemp creates 0600; outputs get the usual 0666 & ~umask.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(m_fd, 0666 & ~mask);
    m_buffer.reserve(kBufferBytes);
}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : m_target(std::move(other.m_target)),
      m_temp(std::move(other.m_temp)),
      m_fd(other.m_fd),
      m_buffer(std::move(other.m_buffer)),
      m_bytes_written(other.m_bytes_written),
      m_committed(other.m_committed),
      m_direct(other.m_direct),
      m_publish(std::move(other.m_publish)),
      m_slot(other.m_slot) {
    other.m_fd = -1;
    other.m_slot = -1;
    other.m_temp.clear();  // the moved-from object owns nothing to remove
}

AtomicFile::~AtomicFile() {
    if (!m_committed) abandon();
}

void AtomicFile::write(const void* data, std::size_t size_bytes) {
    if (m_fd < 0) throw internal_error("write to a closed AtomicFile " + m_target.string());
    const char* bytes = static_cast<const char*>(data);
    if (m_buffer.size() + size_bytes > kBufferBytes) flush_buffer();
    if (size_bytes >= kBufferBytes) {
        std::size_t written = 0;
        while (written < size_bytes) {
            const ssize_t n = ::write(m_fd, bytes + written, size_bytes - written);
            if (n < 0) {
                if (errno == EINTR) continue;
                const int code = errno;
                throw io_error("write failed: " + errno_text(code), m_target.string());
            }
            written += static_cast<std::size_t>(n);
        }
    } else {
        m_buffer.insert(m_buffer.end(), bytes, bytes + size_bytes);
    }
    m_bytes_written += size_bytes;
}

void AtomicFile::flush_buffer() {
    std::size_t written = 0;
    while (written < m_buffer.size()) {
        const ssize_t n = ::write(m_fd, m_buffer.data() + written, m_buffer.size() - written);
        if (n < 0) {
            if (errno == EINTR) continue;
            const int code = errno;
            throw io_error("write failed: " + errno_text(code), m_target.string());
        }
        written += static_cast<std::size_t>(n);
    }
    m_buffer.clear();
}

void AtomicFile::release_for_external_writer() {
    if (m_fd < 0) return;
    if (m_direct) {  // the external writer opens the target itself
        flush_buffer();
        ::close(m_fd);
        m_fd = -1;
        return;
    }
    flush_buffer();
    ::close(m_fd);
    m_fd = -1;
}

void AtomicFile::commit() {
    if (m_committed) return;
    if (m_direct) {  // a device, FIFO or socket: written straight, nothing to sync or rename
        if (m_fd >= 0) {
            flush_buffer();
            const int fd = m_fd;
            m_fd = -1;
            if (::close(fd) != 0) {
                const int code = errno;
                throw io_error("close failed: " + errno_text(code), m_target.string());
            }
        }
        m_committed = true;
        return;
    }
    if (m_fd < 0) {
        m_fd = ::open(m_temp.c_str(), O_RDWR | O_CLOEXEC);
        if (m_fd < 0) {
            const int code = errno;
            throw io_error("cannot reopen temporary output: " + errno_text(code),
                           m_target.string());
        }
    }
    flush_buffer();
    if (::fsync(m_fd) != 0) {
        const int code = errno;
        throw io_error("fsync failed: " + errno_text(code), m_target.string());
    }
    const int fd = m_fd;
    m_fd = -1;
    if (::close(fd) != 0) {
        const int code = errno;
        throw io_error("close failed: " + errno_text(code), m_target.string());
    }
    if (::rename(m_temp.c_str(), m_publish.c_str()) != 0) {
        const int code = errno;
        throw io_error("cannot rename temporary output into place: " + errno_text(code),
                       m_target.string());
    }
    m_committed = true;
    temporary_files::remove(m_slot);
    m_slot = -1;
    fsync_folder(folder_of(m_publish));
}

void AtomicFile::abandon() noexcept {
    if (m_fd >= 0) {
        ::close(m_fd);
        m_fd = -1;
    }
    if (!m_temp.empty() && !m_direct) {
        ::unlink(m_temp.c_str());
    }
    temporary_files::remove(m_slot);
    m_slot = -1;
    m_temp.clear();
}

void write_file_atomically(const std::filesystem::path& target, std::string_view content) {
    AtomicFile file(target);
    file.write(content);
    file.commit();
}

void ensure_not_an_input(const std::filesystem::path& output,
                         std::span<const std::filesystem::path> inputs) {
    for (const auto& input : inputs) {
        std::error_code ec;
        if (std::filesystem::equivalent(output, input, ec) && !ec) {
            throw usage_error("refusing to overwrite input " + input.string());
        }
    }
}

}  // namespace glint
