// SPDX-License-Identifier: Apache-2.0
// An exclusive advisory lock on an output folder (flock on the folder itself, so no lock
// file is left behind), held while a run writes into it. Two renders into one folder would
// otherwise interleave their files: a header of one run beside the data of the other.
#pragma once

#include <filesystem>

namespace glint {

class FolderLock {
public:
    /// Locks `folder` (which must exist). Throws glint::Error (io) naming it when another
    /// process holds the lock ("another glint run is writing into it"), or when it cannot be
    /// opened. The lock ends with the object, or with the process however it ends.
    explicit FolderLock(const std::filesystem::path& folder);
    ~FolderLock();
    FolderLock(FolderLock&& other) noexcept;
    FolderLock& operator=(FolderLock&&) = delete;
    FolderLock(const FolderLock&) = delete;
    FolderLock& operator=(const FolderLock&) = delete;

private:
    int m_fd = -1;
};

}  // namespace glint
