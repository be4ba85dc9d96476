// SPDX-License-Identifier: Apache-2.0
// Atomic output: a file is written under a temporary name in its target folder, flushed to
// disk and renamed into place only when complete, so a failed or interrupted run never
// leaves a partial file under a final name. A target that is a symbolic link is published at
// the file the link names (the link stays); a target that exists and is not a regular file (a
// character or block device such as /dev/null, a FIFO, a socket, /dev/stdout's pipe or
// terminal) is written straight, never renamed over.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

namespace glint {

/// A file being written atomically. The temporary file lives beside the target (beside the
/// file a symbolic link names, after following every link), named
/// `.<target name>.tmp-XXXXXX<target extension>` (the extension is kept so that libraries
/// which choose a format by extension can write it). The destructor removes the temporary
/// file unless commit() succeeded. An existing target that is not a regular file is opened
/// and written directly (direct(); temp_path() is then the target itself and nothing is
/// renamed). A folder is refused. Write errors throw glint::Error (io).
class AtomicFile {
public:
    explicit AtomicFile(std::filesystem::path target);
    ~AtomicFile();
    AtomicFile(AtomicFile&& other) noexcept;
    AtomicFile& operator=(AtomicFile&&) = delete;
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    /// Appends bytes (buffered).
    void write(const void* data, std::size_t size_bytes);
    void write(std::string_view text) { write(text.data(), text.size()); }

    /// Closes this object's handle so another library may write `temp_path()` by name;
    /// commit() then syncs whatever that library left there.
    void release_for_external_writer();

    /// Flushes, fsyncs, closes and renames the temporary file onto the target, then syncs the
    /// folder. Close and flush errors are failures.
    void commit();
    /// Removes the temporary file now (also done by the destructor when not committed).
    void abandon() noexcept;

    const std::filesystem::path& target() const { return m_target; }
    /// True when the target is written straight (a device, FIFO or socket), not renamed.
    bool direct() const { return m_direct; }
    const std::filesystem::path& temp_path() const { return m_temp; }
    std::uint64_t bytes_written() const { return m_bytes_written; }
    bool committed() const { return m_committed; }

private:
    void flush_buffer();

    std::filesystem::path m_target;
    std::filesystem::path m_temp;
    int m_fd = -1;
    std::vector<char> m_buffer;
    std::uint64_t m_bytes_written = 0;
    bool m_committed = false;
    bool m_direct = false;
    std::filesystem::path m_publish;  ///< where commit() renames to (links followed)
    int m_slot = -1;  ///< in glint::temporary_files, removed at a second stop signal
};

/// Writes `content` to `target` atomically.
void write_file_atomically(const std::filesystem::path& target, std::string_view content);

/// Throws a usage error when `output` names the same file as one of `inputs`
/// ("refusing to overwrite input FILE").
void ensure_not_an_input(const std::filesystem::path& output,
                         std::span<const std::filesystem::path> inputs);

}  // namespace glint
