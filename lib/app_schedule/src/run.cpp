// SPDX-License-Identifier: Apache-2.0
// glint-schedule's entry point: load the simulation (every problem reported), check the
// options against it, then either summarise the selection or stream the selected captures
// through the writers into the outputs, which are committed only when everything worked.
#include <span>

#include "glint/app_schedule/schedule_tool.h"
#include "glint/core/error.h"
#include "glint/core/stdio_name.h"
#include "glint/inputs/load.h"
#include "output.h"
#include "writers.h"

namespace glint::app_schedule {
namespace {

namespace fs = std::filesystem;
using internal::CaptureRecord;
using internal::OutputTarget;

/// Loads the schedule; logs every diagnostic. Nullopt (after logging) when the inputs have
/// errors.
std::optional<schedule::Schedule> load(const Options& options, Context& ctx) {
    Diagnostics diagnostics;
    schedule::ScheduleOptions schedule_options = options.schedule;
    schedule_options.seed = ctx.seed;
    try {
        inputs::LoadOptions load_options;
        load_options.read = options.read_options;
        load_options.atmosphere = false;      // the schedule needs no radiometry
        load_options.scene_contents = false;  // only the origin (and any tracked instance)
        const model::SimulationInputs loaded_inputs =
            inputs::load(options.input, load_options, ctx.log, diagnostics);
        schedule::Schedule loaded =
            schedule::Schedule::build(loaded_inputs, schedule_options, ctx.log, diagnostics);
        diagnostics.log_to(ctx.log);
        return loaded;
    } catch (const Error& e) {
        if (e.category() != ErrorCategory::input) throw;
        if (!diagnostics.has_errors()) diagnostics.add(e);
        diagnostics.log_to(ctx.log);
        ctx.log.error(nothing_written_message(diagnostics.error_count()));
        return std::nullopt;
    }
}

void check_options(const Options& options) {
    if (options.input.empty()) throw usage_error("no simulation given: glint-schedule SIM.jsim");
    refuse_stdio_name(options.input, StdioRole::input, "the simulation of glint-schedule",
                      kSimulationNeedsFile);
    if (options.summary && !options.log_info_file.empty()) {
        throw usage_error("--log_info_filename cannot be combined with --summary");
    }
    if (options.summary && options.format == OutputFormat::capture_list) {
        throw usage_error("--summary is written as text or json, not capture_list");
    }
    if (!options.log_info_file.empty()) {
        if (internal::is_stdout(options.log_info_file)) {
            throw usage_error("--log_info_filename needs a file name (stdout is -o's)");
        }
        if (!internal::is_stdout(options.output) &&
            fs::absolute(options.output).lexically_normal() ==
                fs::absolute(options.log_info_file).lexically_normal()) {
            throw usage_error("-o and --log_info_filename name the same file " + options.output);
        }
    }
}

/// Refuses outputs that name the simulation, a platform or a tasks file.
void refuse_overwrite(const Options& options, const schedule::Schedule& schedule) {
    std::vector<fs::path> inputs{options.input};
    for (const schedule::PluginSchedule& plugin : schedule.plugins()) {
        if (plugin.platform) inputs.emplace_back(plugin.platform->file);
        inputs.emplace_back(plugin.tasks.file);
    }
    for (const std::string& output : {options.output, options.log_info_file}) {
        if (!internal::is_stdout(output)) {
            ensure_not_an_input(output, std::span<const fs::path>(inputs));
        }
    }
}

/// Streams the selected captures into `writers`; returns the totals written.
internal::WrittenTotals stream_captures(const schedule::Schedule& schedule,
                                        const Selection& selection,
                                        std::span<internal::CaptureWriter* const> writers,
                                        Context& ctx) {
    const auto& sources = schedule.sources();
    const auto& plugins = schedule.plugins();
    // Event numbers: captures of a plugin's task, all sources together, 1-based.
    std::vector<std::vector<std::uint64_t>> events(plugins.size());
    std::vector<std::vector<std::uint64_t>> event_counts(plugins.size());
    for (std::size_t p = 0; p < plugins.size(); ++p) {
        events[p].assign(plugins[p].tasks.tasks.size(), 0);
        event_counts[p].assign(plugins[p].tasks.tasks.size(), 0);
    }
    for (std::size_t s = 0; s < sources.size(); ++s) {
        for (std::size_t t = 0; t < event_counts[sources[s].plugin].size(); ++t) {
            event_counts[sources[s].plugin][t] += schedule.count(s, t);
        }
    }
    std::optional<ShardSplitter> splitter;
    const std::optional<ShardSpec>& shard_spec = selection.filters().shard;
    if (shard_spec && !shard_spec->by_rows) {
        splitter.emplace(selection_totals(schedule, selection, ctx.cancel),
                         selection.filters().shard->count);
    }
    const std::uint64_t total = schedule.total_captures();
    internal::WrittenTotals written;
    schedule::Schedule::Generator generator = schedule.captures();
    while (const std::optional<schedule::Capture> capture = generator.next()) {
        if ((capture->index & 0x3FF) == 0) {
            ctx.cancel.throw_if_cancelled();
            ctx.progress.update("captures", capture->index, total);
        }
        const schedule::ClockedFocalPlane& source = sources[capture->source];
        const std::uint64_t event = ++events[source.plugin][capture->task_index];
        if (selection.matches(*capture)) {
            const std::uint64_t shard =
                splitter ? splitter->shard_of(problems_per_capture(source)) : 0;
            if (splitter && shard > selection.filters().shard->index) break;  // contiguous
            if (!splitter || shard == selection.filters().shard->index) {
                CaptureRecord record;
                record.capture = *capture;
                record.source = &source;
                record.plugin = &plugins[source.plugin];
                record.event_number = event;
                record.event_count = event_counts[source.plugin][capture->task_index];
                record.problems = selected_problems(source, shard_spec);
                record.rows = shard_rows(source, shard_spec);
                record.image = schedule.image_file(*capture);
                record.truth = schedule.truth_files(*capture);
                for (internal::CaptureWriter* writer : writers) writer->capture(record);
                ++written.captures;
                written.problems += record.problems;
            }
        }
        if (selection.exhausted(*capture)) break;
    }
    ctx.progress.finish("captures", total);
    return written;
}

}  // namespace

std::optional<OutputFormat> parse_output_format(const std::string& text) {
    if (text == "json") return OutputFormat::json;
    if (text == "text") return OutputFormat::text;
    if (text == "capture_list" || text == "capture-list") return OutputFormat::capture_list;
    return std::nullopt;
}

namespace internal {

OutputTarget::OutputTarget(const std::string& target, std::ostream& out)
    : m_out(out), m_name(target) {
    if (is_stdout(target)) return;
    m_file = std::make_unique<AtomicFile>(target);
    m_buf = std::make_unique<AtomicFileBuf>(*m_file);
    m_file_stream = std::make_unique<std::ostream>(m_buf.get());
    m_file_stream->exceptions(std::ios::badbit);  // rethrow the AtomicFile's glint::Error
}

void OutputTarget::commit() {
    if (!m_file) {
        m_out.flush();
        if (!m_out) throw io_error("cannot write to standard output");
        return;
    }
    m_file_stream->flush();
    if (!*m_file_stream) throw io_error("cannot write the output", m_name);
    m_file->commit();
}

}  // namespace internal

int run(const Options& options, Context& ctx, std::ostream& out) {
    check_options(options);
    const std::optional<schedule::Schedule> schedule = load(options, ctx);
    if (!schedule) return 1;
    refuse_overwrite(options, *schedule);
    const Selection selection(*schedule, options.filters);
    const internal::RunInfo info{&*schedule, &options, ctx.seed, &ctx.arguments};

    OutputTarget main_output(options.output, out);
    if (options.summary) {
        internal::write_summary(info, selection, ctx, main_output.stream());
        main_output.commit();
        return 0;
    }
    std::vector<std::unique_ptr<internal::CaptureWriter>> owned;
    std::optional<OutputTarget> log_info;
    owned.push_back(internal::make_writer(options.format, info, main_output.stream()));
    if (!options.log_info_file.empty()) {
        log_info.emplace(options.log_info_file, out);
        owned.push_back(
            internal::make_writer(OutputFormat::capture_list, info, log_info->stream()));
    }
    std::vector<internal::CaptureWriter*> writers;
    for (const auto& writer : owned) writers.push_back(writer.get());
    for (internal::CaptureWriter* writer : writers) writer->begin();
    const internal::WrittenTotals totals = stream_captures(*schedule, selection, writers, ctx);
    for (internal::CaptureWriter* writer : writers) writer->end(totals);
    if (log_info) log_info->commit();
    main_output.commit();
    ctx.log.info(std::to_string(totals.captures) + " captures, " + std::to_string(totals.problems) +
                 " problems written");
    return 0;
}

}  // namespace glint::app_schedule
