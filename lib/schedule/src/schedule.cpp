// SPDX-License-Identifier: Apache-2.0
// The loaded schedule: counts, output names, and the streaming generator — one cursor per
// (source, task) in a binary min-heap ordered by (start time, source, task); the source
// order is (plugin, instrument, focal plane), so ties fall in the documented order.
#include "glint/schedule/schedule.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>

#include "glint/core/error.h"
#include "glint/model/truth.h"
#include "schedule_impl.h"

namespace glint::schedule {

namespace {

/// Zero-based index, zero-padded to 4 digits, in full beyond 9999.
std::string index_text(std::uint64_t index) {
    char text[32];
    std::snprintf(text, sizeof text, "%04llu", static_cast<unsigned long long>(index));
    return text;
}

}  // namespace

std::filesystem::path output_file(const model::ImageFile& image, const std::string& folder,
                                  const std::string& prefix, std::size_t task_index,
                                  std::uint64_t capture_index) {
    std::string name = prefix + image.basename;
    switch (image.schedule) {
        case model::ImageSchedule::simulation:
            break;
        case model::ImageSchedule::task:
            name += "-t" + index_text(task_index);
            break;
        case model::ImageSchedule::capture:
            name += "-t" + index_text(task_index) + "-c" + index_text(capture_index);
            break;
    }
    if (!image.extension.empty()) name += "." + image.extension;
    if (folder.empty()) return name;
    return std::filesystem::path(folder) / name;
}

Schedule::Schedule() : m_impl(std::make_unique<Impl>()) {}
Schedule::Schedule(Schedule&&) noexcept = default;
Schedule& Schedule::operator=(Schedule&&) noexcept = default;
Schedule::~Schedule() = default;

const std::filesystem::path& Schedule::simulation_file() const { return m_impl->simulation_file; }
const motion::SceneFrame& Schedule::frame() const { return m_impl->frame; }
const std::vector<PluginSchedule>& Schedule::plugins() const { return m_impl->plugins; }
const std::vector<ClockedFocalPlane>& Schedule::sources() const { return m_impl->sources; }

const ClockTicks& Schedule::ticks(std::size_t source, std::size_t task) const {
    if (source >= m_impl->ticks.size()) {
        throw usage_error("source " + std::to_string(source) + " out of range (the schedule has " +
                          std::to_string(m_impl->ticks.size()) + ")");
    }
    const std::vector<ClockTicks>& per_task = m_impl->ticks[source];
    if (task >= per_task.size()) {
        throw usage_error("task " + std::to_string(task) + " out of range (the plugin has " +
                          std::to_string(per_task.size()) + ")");
    }
    return per_task[task];
}

std::uint64_t Schedule::count(std::size_t source, std::size_t task) const {
    return ticks(source, task).size();
}

std::uint64_t Schedule::total_captures() const { return m_impl->total_captures; }
std::uint64_t Schedule::total_problems() const { return m_impl->total_problems; }

std::filesystem::path Schedule::image_file(const Capture& capture) const {
    const ClockedFocalPlane& source = m_impl->sources.at(capture.source);
    const model::ImageFile& image = source.focal_plane->capture_method.image_file;
    if (image.basename.empty()) return {};
    const PluginSchedule& plugin = m_impl->plugins[source.plugin];
    return output_file(image, plugin.output_folder, plugin.output_prefix, capture.task_index,
                       capture.capture_index);
}

std::vector<std::filesystem::path> Schedule::truth_files(const Capture& capture) const {
    const ClockedFocalPlane& source = m_impl->sources.at(capture.source);
    const PluginSchedule& plugin = m_impl->plugins[source.plugin];
    std::vector<std::filesystem::path> files;
    for (const model::TruthCollection& truth : source.focal_plane->truth_collections) {
        // A disabled collection or one without collectors writes nothing (the reader warned).
        if (!model::writes_truth(truth)) continue;
        files.push_back(output_file(truth.image_file, plugin.output_folder, plugin.output_prefix,
                                    capture.task_index, capture.capture_index));
    }
    return files;
}

// ---------------------------------------------------------------------------------------
// Generator

// A named namespace, not an anonymous one: Generator::State, a member of a class with
// external linkage, holds Cursors (GCC's -Wsubobject-linkage in a unity build).
namespace generator_detail {

/// The next capture of one (source, task).
struct Cursor {
    double time_s = 0.0;  ///< start of capture `next`
    std::size_t source = 0;
    std::size_t task = 0;
    std::uint64_t next = 0;  ///< capture index within the task
    std::uint64_t count = 0;
    double integration_s = 0.0;
    const ClockTicks* ticks = nullptr;
};

/// Schedule order: start time, then source (plugin, instrument, focal plane), then task.
bool before(const Cursor& a, const Cursor& b) {
    if (a.time_s != b.time_s) return a.time_s < b.time_s;
    if (a.source != b.source) return a.source < b.source;
    return a.task < b.task;
}

}  // namespace generator_detail

using generator_detail::before;
using generator_detail::Cursor;

struct Schedule::Generator::State {
    std::vector<Cursor> heap;  ///< binary min-heap under before()
    std::uint64_t index = 0;

    void sift_down(std::size_t i) {
        const std::size_t n = heap.size();
        Cursor moving = heap[i];
        while (true) {
            std::size_t child = 2 * i + 1;
            if (child >= n) break;
            if (child + 1 < n && before(heap[child + 1], heap[child])) ++child;
            if (!before(heap[child], moving)) break;
            heap[i] = heap[child];
            i = child;
        }
        heap[i] = moving;
    }
};

Schedule::Generator::Generator(std::unique_ptr<State> state) : m_state(std::move(state)) {}
Schedule::Generator::~Generator() = default;
Schedule::Generator::Generator(Generator&&) noexcept = default;

std::optional<Capture> Schedule::Generator::next() {
    State& state = *m_state;
    if (state.heap.empty()) return std::nullopt;
    Cursor& top = state.heap.front();
    Capture capture;
    capture.index = state.index++;
    capture.task_index = top.task;
    capture.capture_index = top.next;
    capture.source = top.source;
    capture.t0_s = top.time_s;
    capture.t1_s = top.time_s + top.integration_s;
    if (++top.next < top.count) {
        top.time_s = top.ticks->time_s(top.next);
    } else {
        top = state.heap.back();
        state.heap.pop_back();
        if (state.heap.empty()) return capture;
    }
    state.sift_down(0);
    return capture;
}

Schedule::Generator Schedule::captures() const {
    auto state = std::make_unique<Generator::State>();
    for (std::size_t s = 0; s < m_impl->sources.size(); ++s) {
        const std::vector<ClockTicks>& per_task = m_impl->ticks[s];
        for (std::size_t t = 0; t < per_task.size(); ++t) {
            if (per_task[t].empty()) continue;
            state->heap.push_back(Cursor{per_task[t].time_s(0), s, t, 0, per_task[t].size(),
                                         m_impl->sources[s].window_s(), &per_task[t]});
        }
    }
    std::sort(state->heap.begin(), state->heap.end(), before);  // sorted = a valid min-heap
    return Generator(std::move(state));
}

std::vector<double> clock_ticks(const model::Clock& clock,
                                const std::vector<model::MasterClock>& clock_table,
                                const std::vector<double>& trigger_times_s, double start_s,
                                double stop_s) {
    return ClockTicks(clock, clock_table, trigger_times_s, start_s, stop_s).times_s();
}

}  // namespace glint::schedule
