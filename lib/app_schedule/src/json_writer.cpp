// SPDX-License-Identifier: Apache-2.0
// The JSON outputs of glint-schedule, written as streams: the "glint-schedule" document
// (head with provenance, options, selection and plugins; one self-contained capture object
// per line; totals at the end) and DIRSIG's --log_info_filename view (capture_list,
// run_info). Field by field in docs/tools/glint-schedule.md.

#include <filesystem>
#include <system_error>

#include "glint/core/json_text.h"
#include "glint/core/runner.h"
#include "glint/model/names.h"
#include "glint/schedule/capture_list.h"
#include "pose_json.h"
#include "writers.h"

namespace glint::app_schedule::internal {
namespace {

Json paths_json(const std::vector<std::filesystem::path>& paths) {
    Json j = Json::array();
    for (const auto& path : paths) j.push_back(path.generic_string());
    return j;
}

Json focal_plane_json(const schedule::ClockedFocalPlane& source) {
    const model::FocalPlane& fp = *source.focal_plane;
    const model::Bandpass& band = fp.capture_method.spectral_response.bandpass;
    Json j;
    j["index"] = source.focal_plane_index;
    j["name"] = fp.name;
    j["x_count"] = source.x_count;
    j["y_count"] = source.y_count;
    j["tdi"] = fp.capture_method.temporal_integration.tdi;
    if (source.tdi_stages > 1) j["tdi_stages"] = source.tdi_stages;
    j["integration_time_s"] = source.integration_time_s;
    j["bandpass_um"] = Json{{"minimum", band.min_um},
                            {"maximum", band.max_um},
                            {"delta", band.delta_um},
                            {"count", band.count}};
    j["image_schedule"] = model::name_of(fp.capture_method.image_file.schedule);
    return j;
}

/// The reference date-time the capture's times are relative to (its plugin's tasks file).
const DateTime& reference_of(const CaptureRecord& record) { return record.plugin->tasks.reference; }

Json capture_json(const CaptureRecord& record, const motion::SceneFrame& frame) {
    const schedule::Capture& c = record.capture;
    const schedule::ClockedFocalPlane& source = *record.source;
    const double t_mid_s = 0.5 * (c.t0_s + c.t1_s);
    Json j;
    j["index"] = c.index;
    j["task_index"] = c.task_index;
    j["capture_index"] = c.capture_index;
    j["event_number"] = record.event_number;
    j["event_count"] = record.event_count;
    j["plugin"] = Json{{"index", record.plugin->plugin_index},
                       {"output_folder", record.plugin->output_folder},
                       {"output_prefix", record.plugin->output_prefix},
                       {"reference_datetime", datetime_utc(reference_of(record), 0)}};
    j["instrument"] =
        Json{{"index", source.instrument_index},
             {"name", source.instrument ? source.instrument->name : ""},
             {"type", source.instrument ? model::name_of(source.instrument->type) : "generic"}};
    j["focal_plane"] = focal_plane_json(source);
    j["time_window_s"] = Json::array({c.t0_s, c.t1_s});
    j["datetime_utc"] = datetime_utc(reference_of(record), c.t0_s);
    j["problem_count"] = record.problems;
    if (record.rows) j["rows"] = Json::array({record.rows->first, record.rows->second});
    if (const std::optional<double> rolling = source.rolling_line_time_s()) {
        const double line_time_s = *rolling;
        const double last_s = line_time_s * static_cast<double>(source.y_count - 1);
        j["rolling_readout"] =
            Json{{"line_time_s", line_time_s},
                 {"line_count", source.y_count},
                 {"last_line_window_s", Json::array({c.t0_s + last_s, c.t1_s + last_s})}};
    }
    j["pose"] = pose_json(*record.plugin, source.instrument_index, t_mid_s, frame);
    j["sun"] = sun_json(add_seconds(reference_of(record), t_mid_s), frame);
    j["files"] = Json{{"image", path_json(record.image)}, {"truth", paths_json(record.truth)}};
    return j;
}

/// Writes `head` (an object) without its closing brace, so that more members can follow.
void write_open_object(std::ostream& out, const Json& head) {
    std::string text = json_text(head, 2);
    text.resize(text.size() - 2);  // drop "\n}"
    out << text;
}

/// The "glint-schedule" JSON document.
class ScheduleJsonWriter final : public CaptureWriter {
public:
    ScheduleJsonWriter(const RunInfo& info, std::ostream& out) : m_info(info), m_out(out) {}

    void begin() override {
        const schedule::Schedule& schedule = *m_info.schedule;
        const Options& options = *m_info.options;
        Json head;
        head["format"] = "glint-schedule";
        head["version"] = 1;
        head["provenance"] = provenance_json(m_info);
        head["simulation_file"] = schedule.simulation_file().generic_string();
        head["reference_datetime"] =
            schedule.plugins().empty()
                ? Json(nullptr)
                : Json(datetime_utc(schedule.plugins()[0].tasks.reference, 0));
        head["scene_origin"] =
            Json{{"latitude_deg", m_info.schedule->frame().origin().latitude_deg},
                 {"longitude_deg", m_info.schedule->frame().origin().longitude_deg},
                 {"altitude_m", m_info.schedule->frame().origin().altitude_m}};
        head["options"] = Json{
            {"output_folder", options.schedule.output_folder ? Json(*options.schedule.output_folder)
                                                             : Json(nullptr)},
            {"output_prefix", options.schedule.output_prefix ? Json(*options.schedule.output_prefix)
                                                             : Json(nullptr)},
            {"scale_resolution", options.schedule.scale_resolution}};
        head["selection"] = selection_json(options.filters);
        head["plugins"] = plugins_json(m_info);
        write_open_object(m_out, head);
        m_out << ",\n  \"captures\": [";
    }

    void capture(const CaptureRecord& record) override {
        m_out << (m_first ? "\n    " : ",\n    ")
              << json_text(capture_json(record, m_info.schedule->frame()));
        m_first = false;
    }

    void end(const WrittenTotals& totals) override {
        m_out << "\n  ],\n  \"capture_count\": " << totals.captures
              << ",\n  \"problem_count\": " << totals.problems << "\n}\n";
    }

private:
    const RunInfo& m_info;
    std::ostream& m_out;
    bool m_first = true;
};

/// DIRSIG's --log_info_filename JSON: the shared capture-list stream.
class CaptureListWriter final : public CaptureWriter {
public:
    CaptureListWriter(const RunInfo& info, std::ostream& out)
        : m_list(out, *info.schedule,
                 schedule::CaptureListProvenance{"glint-schedule", *info.arguments, info.seed}) {}

    void begin() override { m_list.begin(); }
    void capture(const CaptureRecord& record) override {
        m_list.add(record.capture, record.image, record.truth);
    }
    void end(const WrittenTotals& /*totals*/) override { m_list.end(); }

private:
    schedule::CaptureListWriter m_list;
};

}  // namespace

std::unique_ptr<CaptureWriter> make_writer(OutputFormat format, const RunInfo& info,
                                           std::ostream& out) {
    switch (format) {
        case OutputFormat::text:
            return make_text_writer(info, out);
        case OutputFormat::capture_list:
            return std::make_unique<CaptureListWriter>(info, out);
        case OutputFormat::json:
            break;
    }
    return std::make_unique<ScheduleJsonWriter>(info, out);
}

std::string datetime_utc(const DateTime& reference, double seconds) {
    return format_iso8601_utc(add_seconds(reference, seconds), 6);
}

Json path_json(const std::filesystem::path& path) {
    if (path.empty()) return nullptr;
    return path.generic_string();
}

Json provenance_json(const RunInfo& info) {
    Json j;
    j["tool"] = "glint-schedule";
    j["glint_version"] = version();
    j["arguments"] = *info.arguments;
    j["seed"] = info.seed;
    // The folder relative paths in `files` count from (glint-envi merge --expect reads them
    // wherever it runs).
    std::error_code ec;
    const std::filesystem::path working = std::filesystem::current_path(ec);
    j["working_folder"] = ec ? Json(nullptr) : Json(working.generic_string());
    return j;
}

Json selection_json(const Filters& filters) {
    Json j;
    j["task"] = filters.task ? Json(*filters.task) : Json(nullptr);
    if (filters.captures) {
        j["captures"] =
            Json::array({filters.captures->first,
                         filters.captures->end ? Json(*filters.captures->end) : Json(nullptr)});
    } else {
        j["captures"] = nullptr;
    }
    j["focal_plane"] = filters.focal_plane ? Json(*filters.focal_plane) : Json(nullptr);
    j["shard"] = filters.shard ? Json{{"index", filters.shard->index},
                                      {"count", filters.shard->count},
                                      {"by", filters.shard->by_rows ? "rows" : "captures"}}
                               : Json(nullptr);
    return j;
}

Json plugins_json(const RunInfo& info) {
    const schedule::Schedule& schedule = *info.schedule;
    Json plugins = Json::array();
    for (std::size_t p = 0; p < schedule.plugins().size(); ++p) {
        const schedule::PluginSchedule& plugin = schedule.plugins()[p];
        Json j;
        j["plugin_index"] = plugin.plugin_index;
        j["output_folder"] = plugin.output_folder;
        j["output_prefix"] = plugin.output_prefix;
        j["platform_file"] = plugin.platform ? Json(plugin.platform->file) : Json(nullptr);
        j["tasks_file"] = plugin.tasks.file;
        j["reference_datetime"] = datetime_utc(plugin.tasks.reference, 0);
        Json tasks = Json::array();
        for (std::size_t t = 0; t < plugin.tasks.tasks.size(); ++t) {
            const model::Task& task = plugin.tasks.tasks[t];
            std::uint64_t captures = 0;
            std::uint64_t problems = 0;
            for (std::size_t s = 0; s < schedule.sources().size(); ++s) {
                if (schedule.sources()[s].plugin != p) continue;
                const std::uint64_t n = schedule.count(s, t);
                captures += n;
                problems += n * problems_per_capture(schedule.sources()[s]);
            }
            tasks.push_back(
                Json{{"index", t},
                     {"name", task.name},
                     {"start_s", task.start_s},
                     {"stop_s", task.stop_s},
                     {"start_datetime_utc", datetime_utc(plugin.tasks.reference, task.start_s)},
                     {"stop_datetime_utc", datetime_utc(plugin.tasks.reference, task.stop_s)},
                     {"capture_count", captures},
                     {"problem_count", problems}});
        }
        j["tasks"] = std::move(tasks);
        Json focal_planes = Json::array();
        for (std::size_t s = 0; s < schedule.sources().size(); ++s) {
            const schedule::ClockedFocalPlane& source = schedule.sources()[s];
            if (source.plugin != p) continue;
            std::uint64_t captures = 0;
            for (std::size_t t = 0; t < plugin.tasks.tasks.size(); ++t)
                captures += schedule.count(s, t);
            focal_planes.push_back(
                Json{{"instrument_index", source.instrument_index},
                     {"instrument", source.instrument ? source.instrument->name : ""},
                     {"focal_plane_index", source.focal_plane_index},
                     {"focal_plane",
                      source.focal_plane ? Json(source.focal_plane->name) : Json(nullptr)},
                     {"x_count", source.x_count},
                     {"y_count", source.y_count},
                     {"problems_per_capture", problems_per_capture(source)},
                     {"capture_count", captures}});
        }
        j["focal_planes"] = std::move(focal_planes);
        plugins.push_back(std::move(j));
    }
    return plugins;
}

}  // namespace glint::app_schedule::internal
