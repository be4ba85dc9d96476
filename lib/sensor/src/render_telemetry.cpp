// SPDX-License-Identifier: Apache-2.0
// The data recorders of a render (render_parts.h): planned with the images (their files
// BASENAME.csv and BASENAME.jsonl in their platform's output folder, with its prefix) and
// written before the first capture. A --schedule run (a selection or a shard) writes none, with
// one warning per recorder: every shard would write the same files.
#include <set>

#include "glint/core/atomic_file.h"
#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/sensor/telemetry.h"
#include "render_parts.h"

namespace glint::sensor::detail {

std::vector<PlannedTelemetry> plan_telemetry(const RenderInputs& inputs,
                                             const RenderOptions& options, const Context& context) {
    std::vector<PlannedTelemetry> planned;
    std::set<std::filesystem::path> names;
    for (std::size_t p = 0; p < inputs.schedule->plugins().size(); ++p) {
        const schedule::PluginSchedule& plugin = inputs.schedule->plugins()[p];
        const motion::PoseService& poses = *plugin.poses;
        for (std::size_t k = 0; k < poses.instrument_count(); ++k) {
            const model::Instrument& instrument = *poses.instrument_path(k).instrument;
            if (instrument.type != model::InstrumentType::data_recorder) continue;
            if (instrument.recorder.basename.empty()) continue;
            if (!options.only_captures.empty() || options.rows) {
                context.log.warning(format_located(
                    instrument.where, "data recorder " + quote(instrument.name) +
                                          " records nothing in a --schedule or --rows run (each "
                                          "shard would write the same files): render without "
                                          "them to record it"));
                continue;
            }
            PlannedTelemetry t;
            t.plugin = p;
            t.instrument = k;
            t.recorder = &instrument;
            const std::string name = plugin.output_prefix + instrument.recorder.basename;
            const std::filesystem::path folder(plugin.output_folder);
            t.csv = folder / (name + ".csv");
            t.jsonl = folder / (name + ".jsonl");
            for (const auto& file : {t.csv, t.jsonl}) {
                if (!names.insert(file.lexically_normal()).second) {
                    throw input_error("data recorder " + quote(instrument.name) + " would write " +
                                          file.string() +
                                          ", which another recorder writes: "
                                          "give one an <output><basename> of its own",
                                      instrument.recorder.where);
                }
            }
            planned.push_back(std::move(t));
        }
    }
    return planned;
}

void write_telemetry(const Prepared& prepared, const RenderOptions& options,
                     const Context& context) {
    const RenderInputs& in = prepared.inputs;
    for (const PlannedTelemetry& t : prepared.telemetry) {
        const schedule::PluginSchedule& plugin = in.schedule->plugins()[t.plugin];
        const auto times = recorder_times_s(*t.recorder, *plugin.platform, plugin.tasks);
        const std::vector<TelemetryRecord> records = record_telemetry(
            *plugin.poses, t.instrument, times, in.frame, t.recorder->recorder.noise,
            options.schedule.seed, plugin.plugin_index);
        TelemetryHeader header;
        header.instrument = t.recorder->name;
        header.platform_file = plugin.platform->file;
        header.plugin_index = plugin.plugin_index;
        header.scene_origin = in.frame.origin();
        header.order = plugin.poses->platform_rotation_order();
        header.reference = plugin.tasks.reference;
        header.noise = t.recorder->recorder.noise;
        header.tool = "glint-render";
        header.version = options.version;
        header.command_line = context.command_line();
        header.seed = options.schedule.seed;
        for (const auto& file : {t.csv, t.jsonl}) {
            if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
        }
        write_file_atomically(t.csv, telemetry_csv(header, records));
        write_file_atomically(t.jsonl, telemetry_jsonl(header, records));
        context.log.info("Data recorder " + t.recorder->name + ": " +
                         std::to_string(records.size()) + " samples in " + t.csv.string() +
                         " and " + t.jsonl.string());
    }
}

}  // namespace glint::sensor::detail
