// SPDX-License-Identifier: Apache-2.0
// DIRSIG's --log_info_filename JSON (the "capture list"), written as a stream by both
// glint-schedule (--format capture_list, --log_info_filename) and glint-render
// (--log_info_filename): a head with format, version, provenance and run_info, then one
// capture object per line. Field by field in docs/tools/glint-schedule.md ("The capture_list
// view").
#pragma once

#include <cstdint>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "glint/schedule/schedule.h"

namespace glint::schedule {

/// Who wrote the list.
struct CaptureListProvenance {
    std::string tool;                    ///< e.g. "glint-render"
    std::vector<std::string> arguments;  ///< the command line, program first
    std::uint64_t seed = 1;
};

/// Streams a capture list to `out`: begin(), add() per capture, end().
class CaptureListWriter {
public:
    CaptureListWriter(std::ostream& out, const Schedule& schedule,
                      CaptureListProvenance provenance);
    /// Writes the head.
    void begin();
    /// Writes one capture: its indices, time window, plugin data (image and truth files).
    void add(const Capture& capture, const std::filesystem::path& image,
             const std::vector<std::filesystem::path>& truth);
    /// Closes the list and the document.
    void end();

private:
    std::ostream& m_out;
    const Schedule& m_schedule;
    CaptureListProvenance m_provenance;
    bool m_first = true;
};

}  // namespace glint::schedule
