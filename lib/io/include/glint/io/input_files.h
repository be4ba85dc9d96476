// SPDX-License-Identifier: Apache-2.0
// Reading input files: the whole-file read every reader uses (byte cap, folder and device
// checks, errors naming the file), and InputFiles, the record of one load — each file is
// opened once (its text kept for the rest of the load), every open is counted and logged, so
// a test or a `-vv` log shows that no file of a render is read twice.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "glint/core/log.h"

namespace glint::io {

/// The most bytes read_input_file reads of an input (256 MiB): DIRSIG and glint inputs are a
/// few MB at most, so anything larger is a device, a data file or a runaway pipe.
inline constexpr std::size_t kMaxInputBytes = std::size_t{256} << 20;

/// Reads a whole input file as text, at most `max_bytes` bytes. The cap counts the bytes
/// actually read (a device, a pipe or a /proc file reports no useful size), so no input can
/// exhaust memory. Throws glint::Error naming `display_name` (default: the path): io when it
/// cannot be opened or read ("cannot open <kind>: <errno text>"), or is not a regular file
/// (glint/io/regular_file.h: a folder, a FIFO or `<(…)`, a socket, a device such as
/// `/dev/zero`: "is a FIFO (a named pipe), expected a file"), checked before opening; input
/// when it holds more than `max_bytes` ("larger than N bytes (a device or not a text
/// file?)").
std::string read_input_file(const std::filesystem::path& path, const std::string& display_name = {},
                            std::size_t max_bytes = kMaxInputBytes, std::string_view kind = "file");

/// How messages name standard input.
inline constexpr const char* kStandardInputName = "(standard input)";

/// Reads standard input to its end as text, at most `max_bytes` bytes, for the inputs a tool
/// accepts as "-". Throws glint::Error as read_input_file does, naming "(standard input)".
std::string read_standard_input(std::size_t max_bytes, std::string_view kind = "input");

/// The files one load reads. Not thread-safe: one load, one thread.
class InputFiles {
public:
    /// Where the text of a file comes from on its first use: (path, display name) → text,
    /// throwing glint::Error as read_input_file does. Tests and the fuzz targets hand texts
    /// in from memory this way.
    using Source =
        std::function<std::string(const std::filesystem::path&, const std::string& display_name)>;

    /// `log` gets a debug line ("reading FILE") for every file opened; `source` reads the
    /// files (default: read_input_file).
    explicit InputFiles(Log log = {}, Source source = {})
        : m_log(std::move(log)), m_source(std::move(source)) {}

    /// The text of `path` (read through the source on first use, the kept text afterwards;
    /// errors are thrown on every call, nothing is kept for a file that failed).
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
    Source m_source;
    std::map<std::filesystem::path, std::string> m_texts;
    std::vector<std::filesystem::path> m_opened;
};

}  // namespace glint::io
