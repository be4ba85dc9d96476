// SPDX-License-Identifier: Apache-2.0
// The data recorders of a render (render_parts.h): planned with the images (their files
// BASENAME.csv and BASENAME.jsonl in their platform's output folder, with its prefix; their
// clocks checked and their samples counted, so a bad clock fails before anything is written)
// and written before the first capture, sample by sample, each file published whole. A --schedule
// run (a selection or a shard) writes none, with one warning per recorder: every shard would write
// the same files.
#include <set>

#include "glint/core/atomic_file.h"
#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/schedule/clock_ticks.h"
#include "glint/sensor/telemetry.h"
#include "render_parts.h"

namespace glint::render::detail {
namespace {

/// The most samples one data recorder writes in a run: a 1 kHz INS for 2.8 hours (about
/// 3.5 GB of CSV and as much JSON). More is a clock rate or task window typed wrong.
constexpr std::uint64_t kMaxRecorderSamples = 10'000'000;

/// Calls `sample(task, time_s)` at every tick of the recorder's clock in every task window.
template <class Sample>
void for_each_tick(const model::Instrument& recorder, const schedule::PluginSchedule& plugin,
                   Sample&& sample) {
    const model::Clock* clock = sensor::recorder_clock(recorder);
    if (clock == nullptr) return;
    for (std::size_t t = 0; t < plugin.tasks.tasks.size(); ++t) {
        const schedule::ClockTicks ticks(*clock, plugin.platform->clock_table,
                                         clock->trigger_times_s, plugin.tasks.tasks[t].start_s,
                                         plugin.tasks.tasks[t].stop_s);
        if (!sample(t, ticks)) return;
    }
}

}  // namespace

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
            // The ticks are counted, not listed: a clock of 10^9 Hz is refused here, before any
            // file of the run is written.
            for_each_tick(instrument, plugin, [&](std::size_t, const schedule::ClockTicks& ticks) {
                t.samples += ticks.size();
                return t.samples <= kMaxRecorderSamples;
            });
            if (t.samples > kMaxRecorderSamples) {
                throw input_error("data recorder " + quote(instrument.name) +
                                      " would record more than " +
                                      std::to_string(kMaxRecorderSamples) +
                                      " samples (its clock's ticks in the task windows); glint "
                                      "writes at most that many per recorder (a 1 kHz INS for "
                                      "2.8 hours): check the clock's <rate> and the tasks",
                                  instrument.recorder.where);
            }
            planned.push_back(std::move(t));
        }
    }
    return planned;
}

void write_telemetry(const RenderPlan& plan, const RenderOptions& options, const Context& context) {
    const RenderInputs& in = plan.inputs;
    for (const PlannedTelemetry& t : plan.telemetry) {
        const schedule::PluginSchedule& plugin = in.schedule->plugins()[t.plugin];
        sensor::TelemetryHeader header;
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
        // Written as the samples are made (memory does not grow with them), each file
        // published whole when its last sample is in.
        AtomicFile csv(t.csv);
        AtomicFile jsonl(t.jsonl);
        csv.write(sensor::telemetry_csv_head(header));
        jsonl.write(sensor::telemetry_jsonl_head(header));
        std::uint64_t index = 0;
        for_each_tick(
            *t.recorder, plugin, [&](std::size_t task, const schedule::ClockTicks& ticks) {
                for (std::uint64_t i = 0; i < ticks.size(); ++i, ++index) {
                    if (index % 4096 == 0) context.cancel.throw_if_cancelled();
                    const sensor::TelemetryRecord r = sensor::record_sample(
                        *plugin.poses, t.instrument, task, ticks.time_s(i), index, in.frame,
                        t.recorder->recorder.noise, options.schedule.seed, plugin.plugin_index);
                    csv.write(sensor::telemetry_csv_row(header, r));
                    jsonl.write(sensor::telemetry_jsonl_row(header, r));
                }
                return true;
            });
        csv.commit();
        jsonl.commit();
        context.log.info("Data recorder " + t.recorder->name + ": " + std::to_string(index) +
                         " samples in " + t.csv.string() + " and " + t.jsonl.string());
    }
}

}  // namespace glint::render::detail
