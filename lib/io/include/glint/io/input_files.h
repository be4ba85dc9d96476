// SPDX-License-Identifier: Apache-2.0
// Reading input files: the whole-file read every reader uses (size cap, folder check, errors
// naming the file), and InputFiles, the record of one load — each file is opened once (its
// text kept for the rest of the load), every open is counted and logged, so a test or a
// `-vv` log shows that no file of a render is read twice.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "glint/core/log.h"

namespace glint::io {

/// Reads a whole input file as text. Throws glint::Error (io when it cannot be opened or
/// read or is a folder, input when it is larger than any DIRSIG input, 256 MiB), naming
/// `display_name` (default: the path).
std::string read_input_file(const std::filesystem::path& path,
                            const std::string& display_name = {});

/// The files one load reads. Not thread-safe: one load, one thread.
class InputFiles {
public:
    /// `log` gets a debug line ("reading FILE") for every file opened.
    explicit InputFiles(Log log = {}) : m_log(std::move(log)) {}

    /// The text of `path` (read_input_file on first use, the kept text afterwards; errors
    /// are thrown on every call, nothing is kept for a file that failed).
    const std::string& text(const std::filesystem::path& path, const std::string& display_name);

    /// How many times `path` was opened (0 or 1 unless the text was dropped by clear()).
    std::size_t open_count(const std::filesystem::path& path) const;
    /// Every file opened, in order, one entry per open.
    const std::vector<std::filesystem::path>& opened() const noexcept { return m_opened; }
    /// Drops the kept texts (the open record stays).
    void clear() noexcept { m_texts.clear(); }

private:
    static std::filesystem::path key(const std::filesystem::path& path);
    Log m_log;
    std::map<std::filesystem::path, std::string> m_texts;
    std::vector<std::filesystem::path> m_opened;
};

}  // namespace glint::io
