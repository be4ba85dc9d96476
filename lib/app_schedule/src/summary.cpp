// SPDX-License-Identifier: Apache-2.0
// glint-schedule --summary: how many captures and problems the selection holds, per plugin,
// task and focal plane, and the time it spans. Counted analytically (Schedule::count per
// source and task, O(sources × tasks)) unless --captures or --shard make the selection
// depend on the order, in which case the captures are enumerated once (no poses).
#include <algorithm>
#include <cstdio>
#include <limits>

#include "glint/core/json_text.h"
#include "writers.h"

namespace glint::app_schedule::internal {
namespace {

/// Counts of the selection, per source and task.
struct Tally {
    std::vector<std::vector<std::uint64_t>> captures;  ///< [source][task]
    std::uint64_t total_captures = 0;
    std::uint64_t total_problems = 0;
    bool enumerated = false;
    double first_s = std::numeric_limits<double>::infinity();  ///< enumerated only
    double last_s = -std::numeric_limits<double>::infinity();
};

Tally count_selection(const schedule::Schedule& schedule, const Selection& selection,
                      Context& ctx) {
    const auto& sources = schedule.sources();
    Tally tally;
    tally.captures.resize(sources.size());
    for (std::size_t s = 0; s < sources.size(); ++s) {
        tally.captures[s].assign(schedule.plugins()[sources[s].plugin].tasks.tasks.size(), 0);
    }
    const std::optional<ShardSpec>& shard_spec = selection.filters().shard;
    if (selection.analytic() && (!shard_spec || shard_spec->by_rows)) {
        for (std::size_t s = 0; s < sources.size(); ++s) {
            for (std::size_t t = 0; t < tally.captures[s].size(); ++t) {
                if (selection.keeps(s, t)) tally.captures[s][t] = schedule.count(s, t);
            }
        }
    } else {
        tally.enumerated = true;
        std::optional<ShardSplitter> splitter;
        if (shard_spec && !shard_spec->by_rows) {
            splitter.emplace(selection_totals(schedule, selection, ctx.cancel),
                             selection.filters().shard->count);
        }
        const std::uint64_t total = schedule.total_captures();
        schedule::Schedule::Generator generator = schedule.captures();
        while (const std::optional<schedule::Capture> c = generator.next()) {
            if ((c->index & 0xFFFF) == 0) {
                ctx.cancel.throw_if_cancelled();
                ctx.progress.update("captures", c->index, total);
            }
            if (!selection.matches(*c)) {
                if (selection.exhausted(*c)) break;
                continue;
            }
            const std::uint64_t shard =
                splitter ? splitter->shard_of(problems_per_capture(sources[c->source])) : 0;
            if (splitter && shard > selection.filters().shard->index) break;  // contiguous
            if (!splitter || shard == selection.filters().shard->index) {
                ++tally.captures[c->source][c->task_index];
                tally.first_s = std::min(tally.first_s, c->t0_s);
                tally.last_s = std::max(tally.last_s, c->t1_s);
            }
            if (selection.exhausted(*c)) break;
        }
        ctx.progress.finish("captures", total);
    }
    for (std::size_t s = 0; s < sources.size(); ++s) {
        for (std::uint64_t n : tally.captures[s]) {
            tally.total_captures += n;
            tally.total_problems += n * selected_problems(sources[s], shard_spec);
        }
    }
    return tally;
}

std::string seconds_text(double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.6f s", value);
    return buffer;
}

}  // namespace

void write_summary(const RunInfo& info, const Selection& selection, Context& ctx,
                   std::ostream& out) {
    const schedule::Schedule& schedule = *info.schedule;
    const auto& sources = schedule.sources();
    const Tally tally = count_selection(schedule, selection, ctx);

    // Per plugin: its tasks and focal planes with the selection's counts; the task span.
    double span_begin = std::numeric_limits<double>::infinity();
    double span_end = -std::numeric_limits<double>::infinity();
    Json plugins = Json::array();
    for (std::size_t p = 0; p < schedule.plugins().size(); ++p) {
        const schedule::PluginSchedule& plugin = schedule.plugins()[p];
        Json tasks = Json::array();
        for (std::size_t t = 0; t < plugin.tasks.tasks.size(); ++t) {
            std::uint64_t captures = 0;
            std::uint64_t problems = 0;
            for (std::size_t s = 0; s < sources.size(); ++s) {
                if (sources[s].plugin != p) continue;
                captures += tally.captures[s][t];
                problems +=
                    tally.captures[s][t] * selected_problems(sources[s], selection.filters().shard);
            }
            const model::Task& task = plugin.tasks.tasks[t];
            if (captures > 0) {
                span_begin = std::min(span_begin, task.start_s);
                span_end = std::max(span_end, task.stop_s);
            }
            tasks.push_back(Json{{"index", t},
                                 {"name", task.name},
                                 {"start_s", task.start_s},
                                 {"stop_s", task.stop_s},
                                 {"capture_count", captures},
                                 {"problem_count", problems}});
        }
        Json focal_planes = Json::array();
        for (std::size_t s = 0; s < sources.size(); ++s) {
            if (sources[s].plugin != p) continue;
            std::uint64_t captures = 0;
            for (std::uint64_t n : tally.captures[s]) captures += n;
            focal_planes.push_back(
                Json{{"instrument_index", sources[s].instrument_index},
                     {"instrument", sources[s].instrument ? sources[s].instrument->name : ""},
                     {"focal_plane_index", sources[s].focal_plane_index},
                     {"focal_plane",
                      sources[s].focal_plane ? Json(sources[s].focal_plane->name) : Json(nullptr)},
                     {"problems_per_capture", problems_per_capture(sources[s])},
                     {"capture_count", captures},
                     {"problem_count",
                      captures * selected_problems(sources[s], selection.filters().shard)}});
        }
        plugins.push_back(Json{{"plugin_index", plugin.plugin_index},
                               {"output_prefix", plugin.output_prefix},
                               {"reference_datetime", datetime_utc(plugin.tasks.reference, 0)},
                               {"tasks", std::move(tasks)},
                               {"focal_planes", std::move(focal_planes)}});
    }
    const bool any = tally.total_captures > 0;
    const Json task_span = any ? Json::array({span_begin, span_end}) : Json(nullptr);
    const Json capture_span =
        tally.enumerated && any ? Json::array({tally.first_s, tally.last_s}) : Json(nullptr);

    if (info.options->format == OutputFormat::json) {
        Json j;
        j["format"] = "glint-schedule-summary";
        j["version"] = 1;
        j["provenance"] = provenance_json(info);
        j["simulation_file"] = schedule.simulation_file().generic_string();
        j["selection"] = selection_json(info.options->filters);
        j["capture_count"] = tally.total_captures;
        j["problem_count"] = tally.total_problems;
        j["task_span_s"] = task_span;
        j["duration_s"] = any ? Json(span_end - span_begin) : Json(nullptr);
        j["capture_span_s"] = capture_span;
        j["plugins"] = std::move(plugins);
        out << json_text(j, 2) << '\n';
        return;
    }
    out << "simulation: " << schedule.simulation_file().generic_string() << '\n';
    out << "captures: " << tally.total_captures << '\n';
    out << "problems: " << tally.total_problems << " pixels\n";
    if (any) {
        out << "task span: " << seconds_text(span_begin) << " to " << seconds_text(span_end) << " ("
            << seconds_text(span_end - span_begin) << ")\n";
    } else {
        out << "task span: none\n";
    }
    if (!capture_span.is_null()) {
        out << "capture span: " << seconds_text(tally.first_s) << " to "
            << seconds_text(tally.last_s) << '\n';
    }
    for (const Json& plugin : plugins) {
        out << "plugin " << plugin["plugin_index"].get<std::size_t>() << " (prefix \""
            << plugin["output_prefix"].get<std::string>() << "\", reference "
            << plugin["reference_datetime"].get<std::string>() << ")\n";
        for (const Json& task : plugin["tasks"]) {
            out << "  task " << task["index"].get<std::size_t>() << " \""
                << task["name"].get<std::string>() << "\" " << seconds_text(task["start_s"])
                << " to " << seconds_text(task["stop_s"]) << ": "
                << task["capture_count"].get<std::uint64_t>() << " captures, "
                << task["problem_count"].get<std::uint64_t>() << " problems\n";
        }
        for (const Json& fp : plugin["focal_planes"]) {
            out << "  " << fp["instrument"].get<std::string>() << " -> "
                << (fp["focal_plane"].is_null() ? std::string("(data recorder)")
                                                : fp["focal_plane"].get<std::string>())
                << ": " << fp["capture_count"].get<std::uint64_t>() << " captures x "
                << fp["problems_per_capture"].get<std::uint64_t>()
                << " problems = " << fp["problem_count"].get<std::uint64_t>() << "\n";
        }
    }
}

}  // namespace glint::app_schedule::internal
