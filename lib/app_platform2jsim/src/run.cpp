// SPDX-License-Identifier: Apache-2.0
// The modes of glint-platform2jsim: convert a .sim, build a .jsim from parts, append a
// BasicPlatform to a .jsim, check inputs, dump platforms. Each loads everything first
// (inputs.h), reports every problem, and writes only when there is no error.
#include <cctype>
#include <nlohmann/json.hpp>
#include <span>

#include "glint/app_platform2jsim/inputs.h"
#include "glint/app_platform2jsim/platform2jsim.h"
#include "glint/app_platform2jsim/platform_json.h"
#include "glint/core/atomic_file.h"
#include "glint/core/error.h"
#include "glint/core/install_paths.h"
#include "glint/core/json_text.h"
#include "glint/core/stdio_name.h"
#include "glint/core/text.h"
#include "glint/dirsig/readers.h"
#include "glint/model/names.h"
#include "glint/model/output_folder.h"
#include "glint/model/output_name.h"
#include "glint/process/processing_runner.h"

namespace glint::app_platform2jsim {
namespace {

namespace fs = std::filesystem;

constexpr const char* kStdout = "-";

fs::path absolute_normal(const fs::path& path) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(path, ec);
    return (ec ? path : absolute).lexically_normal();
}

/// A FileRef for a path given on the command line by `flag` (relative to the working folder).
model::FileRef command_line_ref(const fs::path& path, const char* flag) {
    model::FileRef ref;
    ref.text = path.string();
    ref.resolved = absolute_normal(path);
    ref.where = ErrorContext{{}, 0, flag};
    return ref;
}

bool to_stdout(const std::string& output) { return output.empty() || output == kStdout; }

/// The folder that paths in a written .jsim are relative to.
fs::path output_folder_of(const std::string& output) {
    if (to_stdout(output)) return absolute_normal(fs::current_path());
    return absolute_normal(output).parent_path();
}

void write_output(const std::string& output, const std::string& text, std::ostream& out) {
    if (to_stdout(output)) {
        out << text;
        out.flush();
        if (!out) throw io_error("cannot write to standard output");
        return;
    }
    write_file_atomically(output, text);
}

/// Refuses an output that names one of the files read.
void refuse_overwrite(const std::string& output, const LoadedInputs& inputs) {
    if (to_stdout(output)) return;
    const std::vector<fs::path> files(inputs.files.begin(), inputs.files.end());
    ensure_not_an_input(output, std::span<const fs::path>(files));
}

/// Logs every diagnostic; true when there was an error (then also says nothing was written).
bool report(const LoadedInputs& inputs, Context& ctx, bool writes) {
    inputs.diagnostics.log_to(ctx.log);
    if (!inputs.diagnostics.has_errors()) return false;
    if (writes) {
        ctx.log.error(nothing_written_message(inputs.diagnostics.error_count()));
    }
    return true;
}

void require_output(const Options& options, const char* mode) {
    if (options.output.empty()) {
        throw usage_error(std::string(mode) +
                          " needs an output: -o FILE.jsim (or -o - for stdout)");
    }
}

void require_parts(const Options& options, const char* mode) {
    for (const auto& [value, flag] :
         {std::pair{&options.platform, "--platform"}, std::pair{&options.motion, "--motion"},
          std::pair{&options.tasks, "--tasks"}}) {
        if (value->empty()) throw usage_error(std::string(mode) + " needs " + flag + " FILE");
    }
}

model::Plugin basic_platform_plugin(const Options& options) {
    model::BasicPlatformInputs in;
    in.platform_file = command_line_ref(options.platform, "--platform");
    in.motion_file = command_line_ref(options.motion, "--motion");
    in.tasks_file = command_line_ref(options.tasks, "--tasks");
    in.output_folder = options.output_folder;
    in.output_prefix = options.output_prefix;
    in.split_channels = options.split_channels;
    model::Plugin plugin;
    plugin.name = "BasicPlatform";
    plugin.basic_platform = std::move(in);
    plugin.where = ErrorContext{{}, 0, "--platform"};
    return plugin;
}

/// "-" names standard input or output; only the .jsim written (-o -) may be it.
void refuse_stdio_names(const Options& o) {
    const auto refuse = [](const fs::path& path, const std::string& what) {
        refuse_stdio_name(path, StdioRole::input, what + " of glint-platform2jsim",
                          kSimulationNeedsFile);
    };
    refuse(o.input, "the input");
    for (const fs::path& file : o.check_files) refuse(file, "a file to check");
    refuse(o.platform, "the --platform file");
    refuse(o.motion, "the --motion file");
    refuse(o.tasks, "the --tasks file");
    if (o.scene) refuse(*o.scene, "the --scene file");
    if (o.atmosphere) refuse(*o.atmosphere, "the --atmosphere file");
    if (o.mode == Mode::append) {
        refuse_stdio_name(o.output, StdioRole::output,
                          "the .jsim that glint-platform2jsim --append rewrites",
                          "append reads the existing file and replaces it");
    }
}

int run_convert(const Options& options, Context& ctx, std::ostream& out) {
    require_output(options, "converting");
    if (!to_stdout(options.output)) {
        const fs::path input = absolute_normal(options.input);
        ensure_not_an_input(options.output, std::span<const fs::path>(&input, 1));
    }
    LoadedInputs inputs;
    load_simulation_file(options.input, inputs, options.read_options);
    for (model::Simulation& simulation : inputs.simulations) {
        for (model::Plugin& plugin : simulation.plugins) {
            if (!plugin.basic_platform) continue;
            if (options.output_folder) plugin.basic_platform->output_folder = options.output_folder;
            if (options.output_prefix) plugin.basic_platform->output_prefix = options.output_prefix;
            if (options.split_channels) plugin.basic_platform->split_channels = true;
        }
    }
    if (inputs.simulations.empty() && !inputs.diagnostics.has_errors()) {
        inputs.diagnostics.error(ErrorContext{options.input.string(), 0, {}},
                                 "no simulation to convert");
    }
    load_references(inputs, options.read_options, LoadDepth::everything);
    if (report(inputs, ctx, true)) return 1;
    refuse_overwrite(options.output, inputs);
    write_output(options.output,
                 dirsig::format_jsim(inputs.simulations, output_folder_of(options.output)), out);
    return 0;
}

int run_parts(const Options& options, Context& ctx, std::ostream& out) {
    require_output(options, "building a .jsim");
    require_parts(options, "building a .jsim");
    LoadedInputs inputs;
    model::Simulation simulation;
    simulation.file = options.output;
    if (options.scene) {
        simulation.scenes.push_back(
            model::SceneEntry{command_line_ref(*options.scene, "--scene"), {}, {}});
    }
    if (options.atmosphere) {
        model::Plugin plugin;
        plugin.name = "BasicAtmosphere";
        plugin.basic_atmosphere =
            model::BasicAtmosphereInputs{command_line_ref(*options.atmosphere, "--atmosphere")};
        plugin.where = ErrorContext{{}, 0, "--atmosphere"};
        simulation.plugins.push_back(std::move(plugin));
    }
    simulation.plugins.push_back(basic_platform_plugin(options));
    inputs.simulations.push_back(std::move(simulation));
    load_references(inputs, options.read_options, LoadDepth::everything);
    if (report(inputs, ctx, true)) return 1;
    refuse_overwrite(options.output, inputs);
    write_output(options.output,
                 dirsig::format_jsim(inputs.simulations, output_folder_of(options.output)), out);
    return 0;
}

int run_append(const Options& options, Context& ctx, std::ostream& /*out*/) {
    if (options.output.empty() || options.output == kStdout) {
        throw usage_error("--append needs -o naming the existing .jsim to add to");
    }
    require_parts(options, "--append");
    if (options.scene || options.atmosphere) {
        throw usage_error(
            "--append adds a BasicPlatform only; --scene and --atmosphere "
            "cannot be given with it");
    }
    const fs::path jsim = options.output;
    std::error_code ec;
    if (!fs::is_regular_file(jsim, ec)) {
        throw input_error("--append: no .jsim to add to: " + jsim.string() +
                          " does not exist (build one first without --append)");
    }
    LoadedInputs inputs;
    inputs.files.insert(absolute_normal(jsim));
    inputs.simulations = dirsig::read_jsim(jsim, options.read_options, inputs.diagnostics);
    if (!inputs.diagnostics.has_errors() && inputs.simulations.size() != 1) {
        inputs.diagnostics.error(ErrorContext{jsim.string(), 0, {}},
                                 "--append needs a .jsim holding one simulation, found " +
                                     std::to_string(inputs.simulations.size()));
    }
    if (inputs.diagnostics.has_errors()) {
        report(inputs, ctx, true);
        return 1;
    }
    model::Simulation& simulation = inputs.simulations.front();
    model::Plugin plugin = basic_platform_plugin(options);
    const model::BasicPlatformInputs& added = *plugin.basic_platform;
    for (std::size_t index : simulation.basic_platform_indices()) {
        const model::BasicPlatformInputs& existing = *simulation.plugins[index].basic_platform;
        if (existing.output_folder.value_or("") == added.output_folder.value_or("") &&
            existing.output_prefix.value_or("") == added.output_prefix.value_or("")) {
            inputs.diagnostics.error(ErrorContext{{}, 0, "--output-prefix"},
                                     "plugin_list[" + std::to_string(index) + "] of " +
                                         jsim.string() + " already writes with " +
                                         describe_output_name(added) +
                                         "; give the new entry a distinct --output-prefix");
        }
    }
    load_basic_platform(added, inputs, options.read_options, LoadDepth::everything);
    if (report(inputs, ctx, true)) return 1;
    // The .jsim itself is rewritten on purpose; no other input may be.
    std::vector<fs::path> others;
    for (const fs::path& file : inputs.files) {
        if (file != absolute_normal(jsim)) others.push_back(file);
    }
    ensure_not_an_input(jsim, std::span<const fs::path>(others));
    simulation.plugins.push_back(std::move(plugin));
    write_file_atomically(jsim, dirsig::format_jsim(inputs.simulations, output_folder_of(jsim)));
    return 0;
}

/// A line for every processing task of the platforms read — the command a run would start,
/// $$IMG_BASENAME$$ in place — and an error for each that glint-render would refuse (a
/// program found nowhere, one the user has not allowed).
void list_processing(LoadedInputs& inputs, const Options& options, const Context& ctx) {
    process::ProcessingOptions processing;
    processing.tools_dir = executable_path().parent_path();
    processing.allow_all = options.allow_processing;
    if (!processing.allow_all) processing.allow_list = process::allow_list_from_environment();
    process::ProcessingRunner runner(processing, ctx);
    for (const auto& [file, platform] : inputs.platforms) {
        for (const model::InstrumentPath& path : model::list_instruments(platform)) {
            for (const model::FocalPlane& fp : path.instrument->focal_planes) {
                for (const model::ProcessingTask& task : fp.capture_method.processing) {
                    std::string line = "processing: " + std::string(model::name_of(task.schedule)) +
                                       " " + path.instrument->name + " -> " + fp.name + ": ";
                    try {
                        const process::TaskCommand command = runner.command_template(task);
                        line += format_command_line(command.argv);
                        if (command.refusal) {
                            line += " (refused: not allowed)";
                            inputs.diagnostics.error(task.where, *command.refusal);
                        }
                    } catch (const Error& error) {
                        line += "(" + terminal_safe_line(error.message()) + ")";
                        inputs.diagnostics.add(error);
                    }
                    inputs.contents.push_back(line + " (" + task.where.file + ":" +
                                              std::to_string(task.where.line) + ")");
                }
            }
        }
    }
}

/// A line for the output folder of every BasicPlatform of the simulations read that names
/// its own (the others write where glint-render's --output-folder says, else into the
/// working folder), and a warning where one lies outside both the simulation's folder and
/// the working folder.
void list_output_folders(LoadedInputs& inputs) {
    std::error_code ec;
    const fs::path working = fs::current_path(ec);
    if (ec) return;
    for (const model::Simulation& simulation : inputs.simulations) {
        for (const model::OutputFolder& output :
             model::output_folders(simulation, std::nullopt, working)) {
            if (!output.from_simulation) continue;
            inputs.contents.push_back("output folder " + output.folder.string() + ": plugin_list[" +
                                      std::to_string(output.plugin_index) + "] of " +
                                      simulation.file);
            if (auto why = model::unexpected_output_folder(output, simulation, working)) {
                inputs.diagnostics.warning(output.where, *why);
            }
        }
    }
}

int run_check(const Options& options, Context& ctx, std::ostream& out) {
    if (options.check_files.empty()) throw usage_error("--check needs at least one FILE");
    LoadedInputs inputs;
    for (const fs::path& file : options.check_files) {
        check_file(file, inputs, options.read_options, ctx.log);
    }
    check_truth_targets(inputs);
    list_output_folders(inputs);
    list_processing(inputs, options, ctx);
    report(inputs, ctx, false);
    for (const std::string& line : inputs.contents) out << terminal_safe_line(line) << '\n';
    out << "check: "
        << summary_text(inputs.diagnostics.error_count(), inputs.diagnostics.warning_count(),
                        inputs.files.size())
        << '\n';
    out.flush();
    return inputs.diagnostics.has_errors() ? 1 : 0;
}

bool is_platform_file(const fs::path& file) {
    std::string extension = file.extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension == ".platform";
}

int run_dump(const Options& options, Context& ctx, std::ostream& out) {
    LoadedInputs inputs;
    std::string text;
    if (is_platform_file(options.input)) {
        const model::Platform* platform =
            load_platform_file(options.input, inputs, options.read_options, false);
        if (report(inputs, ctx, true)) return 1;
        text = app_platform2jsim::platform_to_json(*platform) + "\n";
    } else {
        load_simulation_file(options.input, inputs, options.read_options);
        load_references(inputs, options.read_options, LoadDepth::platforms);
        if (report(inputs, ctx, true)) return 1;
        nlohmann::ordered_json all = nlohmann::ordered_json::array();
        for (const model::Simulation& simulation : inputs.simulations) {
            for (std::size_t index : simulation.basic_platform_indices()) {
                const model::Platform* platform =
                    inputs.platform_of(*simulation.plugins[index].basic_platform);
                if (platform == nullptr) continue;
                all.push_back(
                    nlohmann::ordered_json::parse(app_platform2jsim::platform_to_json(*platform)));
            }
        }
        text = json_text(all, 2) + "\n";
    }
    refuse_overwrite(options.output, inputs);
    write_output(options.output, text, out);
    return 0;
}

}  // namespace

int run(const Options& options, Context& ctx, std::ostream& out) {
    refuse_stdio_names(options);
    if (options.output_prefix) {
        if (const auto problem = model::output_name_problem(*options.output_prefix)) {
            throw usage_error("--output_prefix " + quote(*options.output_prefix) + " " + *problem);
        }
    }
    switch (options.mode) {
        case Mode::convert:
            if (options.input.empty()) throw usage_error("no input: give a .sim or .jsim file");
            return run_convert(options, ctx, out);
        case Mode::parts:
            return run_parts(options, ctx, out);
        case Mode::append:
            return run_append(options, ctx, out);
        case Mode::check:
            return run_check(options, ctx, out);
        case Mode::dump_platform:
            if (options.input.empty()) throw usage_error("--dump-platform needs a FILE");
            return run_dump(options, ctx, out);
    }
    throw internal_error("unknown mode");
}

}  // namespace glint::app_platform2jsim
