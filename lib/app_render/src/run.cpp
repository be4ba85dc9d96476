// SPDX-License-Identifier: Apache-2.0
// glint-render: option parsing helpers, the dry-run plan and the render report.
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <ostream>
#include <string>
#include <utility>

#include "glint/app_render/render_tool.h"
#include "glint/core/error.h"
#include "glint/core/install_paths.h"
#include "glint/core/runner.h"
#include "glint/core/stdio_name.h"
#include "glint/core/text.h"
#include "glint/inputs/data_tables.h"
#include "glint/inputs/load.h"
#include "glint/inputs/schedule_file.h"
#include "glint/model/names.h"
#include "glint/model/output_folder.h"

namespace glint::app_render {
namespace {

double parse_number(const std::string& text, const std::string& what) {
    const std::optional<double> value = parse_double(text);
    if (!value) throw usage_error(what + ": expected a number, got \"" + text + "\"");
    return *value;
}

std::string mebibytes(std::uint64_t bytes) {
    return format_shortest(static_cast<double>(bytes) / (1024.0 * 1024.0)) + " MiB";
}

/// Runs the processing tasks at the render's events.
class ProcessingObserver final : public render::RenderObserver {
public:
    explicit ProcessingObserver(process::ProcessingRunner& runner) : m_runner(runner) {}
    void on_plan(const std::vector<model::ProcessingEvent>& events) override {
        m_runner.check(events);
    }
    void on_event(const model::ProcessingEvent& event) override { m_runner.run(event); }

private:
    process::ProcessingRunner& m_runner;
};

/// The folders the run writes into, each once, in plugin order; a warning for each the
/// simulation chose outside both its own folder and the working folder.
std::vector<std::filesystem::path> output_folders(const model::SimulationInputs& loaded,
                                                  const render::RenderOptions& settings,
                                                  const Context& ctx) {
    std::error_code ec;
    const std::filesystem::path working = std::filesystem::current_path(ec);
    std::vector<std::filesystem::path> folders;
    if (ec) return folders;
    for (const model::OutputFolder& output :
         model::output_folders(loaded.simulation, settings.schedule.output_folder, working)) {
        if (std::find(folders.begin(), folders.end(), output.folder) != folders.end()) continue;
        folders.push_back(output.folder);
        if (auto why = model::unexpected_output_folder(output, loaded.simulation, working)) {
            ctx.log.warning(format_located(output.where, *why));
        }
    }
    return folders;
}

/// The number of tasks the events run.
std::size_t task_count(const std::vector<model::ProcessingEvent>& events) {
    std::size_t n = 0;
    for (const model::ProcessingEvent& e : events) n += e.tasks.size();
    return n;
}

/// --dry-run: each event with the commands its tasks would run.
void print_events(const std::vector<model::ProcessingEvent>& events,
                  process::ProcessingRunner& runner, std::ostream& out) {
    for (const model::ProcessingEvent& e : events) {
        for (const model::ProcessingTask& task : e.tasks) {
            out << "processing: " << model::name_of(e.kind) << " " << e.focal_plane << " task "
                << e.task + 1 << " capture " << e.capture + 1 << ": ";
            try {
                const process::TaskCommand command = runner.command(task, e);
                out << format_command_line(command.argv);
                if (command.refusal) out << " (refused: not allowed)";
            } catch (const Error& error) {
                out << "(" << terminal_safe_line(error.message()) << ")";
            }
            if (task.remove_file) out << " (then removes " << e.file.filename().string() << ")";
            out << "\n";
        }
    }
}

}  // namespace

radiometry::Convergence parse_convergence(const std::string& text) {
    std::vector<std::string> parts;
    std::string part;
    for (char c : text + ",") {
        if (c == ',') {
            parts.push_back(part);
            part.clear();
        } else {
            part += c;
        }
    }
    if (parts.size() != 3) {
        throw usage_error("--convergence: expected MIN,MAX,THRESHOLD, got \"" + text + "\"");
    }
    const double min = parse_number(parts[0], "--convergence minimum");
    const double max = parse_number(parts[1], "--convergence maximum");
    const double threshold = parse_number(parts[2], "--convergence threshold");
    if (min < 1 || max < min || min != std::floor(min) || max != std::floor(max) || max > 1e12) {
        throw usage_error("--convergence: expected whole numbers 1 <= MIN <= MAX, got \"" + text +
                          "\"");
    }
    if (threshold < 0) throw usage_error("--convergence: the threshold must be >= 0");
    return {static_cast<std::uint64_t>(min), static_cast<std::uint64_t>(max), threshold};
}

std::filesystem::path default_data_dir() {
    DataDirCandidates candidates;
    if (const char* dir = std::getenv("GLINT_DATA_DIR"); dir != nullptr) {
        candidates.environment = dir;
    }
    candidates.executable = executable_path();
    candidates.built_in = GLINT_SOURCE_DATA_DIR;
    return data_dir_lookup(candidates);
}

int run(const Options& options, Context& ctx, std::ostream& out) {
    refuse_stdio_name(options.input, StdioRole::input, "the simulation of glint-render",
                      kSimulationNeedsFile);
    render::RenderOptions settings = options.render;
    settings.schedule.seed = ctx.seed;
    settings.version = version();
    settings.radiance_only = options.radiance_only;
    if (settings.data_dir.empty()) settings.data_dir = default_data_dir();
    ctx.log.info("Data folder: " + settings.data_dir.string());
    if (!options.schedule_file.empty()) {
        const inputs::ScheduleFile selection = inputs::read_schedule_file(options.schedule_file);
        for (const inputs::ScheduleFile::Capture& c : selection.captures) {
            settings.only_captures.insert(c.index);
        }
        if (selection.row_shard) {
            if (settings.rows) {
                throw usage_error("--rows and a --by rows shard in --schedule " +
                                  options.schedule_file.string() + ": give one band of lines");
            }
            settings.rows = schedule::RowBand{};
            settings.rows->shard = selection.row_shard;
        }
    }
    inputs::LoadOptions load_options;
    load_options.read = options.read;
    if (!options.atmosphere.empty()) {
        load_options.atmosphere_override = inputs::parse_atmosphere_override(options.atmosphere);
    }
    model::SimulationInputs loaded = inputs::load_logged(options.input, load_options, ctx.log);
    settings.data =
        inputs::read_data_tables(settings.data_dir, atmosphere::needs_gas_table(loaded.atmosphere),
                                 atmosphere::needs_aerosol_table(loaded.atmosphere));
    process::ProcessingOptions processing = options.processing;
    if (processing.tools_dir.empty()) processing.tools_dir = executable_path().parent_path();
    if (processing.allow_list.empty() && !processing.allow_all) {
        processing.allow_list = process::allow_list_from_environment();
    }
    process::ProcessingRunner runner(processing, ctx);
    const std::vector<std::filesystem::path> folders = output_folders(loaded, settings, ctx);
    if (options.dry_run) {
        const render::RenderReport plan = render::dry_run(std::move(loaded), settings, ctx);
        out << "captures: " << plan.captures.size() << "\n";
        out << "pixels: " << plan.pixels << "\n";
        out << "memory estimate: " << mebibytes(plan.memory_estimate_bytes) << "\n";
        for (const auto& folder : folders) {
            out << "output folder: " << terminal_safe_line(folder.string()) << "\n";
        }
        for (const auto& file : plan.files) {
            out << "output: " << terminal_safe_line(file.string()) << "\n";
        }
        if (!options.no_processing) {
            print_events(plan.events, runner, out);
            out.flush();
            // What the run would refuse before tracing, the dry run refuses too.
            runner.check(plan.events);
        }
        return kExitSuccess;
    }
    // A band of lines is part of its images: processing tasks would see parts, so they run on
    // the merged files instead (docs/scale.md).
    const bool run_tasks = !options.no_processing && !settings.rows;
    ProcessingObserver observer(runner);
    const render::RenderReport report =
        render::render(std::move(loaded), settings, ctx, run_tasks ? &observer : nullptr);
    if (!run_tasks && !report.events.empty()) {
        const std::string why =
            options.no_processing
                ? std::string("--no-processing")
                : "--rows " + settings.rows->describe() +
                      " (a band of lines; run them on the files glint-envi merge joins)";
        ctx.log.warning(why + ": " + std::to_string(task_count(report.events)) +
                        " processing task runs at " + std::to_string(report.events.size()) +
                        " events were skipped");
    }
    for (const auto& file : report.files) {
        if (runner.removed().count(file) == 0) out << terminal_safe_line(file.string()) << "\n";
    }
    return kExitSuccess;
}

}  // namespace glint::app_render
