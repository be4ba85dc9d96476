// SPDX-License-Identifier: Apache-2.0
// One firing of a focal plane's processing tasks (the DIRSIG5 BasicPlatform manual's "Inline
// Processing"): which event of the capture schedule it is, the tasks that run at it, and the
// radiometric image file its $$IMG_BASENAME$$ names. The renderer plans and fires these
// (glint/render/render.h); lib/process runs the tasks (glint/process/processing_runner.h).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "glint/model/capture.h"

namespace glint::model {

/// One event of one focal plane's processing schedule.
struct ProcessingEvent {
    ProcessingSchedule kind = ProcessingSchedule::capture_completed;
    std::uint64_t source = 0;   ///< the focal plane: its schedule source index
    std::string focal_plane;    ///< "Instrument -> FocalPlane", for messages
    std::uint64_t task = 0;     ///< task index within its BasicPlatform's task list
    std::uint64_t capture = 0;  ///< capture index within that task
    /// The tasks of the focal plane that run at this event (in file order; not empty).
    std::vector<ProcessingTask> tasks;
    /// The radiometric image file of the event's capture (collection and task events: the
    /// first capture's for *_started, the last capture's for *_completed).
    std::filesystem::path file;
    /// Whether `file` is published (complete, under its name) when the event fires.
    bool file_complete = false;
};

}  // namespace glint::model
