// SPDX-License-Identifier: Apache-2.0
// The ENVI image files of a render: each file is planned with its header and the number of
// captures it will hold, opened at its first capture, receives each capture's lines in
// schedule order, whole or in bands of lines (several captures of one file are appended along the
// line axis, as a pushbroom builds its image line by line), and is published atomically — data,
// then header — when its last capture has arrived. The header's `glint capture times` and `glint
// captures` keys list the captures the file holds. Files not complete when the object is destroyed
// (an error or an interrupt) leave nothing under their final names. A lidar capture's DIRSIG BIN
// file (glint/io/lidar_bin.h) is planned with its file header and task headers the same way,
// receives its pulses one at a time in schedule order (nothing but the current pulse is held) and
// is published after its last.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "glint/core/folder_lock.h"
#include "glint/io/envi.h"
#include "glint/io/lidar_bin.h"

namespace glint::render {

/// One capture as a file records it.
struct CaptureStamp {
    std::uint64_t task = 0;     ///< task index within its plugin
    std::uint64_t capture = 0;  ///< capture index within its task
    double t0_s = 0.0;          ///< window start, s after the tasks reference
    double t1_s = 0.0;          ///< window end
    std::string datetime_utc;   ///< ISO 8601 of t0
    std::uint64_t index = 0;    ///< global schedule index (the random streams' capture key)
};

/// What a part (a file holding some of the whole file's lines or captures, glint/io/envi_part.h)
/// is part of: its header gets the `glint part ...` keys.
struct PartOf {
    std::uint64_t first_line = 0;  ///< lines first_line … end_line − 1 of each capture
    std::uint64_t end_line = 0;
    std::uint64_t whole_lines_per_capture = 0;
    std::vector<std::uint64_t> whole_captures;  ///< global indices of the whole file, sorted
};

class ImageOutputs {
public:
    ImageOutputs();
    ~ImageOutputs();
    ImageOutputs(const ImageOutputs&) = delete;
    ImageOutputs& operator=(const ImageOutputs&) = delete;
    ImageOutputs(ImageOutputs&&) noexcept;
    ImageOutputs& operator=(ImageOutputs&&) noexcept;

    /// Declares that `path` receives `captures` captures of `lines_per_capture` lines each,
    /// with `header` (its `lines` is set here); `part`, when given, says what whole file it is
    /// a part of. Nothing is created yet. Throws glint::Error (usage) when `path` is planned
    /// twice with a different header shape.
    void plan(const std::filesystem::path& path, io::EnviHeader header,
              std::uint64_t lines_per_capture, std::uint64_t captures,
              std::optional<PartOf> part = std::nullopt);

    /// Writes one capture (lines_per_capture × samples × bands values, BIP) to `path`: opens
    /// the file at its first capture, publishes it after its last. Throws glint::Error
    /// (internal) for an unplanned path or a wrong size, (io) when the file cannot be
    /// written.
    void write_capture(const std::filesystem::path& path, std::span<const double> image,
                       const CaptureStamp& stamp);

    /// Appends whole lines (samples × bands values each, BIP) of the current capture of
    /// `path`, opening the file at its first line: a capture may be written in pieces.
    /// Throws glint::Error (internal) for an unplanned path, a partial line or more lines than
    /// a capture holds, (io) when the file cannot be written.
    void write_lines(const std::filesystem::path& path, std::span<const double> lines);
    /// Ends the current capture of `path` (all its lines written: internal error otherwise)
    /// and publishes the file after its last capture.
    void end_capture(const std::filesystem::path& path, const CaptureStamp& stamp);

    /// Declares that `path` is a lidar BIN file of `header` holding `tasks` in order, each
    /// task header with its pulse count. Throws glint::Error (usage) when `path` is planned
    /// twice.
    void plan_bin(const std::filesystem::path& path, const io::BinFileHeader& header,
                  std::vector<std::pair<io::BinTaskHeader, std::uint32_t>> tasks);
    /// Writes the next pulse of `path`: opens the file at its first pulse, starts each task at
    /// its first pulse, publishes the file after its last. Throws glint::Error (internal) for
    /// an unplanned path or a pulse too many, (io) when it cannot be written.
    void write_pulse(const std::filesystem::path& path, const io::BinPulse& pulse);
    /// Locks every planned output folder that exists already (glint::FolderLock), so a
    /// second run into one of them fails before it traces anything; folders created later
    /// are locked when they are created. Throws glint::Error (io) when another run holds one.
    void lock_folders();

    /// Files published so far, in the order they were completed.
    const std::vector<std::filesystem::path>& published() const noexcept { return m_published; }
    /// Files planned, in planning order.
    std::vector<std::filesystem::path> planned() const;
    /// Every file the planned outputs write, with what it is ("image X", "header of image X",
    /// "lidar file X"), in planning order: an ENVI file writes its data and `<data>.hdr`.
    std::vector<std::pair<std::filesystem::path, std::string>> written() const;

private:
    struct File;
    /// Creates `path`'s folder (as DIRSIG does) and locks it, once per folder.
    void open_folder(const std::filesystem::path& path);
    struct BinFile;
    std::map<std::filesystem::path, std::unique_ptr<File>> m_files;
    std::map<std::filesystem::path, std::unique_ptr<BinFile>> m_bins;
    std::vector<std::filesystem::path> m_order;
    std::vector<std::filesystem::path> m_published;
    std::map<std::filesystem::path, FolderLock> m_locks;  ///< by folder, held to the end
};

}  // namespace glint::render
