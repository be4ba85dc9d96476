// SPDX-License-Identifier: Apache-2.0
// The streaming writers of glint-schedule: the "glint-schedule" JSON, the text table and
// DIRSIG's capture_list view. Each writes its head in begin(), one capture per call to
// capture() (straight to the stream, nothing kept), and its tail in end().
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "glint/app_schedule/schedule_tool.h"
#include "glint/core/datetime.h"
#include "glint/schedule/schedule.h"

namespace glint::app_schedule::internal {

/// What every writer needs to know about the run.
struct RunInfo {
    const schedule::Schedule* schedule = nullptr;
    const Options* options = nullptr;
    std::uint64_t seed = 1;
    const std::vector<std::string>* arguments = nullptr;  ///< the command line (Context)
};

/// One capture and everything derived from it that more than one writer uses.
struct CaptureRecord {
    schedule::Capture capture;
    const schedule::ClockedFocalPlane* source = nullptr;
    const schedule::PluginSchedule* plugin = nullptr;
    std::uint64_t event_number = 0;  ///< 1-based among its plugin's captures in its task
    std::uint64_t event_count = 0;   ///< captures of its plugin in its task
    std::uint64_t problems = 0;
    /// The lines [a, b) of a --by rows shard; none: the whole capture.
    std::optional<std::pair<std::uint64_t, std::uint64_t>> rows;
    std::filesystem::path image;  ///< empty when the source writes no image
    std::vector<std::filesystem::path> truth;
};

/// Totals of what was written (the JSON tail).
struct WrittenTotals {
    std::uint64_t captures = 0;
    std::uint64_t problems = 0;
};

/// A streaming writer of one output format.
class CaptureWriter {
public:
    virtual ~CaptureWriter() = default;
    virtual void begin() = 0;
    virtual void capture(const CaptureRecord& record) = 0;
    virtual void end(const WrittenTotals& totals) = 0;
};

/// The text table writer (text_writer.cpp).
std::unique_ptr<CaptureWriter> make_text_writer(const RunInfo& info, std::ostream& out);
/// The writer of `format` on `out`.
std::unique_ptr<CaptureWriter> make_writer(OutputFormat format, const RunInfo& info,
                                           std::ostream& out);

using Json = nlohmann::ordered_json;

/// The "provenance" object: tool, glint version, arguments, seed.
Json provenance_json(const RunInfo& info);
/// The "selection" object: the filters and shard as given (null where not given).
Json selection_json(const Filters& filters);
/// The "plugins" array: per BasicPlatform entry its files, output folder and prefix,
/// reference date-time, tasks and capturing focal planes (with analytic counts).
Json plugins_json(const RunInfo& info);
/// A path as JSON text (generic form); null when empty.
Json path_json(const std::filesystem::path& path);
/// An ISO-8601 UTC date-time `seconds` after `reference`.
std::string datetime_utc(const DateTime& reference, double seconds);

/// Writes the --summary report of the selection in `format` (json, or text otherwise).
/// Enumerates the captures when the selection needs it (--captures, --shard).
void write_summary(const RunInfo& info, const Selection& selection, Context& ctx,
                   std::ostream& out);

}  // namespace glint::app_schedule::internal
