// SPDX-License-Identifier: Apache-2.0
// The processing events of a render (render_parts.h, plan_events): for each focal plane with
// processing tasks, collection_started before the run's first capture and collection_completed
// after its last; task_started before its first capture of a task and task_completed after its
// last; capture_started and capture_completed around each of its captures. docs/processing.md
// is the reference.
#include <map>
#include <utility>

#include "render_parts.h"

namespace glint::render::detail {
namespace {

using model::ProcessingSchedule;

/// The tasks of `tasks` scheduled at `kind`.
std::vector<model::ProcessingTask> tasks_at(const std::vector<model::ProcessingTask>& tasks,
                                            ProcessingSchedule kind) {
    std::vector<model::ProcessingTask> out;
    for (const model::ProcessingTask& task : tasks) {
        if (task.schedule == kind) out.push_back(task);
    }
    return out;
}

}  // namespace

EventPlan plan_events(const RenderPlan& render_plan) {
    const RenderInputs& in = render_plan.inputs;
    const std::vector<PlannedCapture>& captures = render_plan.captures;
    EventPlan plan;
    plan.before.resize(captures.size());
    plan.after.resize(captures.size());
    if (captures.empty()) return plan;

    // The last planned capture of each file (its file is published after it), of each
    // (source, task) and of each source; the first of each (source, task) and source.
    std::map<std::filesystem::path, std::size_t> last_of_file;
    std::map<std::pair<std::size_t, std::uint64_t>, std::size_t> first_of_task;
    std::map<std::pair<std::size_t, std::uint64_t>, std::size_t> last_of_task;
    std::map<std::size_t, std::size_t> first_of_source;
    std::map<std::size_t, std::size_t> last_of_source;
    for (std::size_t i = 0; i < captures.size(); ++i) {
        const schedule::Capture& c = captures[i].capture;
        last_of_file[captures[i].file] = i;
        first_of_task.emplace(std::make_pair(c.source, c.task_index), i);
        last_of_task[{c.source, c.task_index}] = i;
        first_of_source.emplace(c.source, i);
        last_of_source[c.source] = i;
    }
    // Appends the event `kind` of capture i's focal plane, about capture i, to `sink`.
    auto event = [&](ProcessingSchedule kind, std::size_t i,
                     std::vector<model::ProcessingEvent>& sink) {
        const PlannedCapture& p = captures[i];
        const schedule::ClockedFocalPlane& source = in.schedule->sources()[p.capture.source];
        std::vector<model::ProcessingTask> tasks =
            tasks_at(source.focal_plane->capture_method.processing, kind);
        if (tasks.empty()) return;
        model::ProcessingEvent e;
        e.kind = kind;
        e.source = p.capture.source;
        e.focal_plane = source.instrument->name + " -> " + source.focal_plane->name;
        e.task = p.capture.task_index;
        e.capture = p.capture.capture_index;
        e.tasks = std::move(tasks);
        e.file = p.file;
        const bool completed = kind == ProcessingSchedule::capture_completed ||
                               kind == ProcessingSchedule::task_completed ||
                               kind == ProcessingSchedule::collection_completed;
        e.file_complete = completed && last_of_file.at(p.file) == i;
        sink.push_back(std::move(e));
    };
    // The collection starts before the run's first capture, for every focal plane (in
    // schedule source order), and completes after its last.
    for (const auto& [source, first] : first_of_source) {
        event(ProcessingSchedule::collection_started, first, plan.before.front());
    }
    for (std::size_t i = 0; i < captures.size(); ++i) {
        const schedule::Capture& c = captures[i].capture;
        if (first_of_task.at({c.source, c.task_index}) == i) {
            event(ProcessingSchedule::task_started, i, plan.before[i]);
        }
        event(ProcessingSchedule::capture_started, i, plan.before[i]);
        event(ProcessingSchedule::capture_completed, i, plan.after[i]);
        if (last_of_task.at({c.source, c.task_index}) == i) {
            event(ProcessingSchedule::task_completed, i, plan.after[i]);
        }
    }
    for (const auto& [source, last] : last_of_source) {
        event(ProcessingSchedule::collection_completed, last, plan.after.back());
    }
    return plan;
}

std::vector<model::ProcessingEvent> EventPlan::in_order() const {
    std::vector<model::ProcessingEvent> out;
    for (std::size_t i = 0; i < before.size(); ++i) {
        out.insert(out.end(), before[i].begin(), before[i].end());
        out.insert(out.end(), after[i].begin(), after[i].end());
    }
    return out;
}

}  // namespace glint::render::detail
