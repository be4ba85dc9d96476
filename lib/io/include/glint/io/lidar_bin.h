// SPDX-License-Identifier: Apache-2.0
// DIRSIG's lidar BIN format (the lidar capture method's output; docs/lidar-bin.md): a file
// header, then per task a task header, then per pulse a pulse header and its data — the
// per-pixel passive photon rate followed by the time-bin photon counts, float64, zlib
// compressed. Every multi-byte value uses the byte order the file header names; strings are
// fixed-length and NUL padded. The reader takes format versions 0, 1 and 2; the writer writes
// version 2, little endian. Pixel order of pulse data (the reading of the two published
// readers that index x and y separately, which the writer follows; docs/lidar-bin.md):
// pixel after pixel with x (column) slowest and y (row) fastest — a C array [x][y][value] —
// each pixel's 1 + bins × samples_per_bin values together, the passive rate first.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <istream>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "glint/core/atomic_file.h"

namespace glint::io {

/// The BIN file header.
struct BinFileHeader {
    std::uint8_t version = 2;
    bool little_endian = true;
    std::string created;         ///< 15 characters, "YYYYMMDDThhmmss" (UTC)
    std::string dirsig_version;  ///< 32 characters
    std::string description;     ///< 256 characters
    double origin_latitude_deg = 0.0;
    double origin_longitude_deg = 0.0;
    double origin_height_m = 0.0;
    std::string transmitter_mount;  ///< 16 characters
    std::string receiver_mount;     ///< 16 characters
    std::uint32_t x_count = 0;
    std::uint32_t y_count = 0;
    double x_pitch_m = 0.0;
    double y_pitch_m = 0.0;
    double x_offset_m = 0.0;  ///< version ≥ 1
    double y_offset_m = 0.0;
    double k1 = 0.0;  ///< lens distortion, version ≥ 1
    double k2 = 0.0;
    std::uint32_t task_count = 0;
    std::uint16_t focal_plane_id = 0;  ///< version ≥ 2
};

/// A task header.
struct BinTaskHeader {
    std::string description;  ///< 64 characters
    std::string start;        ///< 15 characters
    std::string stop;         ///< 15 characters
    double focal_length_mm = 0.0;
    double pulse_rate_hz = 0.0;
    double pulse_duration_s = 0.0;
    double pulse_energy_j = 0.0;
    double laser_center_um = 0.0;
    double laser_width_um = 0.0;
    std::uint32_t pulse_count = 0;
};

using Affine16 = std::array<double, 16>;  ///< row-major 4 × 4
inline constexpr Affine16 kIdentity16{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

/// Where pixel (x, y) of an array of `y_count` rows sits in a pulse's data, in pixels: x
/// slowest, y fastest (the pixel order above).
constexpr std::size_t bin_pixel_index(std::size_t x, std::size_t y, std::size_t y_count) {
    return x * y_count + y;
}

/// A pulse: its header and, decompressed, its data.
struct BinPulse {
    double time_s = 0.0;
    double gate_start_s = 0.0;  ///< after the pulse
    double gate_stop_s = 0.0;
    std::uint32_t bin_count = 0;
    std::uint32_t samples_per_bin = 1;
    std::array<double, 3> platform_location{};
    std::array<double, 3> platform_rotation{};
    std::string angle_order = "xyz";  ///< versions 0 and 1 only
    Affine16 transmitter_to_mount = kIdentity16;
    std::array<double, 3> transmitter_mount_pointing{};
    Affine16 transmitter_mount_to_platform = kIdentity16;
    Affine16 receiver_to_mount = kIdentity16;
    std::array<double, 3> receiver_mount_pointing{};
    Affine16 receiver_mount_to_platform = kIdentity16;
    std::int32_t data_type = 5;               ///< 5 = float64 (the only one read)
    std::uint8_t compression = 1;             ///< 0 none, 1 zlib
    std::uint32_t pulse_index = 0;            ///< version 2
    std::uint64_t data_bytes = 0;             ///< as stored
    Affine16 transmit_mueller = kIdentity16;  ///< version 2
    Affine16 receive_mueller = kIdentity16;
    /// x_count · y_count · (1 + bin_count · samples_per_bin) values, pixel (x, y) from
    /// bin_pixel_index(x, y, y_count) · values_per_pixel() on.
    std::vector<double> data;

    /// Values per pixel.
    std::size_t values_per_pixel() const {
        return 1 + static_cast<std::size_t>(bin_count) * samples_per_bin;
    }
};

/// A task and its pulses.
struct BinTask {
    BinTaskHeader header;
    std::vector<BinPulse> pulses;
};

/// A whole BIN file.
struct BinFile {
    BinFileHeader header;
    std::vector<BinTask> tasks;
};

/// Reads a BIN file as a stream: the file header at construction, then each task's header
/// and each pulse's header in file order, and a pulse's data in pieces of the caller's size,
/// inflated as they are read. Nothing but the current pulse's header and a 1 MiB window of
/// its compressed data is held, so memory does not grow with the file, a pulse or what its
/// data claims to inflate to (a zip bomb). Throws glint::Error (io) when the file cannot be
/// read, (input, naming the file and the byte offset) when it is not a BIN file or is
/// truncated or inconsistent: counts whose product overflows, a pulse whose data would lie
/// beyond the end of the file, data that does not inflate to exactly its values.
class BinReader {
public:
    /// Opens `path` (a regular file) and reads its file header.
    explicit BinReader(const std::filesystem::path& path);
    /// Reads the file `bytes` from memory, named `name` in messages (tests, fuzzing).
    BinReader(std::string bytes, std::string name);
    ~BinReader();
    BinReader(const BinReader&) = delete;
    BinReader& operator=(const BinReader&) = delete;

    const BinFileHeader& header() const noexcept { return m_header; }

    /// The next task's header (what is left of the current task is skipped), or nullopt
    /// after the last one, when nothing may follow it in the file.
    std::optional<BinTaskHeader> next_task();
    /// The next pulse of the current task with its header and an empty `data` (what is left
    /// of the current pulse's data is skipped, unread), or nullopt after the task's last.
    /// Versions 0 and 1 number pulses in file order.
    std::optional<BinPulse> next_pulse();
    /// The values of the current pulse not read yet.
    std::uint64_t values_left() const noexcept { return m_values_left; }
    /// Fills `out` with the current pulse's next values (native byte order). Throws
    /// glint::Error (usage) for more values than are left, (input) for data that does not
    /// inflate to them; after the pulse's last value, also for data that holds more.
    void read_values(std::span<double> out);

private:
    struct Inflater;
    std::string m_name;  ///< the file, for messages
    std::unique_ptr<std::istream> m_stream;
    std::istream& m_in;
    std::uint64_t m_size = 0;  ///< the file's bytes
    std::uint64_t m_at = 0;    ///< where the next read starts
    bool m_swap = false;
    BinFileHeader m_header;
    std::uint32_t m_tasks_left = 0;
    std::uint32_t m_pulses_left = 0;
    std::uint32_t m_pulse_number = 0;
    std::uint8_t m_compression = 0;
    std::uint64_t m_data_left = 0;    ///< compressed bytes of the current pulse not read
    std::uint64_t m_values_left = 0;  ///< values of the current pulse not returned
    std::unique_ptr<Inflater> m_inflater;

    [[noreturn]] void fail(const std::string& what) const;
    std::string take(std::size_t n, const char* what);
    template <class T>
    T value(const char* what);
    std::string text(std::size_t n, const char* what);
    template <std::size_t N>
    std::array<double, N> doubles(const char* what);
    void read_file_header();
    void skip_data();
    void refill();
    /// One inflate() into `room` bytes at `out` (input refilled first); returns the bytes
    /// made. Fails with `ends_early` when the data ends inside the zlib stream.
    std::size_t inflate_step(unsigned char* out, std::size_t room, const char* ends_early);
    void inflate_into(unsigned char* bytes, std::size_t count);
    void finish_inflating();
};

/// Reads a whole BIN file (versions 0–2, either byte order; zlib or uncompressed float64
/// data) through a BinReader, every pulse's values held: for small files (tests, tools).
/// Throws what BinReader throws, and glint::Error (input) for a file whose values would take
/// more than 4 GiB.
BinFile read_bin(const std::filesystem::path& path);

/// Writes `file` as a version-2, little-endian BIN file with zlib-compressed data, atomically
/// (a BinWriter). Throws what BinWriter throws.
void write_bin(const std::filesystem::path& path, const BinFile& file);

/// Writes a version-2, little-endian BIN file pulse by pulse, so a renderer holds one pulse at
/// a time: the file header at construction, then for each of the `task_count` tasks
/// begin_task() and its pulses, then commit(), which publishes the file under its name
/// (atomically: a writer destroyed before commit() leaves nothing there).
class BinWriter {
public:
    /// Opens the temporary file and writes the header (its task count is `task_count`).
    /// Throws glint::Error (io) when it cannot be created.
    BinWriter(const std::filesystem::path& path, const BinFileHeader& header,
              std::uint32_t task_count);
    ~BinWriter();
    BinWriter(const BinWriter&) = delete;
    BinWriter& operator=(const BinWriter&) = delete;

    /// Starts a task of `pulse_count` pulses. Throws glint::Error (usage) when the previous
    /// task is not complete or every task has been written.
    void begin_task(const BinTaskHeader& header, std::uint32_t pulse_count);
    /// Writes one pulse of the current task, its data compressed. Throws glint::Error (usage)
    /// when no task is open, the task is complete or the data size does not match the header
    /// counts, (io) when it cannot be written.
    void add_pulse(const BinPulse& pulse);
    /// Publishes the file. Throws glint::Error (usage) when a task or pulse is missing, (io)
    /// when it cannot be published.
    void commit();
    /// The file's final name.
    const std::filesystem::path& path() const noexcept { return m_path; }

private:
    std::filesystem::path m_path;
    AtomicFile m_file;
    std::size_t m_pixels = 0;
    std::uint32_t m_tasks_left = 0;
    std::uint32_t m_pulses_left = 0;
    bool m_task_open = false;
};

}  // namespace glint::io
