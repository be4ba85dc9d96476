// SPDX-License-Identifier: Apache-2.0
// inputs::load (glint/inputs/load.h): the simulation, its scene and atmosphere, and each
// BasicPlatform's platform, motion and tasks files with the PSD and trigger files they name.
#include "glint/inputs/load.h"

#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "glint/core/error.h"
#include "glint/dirsig/motion_reader.h"
#include "glint/dirsig/psd_reader.h"
#include "glint/dirsig/pulse_shape.h"
#include "glint/dirsig/readers.h"
#include "glint/dirsig/trigger_file.h"
#include "glint/inputs/scene_atmosphere.h"
#include "glint/inputs/weather.h"

namespace glint::inputs {
namespace {

/// The file a BasicPlatform input names, or an error at the entry naming the key.
const model::FileRef* required_file(const model::FileRef& ref, const char* key,
                                    const model::Plugin& plugin, Diagnostics& diagnostics) {
    if (ref.resolved.empty()) {
        diagnostics.error(plugin.where, std::string("BasicPlatform has no ") + key);
        return nullptr;
    }
    return &ref;
}

/// The table of a PSD file reference (nullopt when it names none or cannot be used).
std::optional<model::PsdTable> read_psd(const model::FileRef& file, const ReadOptions& options,
                                        Diagnostics& diagnostics) {
    if (file.empty()) return std::nullopt;
    const std::filesystem::path path =
        file.resolved.empty() ? std::filesystem::path(file.text) : file.resolved;
    return dirsig::read_psd_file(path, options, diagnostics, file.text);
}

void read_mount_psd(std::vector<model::Attachment>& attachments, const ReadOptions& options,
                    Diagnostics& diagnostics) {
    for (model::Attachment& attachment : attachments) {
        for (model::Mount& mount : attachment.mounts) {
            for (model::JitterSpec& axis : mount.deviates.axes) {
                if (axis.kind == model::JitterSpec::Kind::psd && !axis.psd) {
                    axis.psd = read_psd(axis.psd_file, options, diagnostics);
                }
            }
            read_mount_psd(mount.attachments, options, diagnostics);
        }
    }
}

void read_jitter_psd(model::PlatformJitter& jitter, const ReadOptions& options,
                     Diagnostics& diagnostics) {
    for (auto* axes : {&jitter.location_m, &jitter.orientation_rad}) {
        for (model::JitterSpec& spec : *axes) {
            if (spec.kind == model::JitterSpec::Kind::psd && !spec.psd) {
                spec.psd = read_psd(spec.psd_file, options, diagnostics);
            }
        }
    }
}

void read_clock_triggers(std::vector<model::Attachment>& attachments, const ReadOptions& options,
                         Diagnostics& diagnostics) {
    for (model::Attachment& attachment : attachments) {
        for (model::Instrument& instrument : attachment.instruments) {
            for (model::FocalPlane& plane : instrument.focal_planes) {
                model::Clock& clock = plane.detector_array.clock;
                if (!plane.enabled || clock.type != model::ClockType::external_trigger ||
                    clock.trigger_file.resolved.empty()) {
                    continue;
                }
                clock.trigger_times_s =
                    dirsig::read_trigger_file(clock.trigger_file.resolved, options, diagnostics);
            }
            // A lidar's tabulated pulse shape is read with the trigger files.
            if (instrument.transmitter && !instrument.transmitter->pulse_shape_file.empty() &&
                !instrument.transmitter->pulse_shape_file.resolved.empty()) {
                model::Transmitter& t = *instrument.transmitter;
                t.pulse_shape = dirsig::read_pulse_shape_file(t.pulse_shape_file.resolved, options,
                                                              diagnostics);
            }
        }
        for (model::Mount& mount : attachment.mounts) {
            read_clock_triggers(mount.attachments, options, diagnostics);
        }
    }
}

}  // namespace

void read_psd_tables(model::Platform& platform, const ReadOptions& options,
                     Diagnostics& diagnostics) {
    read_mount_psd(platform.attachments, options, diagnostics);
}

void read_psd_tables(model::PlatformMotion& motion, const ReadOptions& options,
                     Diagnostics& diagnostics) {
    if (motion.generic) read_jitter_psd(motion.generic->jitter, options, diagnostics);
    if (motion.flexible) read_jitter_psd(motion.flexible->jitter, options, diagnostics);
}

void read_trigger_files(model::Platform& platform, const ReadOptions& options,
                        Diagnostics& diagnostics) {
    read_clock_triggers(platform.attachments, options, diagnostics);
}

namespace {

/// The files of one load already parsed (with their PSD and trigger files), by path: an entry
/// naming a file another entry named shares its model, and its problems are reported once.
struct ParsedFiles {
    std::map<std::filesystem::path, std::shared_ptr<const model::Platform>> platforms;
    std::map<std::filesystem::path, model::PlatformMotion> motions;
    std::map<std::filesystem::path, model::TaskList> task_lists;
};

std::shared_ptr<const model::Platform> parsed_platform(const std::filesystem::path& file,
                                                       const ReadOptions& options,
                                                       ParsedFiles& parsed,
                                                       Diagnostics& diagnostics) {
    auto& slot = parsed.platforms[file];
    if (!slot) {
        auto platform =
            std::make_shared<model::Platform>(dirsig::read_platform(file, options, diagnostics));
        read_psd_tables(*platform, options, diagnostics);
        read_trigger_files(*platform, options, diagnostics);
        read_weight_images(*platform, diagnostics);
        slot = std::move(platform);
    }
    return slot;
}

const model::PlatformMotion& parsed_motion(const std::filesystem::path& file,
                                           const ReadOptions& options, ParsedFiles& parsed,
                                           Diagnostics& diagnostics) {
    if (const auto found = parsed.motions.find(file); found != parsed.motions.end()) {
        return found->second;
    }
    model::PlatformMotion motion = dirsig::read_motion(file, options, diagnostics);
    read_psd_tables(motion, options, diagnostics);
    return parsed.motions.emplace(file, std::move(motion)).first->second;
}

const model::TaskList& parsed_tasks(const std::filesystem::path& file, const ReadOptions& options,
                                    ParsedFiles& parsed, Diagnostics& diagnostics) {
    if (const auto found = parsed.task_lists.find(file); found != parsed.task_lists.end()) {
        return found->second;
    }
    return parsed.task_lists.emplace(file, dirsig::read_tasks(file, options, diagnostics))
        .first->second;
}

std::optional<model::PlatformInputs> read_entry(const model::Simulation& simulation,
                                                std::size_t plugin_index,
                                                const ReadOptions& options, ParsedFiles& parsed,
                                                Diagnostics& diagnostics) {
    if (plugin_index >= simulation.plugins.size()) {
        throw usage_error("plugin index " + std::to_string(plugin_index) + " out of range (" +
                          simulation.file + " has " + std::to_string(simulation.plugins.size()) +
                          " plugins)");
    }
    const model::Plugin& plugin = simulation.plugins[plugin_index];
    if (!plugin.basic_platform) {
        throw usage_error("plugin_list[" + std::to_string(plugin_index) + "] of " +
                          simulation.file + " is " + plugin.name + ", expected a BasicPlatform");
    }
    const model::BasicPlatformInputs& files = *plugin.basic_platform;
    const model::FileRef* platform_file =
        required_file(files.platform_file, "platform_filename", plugin, diagnostics);
    const model::FileRef* motion_file =
        required_file(files.motion_file, "motion_filename", plugin, diagnostics);
    const model::FileRef* tasks_file =
        required_file(files.tasks_file, "tasks_filename", plugin, diagnostics);
    if (!platform_file || !motion_file || !tasks_file) return std::nullopt;
    // Each that is missing is said at the entry's key; the rest are still read.
    const bool platform_exists = existing_file(*platform_file, "platform", diagnostics);
    const bool motion_exists = existing_file(*motion_file, "motion", diagnostics);
    const bool tasks_exists = existing_file(*tasks_file, "tasks", diagnostics);
    if (!platform_exists || !motion_exists || !tasks_exists) {
        if (platform_exists)
            (void)parsed_platform(platform_file->resolved, options, parsed, diagnostics);
        if (motion_exists) (void)parsed_motion(motion_file->resolved, options, parsed, diagnostics);
        if (tasks_exists) (void)parsed_tasks(tasks_file->resolved, options, parsed, diagnostics);
        return std::nullopt;
    }

    model::PlatformInputs entry;
    entry.plugin_index = plugin_index;
    entry.platform = parsed_platform(platform_file->resolved, options, parsed, diagnostics);
    entry.motion = parsed_motion(motion_file->resolved, options, parsed, diagnostics);
    entry.tasks = parsed_tasks(tasks_file->resolved, options, parsed, diagnostics);
    return entry;
}

/// Whether a mount of `attachments` (or below) tracks a named scene instance.
bool tracks_named_target(const std::vector<model::Attachment>& attachments) {
    for (const model::Attachment& attachment : attachments) {
        for (const model::Mount& mount : attachment.mounts) {
            if (mount.tracking && !mount.tracking->point_m && !mount.tracking->name.empty()) {
                return true;
            }
            if (tracks_named_target(mount.attachments)) return true;
        }
    }
    return false;
}

/// Copies the scene's problems `found` into `diagnostics`. With `contents_needed` false, its
/// errors outside the scene-list files themselves become one warning.
void report_scene_problems(const model::Simulation& simulation, const Diagnostics& found,
                           bool contents_needed, Diagnostics& diagnostics) {
    std::set<std::string> scene_files;
    for (const model::SceneEntry& entry : simulation.scenes) {
        scene_files.insert(entry.file.resolved.string());
    }
    std::size_t left = 0;
    const Diagnostic* first = nullptr;
    for (const Diagnostic& d : found.items()) {
        const bool contents_error = !contents_needed && d.severity == Diagnostic::Severity::error &&
                                    scene_files.count(d.where.file) == 0;
        if (!contents_error) {
            diagnostics.copy(d);
            continue;
        }
        ++left;
        if (first == nullptr) first = &d;
    }
    if (first == nullptr) return;
    ErrorContext where;
    if (simulation.scenes.size() == 1)
        where.file = simulation.scenes.front().file.resolved.string();
    diagnostics.warning(where, "the scene's contents have " + std::to_string(left) +
                                   (left == 1 ? " error" : " errors") +
                                   " (the first: " + first->text() +
                                   "); this tool needs only the scene's origin, but "
                                   "glint-render and glint-platform2jsim --check refuse it");
}

/// Tells `observer` what the simulation's atmosphere file held (the errors found since `errors`
/// were counted); nothing when its file does not exist.
void report_atmosphere(const model::SimulationInputs& inputs, std::size_t errors,
                       const Diagnostics& diagnostics, ReadObserver& observer) {
    Diagnostics repeated;  // used_atmosphere_plugin's warnings were given once already
    const model::Plugin* plugin = used_atmosphere_plugin(inputs.simulation, repeated);
    if (plugin == nullptr) {
        observer.atmosphere_read(inputs.simulation, nullptr, 0, inputs.atmosphere);
        return;
    }
    const model::FileRef& file = plugin->basic_atmosphere->atmosphere_file;
    std::error_code ec;
    if (file.resolved.empty() || !std::filesystem::is_regular_file(file.resolved, ec)) return;
    observer.atmosphere_read(inputs.simulation, &file, diagnostics.error_count() - errors,
                             inputs.atmosphere);
}

}  // namespace

std::optional<model::PlatformInputs> read_platform_entry(const model::Simulation& simulation,
                                                         std::size_t plugin_index,
                                                         const ReadOptions& options,
                                                         Diagnostics& diagnostics) {
    ParsedFiles parsed;
    return read_entry(simulation, plugin_index, options, parsed, diagnostics);
}

model::SimulationInputs load(const std::filesystem::path& simulation_file,
                             const LoadOptions& options, const Log& log, Diagnostics& diagnostics) {
    ReadOptions read = options.read;
    if (!read.files) read.files = std::make_shared<io::InputFiles>(log);

    std::vector<model::Simulation> simulations =
        dirsig::read_simulation(simulation_file, read, diagnostics);
    // keep_going: a simulation with errors is still looked into, to find the others.
    if (!options.keep_going || simulations.size() != 1) diagnostics.throw_if_errors();
    if (simulations.size() != 1) {
        throw input_error("the file holds " + std::to_string(simulations.size()) +
                              " simulations, expected one (split the array into one .jsim "
                              "per simulation)",
                          ErrorContext{simulation_file.string(), 0, {}});
    }
    model::SimulationInputs inputs;
    inputs.simulation = std::move(simulations.front());
    // The scene's problems are held back until the platforms tell whether its contents are
    // needed (LoadOptions::scene_contents).
    Diagnostics scene_problems;
    try {
        inputs.scene =
            read_simulation_scene(inputs.simulation, read, scene_problems, options.observer);
    } catch (const Error& e) {
        if (e.category() != ErrorCategory::input) throw;
        scene_problems.add(e);
    }
    if (options.scene_contents) {
        report_scene_problems(inputs.simulation, scene_problems, true, diagnostics);
    }
    if (options.atmosphere && options.atmosphere_override) {
        inputs.atmosphere =
            read_atmosphere_override(*options.atmosphere_override, read, diagnostics);
        log.info("Atmosphere: --atmosphere " +
                 (options.atmosphere_override->kind == AtmosphereOverride::Kind::file
                      ? options.atmosphere_override->file.string()
                      : std::string(model::to_string(inputs.atmosphere.kind))) +
                 " (in place of the simulation's)");
    } else if (options.atmosphere) {
        const std::size_t errors = diagnostics.error_count();
        inputs.atmosphere = read_simulation_atmosphere(inputs.simulation, read, diagnostics, log);
        if (options.observer != nullptr)
            report_atmosphere(inputs, errors, diagnostics, *options.observer);
    } else {
        inputs.atmosphere = default_atmosphere();
    }
    if (options.atmosphere) {
        inputs.weather = read_simulation_weather(inputs.simulation, inputs.atmosphere, read,
                                                 needs_weather(inputs.scene), diagnostics, log);
    }
    if (!options.keep_going) diagnostics.throw_if_errors();  // the scene's before the platforms'
    ParsedFiles parsed;
    for (const std::size_t index : inputs.simulation.basic_platform_indices()) {
        if (auto entry = read_entry(inputs.simulation, index, read, parsed, diagnostics)) {
            inputs.platforms.push_back(std::move(*entry));
        }
    }
    if (!options.scene_contents) {
        bool targets = false;
        for (const model::PlatformInputs& p : inputs.platforms) {
            targets = targets || tracks_named_target(p.platform->attachments);
        }
        report_scene_problems(inputs.simulation, scene_problems, targets, diagnostics);
    }
    if (!options.keep_going) diagnostics.throw_if_errors();
    read.files->clear();  // the texts were parsed; the record of opens stays
    return inputs;
}

model::SimulationInputs load_logged(const std::filesystem::path& simulation_file,
                                    const LoadOptions& options, const Log& log) {
    Diagnostics diagnostics;
    try {
        model::SimulationInputs inputs = load(simulation_file, options, log, diagnostics);
        diagnostics.log_to(log);  // the warnings
        return inputs;
    } catch (const Error& error) {
        diagnostics.log_and_rethrow(error, log);  // every problem, each once
    }
}

}  // namespace glint::inputs
