// SPDX-License-Identifier: Apache-2.0
// An exclusive advisory lock on an output folder (folder_lock.h).
#include "glint/core/folder_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <string>

#include "glint/core/error.h"

namespace glint {

FolderLock::FolderLock(const std::filesystem::path& folder) {
    m_fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (m_fd < 0) {
        throw io_error("cannot open the output folder: " + errno_text(errno), folder.string());
    }
    if (::flock(m_fd, LOCK_EX | LOCK_NB) != 0) {
        const int code = errno;
        ::close(m_fd);
        m_fd = -1;
        if (code == EWOULDBLOCK) {
            throw io_error(
                "another glint run is writing into this output folder; wait for it to end or "
                "choose another --output_folder (two runs would mix their files)",
                folder.string());
        }
        throw io_error("cannot lock the output folder: " + errno_text(code), folder.string());
    }
}

FolderLock::~FolderLock() {
    if (m_fd >= 0) ::close(m_fd);  // closing the last descriptor releases the lock
}

FolderLock::FolderLock(FolderLock&& other) noexcept : m_fd(other.m_fd) { other.m_fd = -1; }

}  // namespace glint
