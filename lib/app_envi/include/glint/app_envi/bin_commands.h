// SPDX-License-Identifier: Apache-2.0
// glint-envi on DIRSIG lidar BIN files (glint/io/lidar_bin.h; docs/lidar-bin.md): `info`
// reports the file, task and pulse headers (text or JSON), `convert` writes one ENVI cube per
// pulse — x × y × (1 + bins · samples per bin), BIP float64, band 0 the passive photon rate
// (photons/s), then the time bins (photons) named by their start time after the pulse.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "glint/app_envi/report.h"
#include "glint/core/context.h"
#include "glint/io/lidar_bin.h"

namespace glint::app_envi {

/// True when `path` is a file beginning with DIRSIG's BIN magic (DIRSIGPROTO).
bool is_lidar_bin(const std::filesystem::path& path);

/// What `info` reports of a BIN file: every header, and each pulse's totals.
struct BinSummary {
    struct Pulse {
        io::BinPulse header;                 ///< `data` empty
        double passive_photons_per_s = 0.0;  ///< the sum of every pixel's passive rate
        double active_photons = 0.0;         ///< the sum of every time sample
    };
    struct Task {
        io::BinTaskHeader header;
        std::vector<Pulse> pulses;
    };
    io::BinFileHeader header;
    std::vector<Task> tasks;
    std::uint64_t pulse_count() const;
};

/// Reads a BIN file through io::BinReader, every pulse's data inflated in pieces of at most
/// 64 Ki values to total it: memory grows with the headers, never with the data (a zip bomb
/// or a sparse 20 GB file costs time in proportion to its data, not memory). Throws what
/// io::BinReader throws; (cancelled) when `cancel` is raised.
BinSummary summarize_bin(const std::filesystem::path& path, const CancelToken& cancel);

/// The text report of a BIN file (what `info` prints).
std::string format_bin_text(const std::filesystem::path& path, const BinSummary& file);
/// Its JSON report, serialized with 2-space indentation.
std::string format_bin_json(const std::filesystem::path& path, const BinSummary& file);

/// Writes `input`'s pulses as ENVI cubes: with `pulse` (0-based over the whole file) that one
/// to `output`; else every pulse to `output` with `-pNNNN` before its extension. With `range`,
/// each pulse becomes a range image instead: x × y × 2, BIP float64, band 0 the range (m) of
/// the pixel's strongest time sample — c/2 × the sample's centre time after the pulse — and
/// band 1 its photons (both 0 for a pixel with no return). Returns the files written. Throws
/// glint::Error (usage) for a pulse out of range or an output that is not ENVI, (input) for a
/// bad BIN file, (io) when an output cannot be written. The file is read twice: once whole,
/// checked, before anything is written, then pulse by pulse, one line of a cube held at a
/// time (a line beyond ctx.max_memory_bytes is refused).
std::vector<std::filesystem::path> convert_bin(const std::filesystem::path& input,
                                               const std::filesystem::path& output,
                                               std::optional<std::uint64_t> pulse, bool range,
                                               const Context& ctx);

}  // namespace glint::app_envi
