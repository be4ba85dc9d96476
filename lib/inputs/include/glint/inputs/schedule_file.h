// SPDX-License-Identifier: Apache-2.0
// The reader of glint-schedule JSON files (`glint-schedule --format json`, docs/formats.md):
// the one reading of the capture lists glint-render --schedule renders and glint-envi merge
// --expect checks.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace glint::inputs {

/// The largest glint-schedule file read (2 GiB): a glint-schedule JSON of the 10⁶ captures one
/// render plans is about 2 GB; anything larger is not one.
inline constexpr std::size_t kMaxScheduleFileBytes = std::size_t{2} << 30;

/// What a glint-schedule JSON file says, as the tools that take one use it.
struct ScheduleFile {
    /// One element of its `captures` array.
    struct Capture {
        std::uint64_t index = 0;  ///< `index`: the capture's global schedule index
        /// `files.image` and `files.truth[]` (read only when asked for; empty otherwise).
        std::string image;
        std::vector<std::string> truth;
    };
    std::vector<Capture> captures;  ///< in file order (at least one)
    /// `selection.shard` K/N of a shard made `"by": "rows"` (a band of lines of every capture);
    /// none for a whole schedule or a shard by captures.
    std::optional<std::pair<std::uint64_t, std::uint64_t>> row_shard;
    /// `provenance.working_folder`: the folder glint-schedule ran in, when it says so.
    std::optional<std::string> working_folder;
};

/// Reads glint-schedule JSON `file` ("-": standard input), streaming: nothing but what
/// ScheduleFile holds is kept, and the captures' file names only when `with_files`. Throws
/// glint::Error (io) when unreadable or over kMaxScheduleFileBytes, (input, with the file)
/// when it is not JSON, not a glint-schedule file, has no `captures` array, a capture without
/// a non-negative integer `index`, no capture at all, or a `selection.shard` whose `by` is
/// neither "captures" nor "rows" or whose row shard lacks 1 <= K <= N.
ScheduleFile read_schedule_file(const std::filesystem::path& file, bool with_files = false);

}  // namespace glint::inputs
