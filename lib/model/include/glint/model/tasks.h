// SPDX-License-Identifier: Apache-2.0
// TaskList (a `.tasks` file): the reference date-time and the collection windows.
//
// | element | type | unit | default |
// |---|---|---|---|
// | tasklist/reference/datetime@type=absolute | ISO-8601 with UTC offset | - | required |
// | task/metadata/entry (Name, Description) | text | - | "" |
// | task/start/datetime@type=relative/absolute | seconds after reference, or ISO-8601 | s | required |
// | task/stop/datetime | as start; stop >= start | s | required |
#pragma once

#include <string>
#include <vector>

#include "glint/core/datetime.h"
#include "glint/model/common.h"

namespace glint::model {

/// One collection window, times relative to the reference date-time.
struct Task {
    std::string name;
    std::string description;
    double start_s = 0.0;
    double stop_s = 0.0;  ///< >= start_s; equal means one instantaneous capture
    ErrorContext where;
};

/// A `.tasks` file.
struct TaskList {
    std::string file;  ///< as named to the reader
    DateTime reference;
    std::vector<Task> tasks;
};

}  // namespace glint::model
