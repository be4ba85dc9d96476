// SPDX-License-Identifier: Apache-2.0
// The pieces of glint-envi merge (merge.cpp): the glint-render images found in the part
// folders, read from their headers, and the whole files they make, checked to cover every
// line of every capture once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "glint/core/context.h"
#include "glint/core/error.h"
#include "glint/io/envi.h"

namespace glint::app_envi::merge_detail {

/// The header key of the command line that made a file (each part's; the merge's own in the
/// whole file).
inline constexpr const char* kCommandLineKey = "glint command line";

/// One glint-render image found in a part folder.
struct Piece {
    std::filesystem::path part;  ///< the part folder
    std::filesystem::path header_path;
    std::filesystem::path data_path;
    io::EnviHeader header;
    std::vector<std::uint64_t> captures;  ///< its captures' global indices, in file order
    std::vector<std::string> ids, windows, datetimes;  ///< per capture
    std::uint64_t first_line = 0;  ///< lines first_line … end_line − 1 of each capture
    std::uint64_t end_line = 0;
    std::uint64_t whole_lines = 0;  ///< lines per capture of the whole file
    /// The whole file's captures as index runs ("{0:4, 7}"), compared between parts and
    /// expanded once per file (WholeFile::captures), never per part.
    std::string whole_captures;
    std::uint64_t whole_capture_count = 0;
};

/// One band of lines of one capture, from a piece.
struct Segment {
    const Piece* piece = nullptr;
    std::size_t position = 0;  ///< the capture's position in the piece
    std::uint64_t first_line = 0;
    std::uint64_t end_line = 0;
};

/// A whole file and its pieces.
struct WholeFile {
    std::filesystem::path relative;
    std::vector<Piece> pieces;
    io::EnviHeader header;                       ///< of the merged file
    std::vector<std::uint64_t> captures;         ///< the whole file's captures, sorted
    std::vector<std::vector<Segment>> segments;  ///< per whole capture, in line order
};

/// Collects the problems of every file; merge writes nothing unless there is none.
class Problems {
public:
    void add(const std::filesystem::path& file, const std::string& message) {
        m_list.push_back(file.string() + ": " + message);
    }
    bool empty() const { return m_list.empty(); }
    /// Logs every problem and throws one input error counting them.
    [[noreturn]] void raise(Context& ctx) const {
        for (const std::string& p : m_list) ctx.log.error(p);
        throw input_error(std::to_string(m_list.size()) +
                          (m_list.size() == 1 ? " problem" : " problems") +
                          " in the parts (above): nothing was written");
    }

private:
    std::vector<std::string> m_list;
};

/// Reads what a glint-render header says about its captures and part into `piece` (its header
/// already read); adds a problem and returns false otherwise.
bool read_piece(Piece& piece, const std::filesystem::path& shown, Problems& problems);

/// Checks that the pieces of `file` cover every line of every capture once and agree; fills
/// its merged header and segments. `shown` names the whole file in problems.
void resolve(WholeFile& file, const std::filesystem::path& shown, Problems& problems);

}  // namespace glint::app_envi::merge_detail
