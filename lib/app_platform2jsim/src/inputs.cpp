// SPDX-License-Identifier: Apache-2.0
// Loading a simulation and the files it references into LoadedInputs, with every problem
// collected in its diagnostics: the platform and tasks readers, the scene and atmosphere
// readers (--check), existence checks for the other files, and the output-name clash check.
#include "glint/app_platform2jsim/inputs.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

#include "glint/core/text.h"
#include "glint/dirsig/motion_reader.h"
#include "glint/dirsig/readers.h"
#include "glint/dirsig/scene_reader.h"
#include "glint/inputs/load.h"
#include "glint/inputs/scene_atmosphere.h"
#include "glint/io/input_files.h"
#include "glint/model/derived.h"
#include "glint/model/truth.h"
#include "glint/schedule/schedule.h"

namespace glint::app_platform2jsim {
namespace {

namespace fs = std::filesystem;

fs::path key_of(const fs::path& file) { return LoadedInputs::key_of(file); }

bool same_place(const ErrorContext& a, const ErrorContext& b) {
    return a.file == b.file && a.line == b.line && a.element == b.element;
}

/// Counts the file and checks that it exists and is not a folder; reports `role` (e.g.
/// "motion") otherwise, unless an error was already reported where it is named.
bool check_exists(const model::FileRef& ref, const std::string& role, LoadedInputs& inputs) {
    if (ref.empty() || ref.resolved.empty()) return false;  // the reader has reported it
    inputs.files.insert(key_of(ref.resolved));
    return inputs::existing_file(ref, role, inputs.diagnostics);
}

void check_platform_references(const model::Platform& platform, LoadedInputs& inputs);

void check_mount_references(const model::Mount& mount, LoadedInputs& inputs);

void check_attachment_references(const model::Attachment& attachment, LoadedInputs& inputs) {
    for (const model::Mount& mount : attachment.mounts) check_mount_references(mount, inputs);
}

void check_mount_references(const model::Mount& mount, LoadedInputs& inputs) {
    for (const model::JitterSpec& axis : mount.deviates.axes) {
        if (!axis.psd_file.empty()) check_exists(axis.psd_file, "jitter PSD", inputs);
    }
    for (const model::Attachment& a : mount.attachments) check_attachment_references(a, inputs);
}

/// A PSF or active-area image, read and checked by the reader a render reads it with
/// (inputs::read_weight_image), so --check refuses what a render refuses, with its message.
void check_weight_image(const model::FileRef& ref, const std::string& element,
                        const ErrorContext& where, double max_value, LoadedInputs& inputs) {
    if (!check_exists(ref, element, inputs)) return;
    (void)inputs::read_weight_image(ref, element, where, max_value, inputs.diagnostics);
}

/// The files a platform names: mount jitter PSD tables, PSF and active-area images,
/// external trigger files.
void check_platform_references(const model::Platform& platform, LoadedInputs& inputs) {
    for (const model::Attachment& a : platform.attachments) check_attachment_references(a, inputs);
    for (const model::InstrumentPath& path : model::list_instruments(platform)) {
        for (const model::FocalPlane& fp : path.instrument->focal_planes) {
            const model::CaptureMethod& capture = fp.capture_method;
            if (capture.psf && !capture.psf->image.empty()) {
                check_weight_image(capture.psf->image, "<psf><image>", capture.psf->where, INFINITY,
                                   inputs);
            }
            if (!capture.active_area_image.empty()) {
                check_weight_image(capture.active_area_image, "<activearea><image>",
                                   capture.active_area_image.where, 1.0, inputs);
            }
            if (!fp.detector_array.clock.trigger_file.empty()) {
                check_exists(fp.detector_array.clock.trigger_file, "trigger", inputs);
            }
        }
    }
}

/// "2 materials, 3 objects, 4 instances, 26 triangles".
std::string describe(const model::Scene& scene) {
    std::size_t triangles = 0;
    for (const model::GeometryObject& object : scene.objects) {
        triangles += object.mesh.triangles.size();
    }
    return plural(scene.materials.size(), "material") + ", " +
           plural(scene.objects.size(), "object") + ", " +
           plural(scene.instances.size(), "instance") + ", " + plural(triangles, "triangle") +
           (scene.maps.empty() ? "" : ", " + plural(scene.maps.size(), "property map"));
}

/// `value` to 4 significant digits (the columns a profile computes carry more).
std::string four_digits(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

/// "parametric, aerosol optical depth 0.1 at 0.55 um, gases (water 2.924 cm, ozone 0.332
/// atm-cm), multiple scattering over ground albedo 0.2, air us_standard_1976 at 288.15 K" and
/// the like.
std::string describe(const model::Atmosphere& atmosphere) {
    const std::string kind = model::to_string(atmosphere.kind);
    switch (atmosphere.kind) {
        case model::AtmosphereKind::none:
            return kind;
        case model::AtmosphereKind::parametric: {
            const model::ParametricAtmosphere& p = atmosphere.parametric;
            const std::string aerosol =
                p.aerosol_profile
                    ? "aerosol profile (" + std::to_string(p.aerosol_profile->densities.size()) +
                          " layers of " + join(p.aerosol_profile->components, ", ") +
                          (p.aerosol_profile->mass_densities ? " in g/m^3" : " per cm^3") +
                          (p.aerosol_column_depth_550
                               ? ", optical depth " + format_shortest(*p.aerosol_column_depth_550) +
                                     " at 0.55 um"
                               : std::string()) +
                          ")"
                : p.aerosol_model.empty()
                    ? "aerosol optical depth " + format_shortest(p.aerosol_optical_depth_550) +
                          " at 0.55 um"
                    : "aerosol " + p.aerosol_model + " (LOWTRAN 7 layers, " +
                          (p.aerosol_column_depth_550
                               ? "optical depth " + format_shortest(*p.aerosol_column_depth_550) +
                                     " at 0.55 um"
                               : "visibility " + format_shortest(p.visibility_km) + " km") +
                          ")";
            return kind + ", " + aerosol + ", " +
                   (p.gas_absorption ? "gases (water " + four_digits(p.water_vapor_cm) +
                                           " cm, ozone " + four_digits(p.ozone_atm_cm) + " atm-cm)"
                                     : std::string("no gas absorption")) +
                   ", " +
                   (p.multiple_scattering ? "multiple scattering over ground albedo " +
                                                format_shortest(p.ground_albedo)
                                          : std::string("single scattering")) +
                   ", air " + model::standard_atmosphere(p.profile).name + " at " +
                   format_shortest(p.air_temperature_k) + " K";
        }
        case model::AtmosphereKind::tabulated: {
            const std::vector<double>& w = atmosphere.tabulated.wavelengths_um;
            std::string text = kind + ", " + plural(w.size(), "row");
            if (!w.empty()) {
                text += ", " + format_shortest(w.front()) + "-" + format_shortest(w.back()) + " um";
            }
            return text;
        }
        case model::AtmosphereKind::simple:
            return kind + ", sky at " +
                   format_shortest(atmosphere.simple.apparent_sky_temperature_k) + " K";
    }
    return kind;
}

/// The contents line of a file read by a reader that found `errors` errors in it.
std::string contents_line(const std::string& role, const fs::path& file, std::size_t errors,
                          const std::string& description) {
    return role + " " + file.string() + ": " +
           (errors == 0 ? description : "not usable, " + plural(errors, "error"));
}

/// Reads a scene file (once); nullptr when it does not exist.
const model::Scene* load_scene_ref(const model::FileRef& ref, LoadedInputs& inputs,
                                   const dirsig::ReadOptions& options) {
    if (!check_exists(ref, "scene", inputs)) return nullptr;
    const fs::path key = key_of(ref.resolved);
    if (const auto it = inputs.scenes.find(key); it != inputs.scenes.end()) return &it->second;
    const std::size_t errors = inputs.diagnostics.error_count();
    model::Scene scene;
    try {
        scene = inputs::read_scene(ref.resolved, options, inputs.diagnostics);
    } catch (const Error& error) {
        inputs.diagnostics.add(error);
    }
    inputs.contents.push_back(contents_line(
        "scene", ref.resolved, inputs.diagnostics.error_count() - errors, describe(scene)));
    return &inputs.scenes.emplace(key, std::move(scene)).first->second;
}

/// Reads an atmosphere file (once).
void load_atmosphere_ref(const model::FileRef& ref, LoadedInputs& inputs,
                         const dirsig::ReadOptions& options) {
    if (!check_exists(ref, "atmosphere", inputs)) return;
    const fs::path key = key_of(ref.resolved);
    if (inputs.atmospheres.count(key) > 0) return;
    const std::size_t errors = inputs.diagnostics.error_count();
    model::Atmosphere atmosphere;
    try {
        atmosphere = inputs::read_atmosphere(ref.resolved, options, inputs.diagnostics,
                                             ref.resolved.string());
    } catch (const Error& error) {
        inputs.diagnostics.add(error);
    }
    inputs.contents.push_back(contents_line("atmosphere", ref.resolved,
                                            inputs.diagnostics.error_count() - errors,
                                            describe(atmosphere)));
    inputs.atmospheres.emplace(key, std::move(atmosphere));
}

const model::Platform* load_platform_ref(const model::FileRef& ref, LoadedInputs& inputs,
                                         const dirsig::ReadOptions& options, LoadDepth depth) {
    if (!check_exists(ref, "platform", inputs)) return nullptr;
    return load_platform_file(ref.resolved, inputs, options, depth != LoadDepth::platforms);
}

void load_tasks_ref(const model::FileRef& ref, LoadedInputs& inputs,
                    const dirsig::ReadOptions& options) {
    if (!check_exists(ref, "tasks", inputs)) return;
    const fs::path key = key_of(ref.resolved);
    if (inputs.task_lists.count(key) > 0) return;
    inputs.task_lists.emplace(key, dirsig::read_tasks(ref.resolved, options, inputs.diagnostics));
}

/// What load() reads, as --check reports it: one contents line per scene and atmosphere file,
/// and each scene kept for the truth-target check.
class ContentsObserver final : public inputs::ReadObserver {
public:
    explicit ContentsObserver(LoadedInputs& inputs) : m_inputs(inputs) {}
    void scene_read(const fs::path& file, std::size_t errors, const model::Scene& scene) override {
        // A file checked before (another argument) is reported once.
        if (!m_inputs.scenes.emplace(key_of(file), scene).second) return;
        m_inputs.contents.push_back(contents_line("scene", file, errors, describe(scene)));
        for (const model::PropertyMap& map : scene.maps) {
            m_inputs.contents.push_back("  " + model::describe_map(map, scene.materials));
        }
        for (const model::Material& material : scene.materials) {
            if (material.temperature_map && !material.texture_parent) {
                m_inputs.contents.push_back(
                    "  " + model::describe_map(*material.temperature_map, scene.materials));
            }
        }
    }
    void atmosphere_read(const model::Simulation& simulation, const model::FileRef* file,
                         std::size_t errors, const model::Atmosphere& atmosphere) override {
        if (file == nullptr) {
            m_inputs.contents.push_back(
                "atmosphere (default: " + inputs::default_atmosphere_reason(simulation) +
                "): " + describe(atmosphere));
            return;
        }
        if (!m_inputs.atmospheres.emplace(key_of(file->resolved), atmosphere).second) return;
        m_inputs.contents.push_back(
            contents_line("atmosphere", file->resolved, errors, describe(atmosphere)));
    }

private:
    LoadedInputs& m_inputs;
};

/// Reads a simulation with the loader glint-render reads it with (inputs::load, going on
/// past errors to find them all), then builds its schedule as a render does (its own checks:
/// clocks, output names, poses), so --check refuses what a render refuses.
void check_simulation(const fs::path& file, LoadedInputs& inputs,
                      const dirsig::ReadOptions& options, const Log& log) {
    inputs::LoadOptions load_options;
    load_options.read = options;
    load_options.read.files = std::make_shared<io::InputFiles>(log);
    load_options.keep_going = true;
    ContentsObserver observer(inputs);
    load_options.observer = &observer;
    Diagnostics found;
    std::optional<model::SimulationInputs> loaded;
    try {
        loaded = inputs::load(file, load_options, log, found);
        if (!found.has_errors()) {
            (void)schedule::Schedule::build(*loaded, schedule::ScheduleOptions{}, log, found);
        }
    } catch (const Error& error) {
        if (error.category() != ErrorCategory::input) throw;
        if (!found.has_errors()) found.add(error);
    }
    for (const Diagnostic& d : found.items()) {
        // A problem of a file checked before (another argument) is reported once.
        const auto& seen = inputs.diagnostics.items();
        if (std::any_of(seen.begin(), seen.end(), [&](const Diagnostic& s) {
                return s.severity == d.severity && s.message == d.message &&
                       same_place(s.where, d.where);
            })) {
            continue;
        }
        inputs.diagnostics.copy(d);
    }
    inputs.files.insert(key_of(file));
    for (const fs::path& opened : load_options.read.files->opened()) {
        inputs.files.insert(key_of(opened));
    }
    if (!loaded) return;
    for (const model::PlatformInputs& entry : loaded->platforms) {
        const model::BasicPlatformInputs& files =
            *loaded->simulation.plugins[entry.plugin_index].basic_platform;
        inputs.platforms.emplace(key_of(files.platform_file.resolved), *entry.platform);
        inputs.task_lists.emplace(key_of(files.tasks_file.resolved), entry.tasks);
        inputs.motions.emplace(key_of(files.motion_file.resolved), entry.motion);
        for (const model::InstrumentPath& path : model::list_instruments(*entry.platform)) {
            for (const model::FocalPlane& fp : path.instrument->focal_planes) {
                const model::CaptureMethod& capture = fp.capture_method;
                if (capture.psf && !capture.psf->image.empty()) {
                    inputs.files.insert(key_of(capture.psf->image.resolved));
                }
                if (!capture.active_area_image.empty()) {
                    inputs.files.insert(key_of(capture.active_area_image.resolved));
                }
            }
        }
    }
    check_output_names(loaded->simulation, inputs.diagnostics);
    inputs.simulations.push_back(std::move(loaded->simulation));
}

void load_one_simulation(std::size_t index, LoadedInputs& inputs,
                         const dirsig::ReadOptions& options, LoadDepth depth) {
    // Copy what is needed: loading may not touch inputs.simulations, but keep it simple.
    const model::Simulation simulation = inputs.simulations[index];
    if (depth == LoadDepth::everything) {
        for (const model::SceneEntry& scene : simulation.scenes) {
            check_exists(scene.file, "scene", inputs);
        }
    }
    for (const model::Plugin& plugin : simulation.plugins) {
        if (plugin.basic_platform) {
            load_basic_platform(*plugin.basic_platform, inputs, options, depth);
        } else if (plugin.basic_atmosphere && depth != LoadDepth::platforms) {
            check_exists(plugin.basic_atmosphere->atmosphere_file, "atmosphere", inputs);
        }
    }
    if (depth != LoadDepth::platforms) check_output_names(simulation, inputs.diagnostics);
}

}  // namespace

fs::path LoadedInputs::key_of(const fs::path& file) {
    std::error_code ec;
    fs::path absolute = fs::absolute(file, ec);
    return (ec ? file : absolute).lexically_normal();
}

const model::Platform* LoadedInputs::platform_of(const model::BasicPlatformInputs& inputs) const {
    if (inputs.platform_file.resolved.empty()) return nullptr;
    const auto it = platforms.find(key_of(inputs.platform_file.resolved));
    return it == platforms.end() ? nullptr : &it->second;
}

void load_simulation_file(const fs::path& file, LoadedInputs& inputs,
                          const dirsig::ReadOptions& options) {
    inputs.files.insert(key_of(file));
    std::vector<model::Simulation> read =
        dirsig::read_simulation(file, options, inputs.diagnostics);
    for (model::Simulation& simulation : read) inputs.simulations.push_back(std::move(simulation));
}

void load_basic_platform(const model::BasicPlatformInputs& entry, LoadedInputs& inputs,
                         const dirsig::ReadOptions& options, LoadDepth depth) {
    load_platform_ref(entry.platform_file, inputs, options, depth);
    if (depth == LoadDepth::platforms) return;
    check_exists(entry.motion_file, "motion", inputs);
    load_tasks_ref(entry.tasks_file, inputs, options);
}

void load_references(LoadedInputs& inputs, const dirsig::ReadOptions& options, LoadDepth depth) {
    for (std::size_t i = 0; i < inputs.simulations.size(); ++i) {
        load_one_simulation(i, inputs, options, depth);
    }
}

const model::Platform* load_platform_file(const fs::path& file, LoadedInputs& inputs,
                                          const dirsig::ReadOptions& options,
                                          bool check_references) {
    const fs::path key = key_of(file);
    inputs.files.insert(key);
    if (const auto it = inputs.platforms.find(key); it != inputs.platforms.end()) {
        return &it->second;
    }
    model::Platform platform = dirsig::read_platform(file, options, inputs.diagnostics);
    const auto [it, inserted] = inputs.platforms.emplace(key, std::move(platform));
    if (check_references) check_platform_references(it->second, inputs);
    return &it->second;
}

/// Whether a glint YAML file is an atmosphere: a line starting "model:" (its one required
/// key), which no scene has at the top level.
bool is_yaml_atmosphere(const fs::path& file, const dirsig::ReadOptions& options) {
    std::string text;
    try {
        text = options.read_text(file, file.string());
    } catch (const Error&) {
        return false;  // the scene reader says why it cannot be read
    }
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("model:", 0) == 0 || line.rfind("model :", 0) == 0) return true;
    }
    return false;
}

/// Checks a material curve file alone: its layout and values, and one contents line.
void check_curve_file(const fs::path& file, const std::string& quantity, LoadedInputs& inputs,
                      const dirsig::ReadOptions& options) {
    inputs.files.insert(key_of(file));
    const std::size_t errors = inputs.diagnostics.error_count();
    const model::SpectralTable table =
        dirsig::read_curve_file(file, quantity, options, inputs.diagnostics);
    std::string description = plural(table.wavelengths_um.size(), "point");
    if (!table.wavelengths_um.empty()) {
        const auto [low, high] = std::minmax_element(table.values.begin(), table.values.end());
        const auto six = [](double value) {  // 6 significant digits (10⁴ / ν is rarely short)
            char text[32];
            std::snprintf(text, sizeof text, "%.6g", value);
            return std::string(text);
        };
        description += ", " + six(table.wavelengths_um.front()) + "-" +
                       six(table.wavelengths_um.back()) + " um, values " + six(*low) + "-" +
                       six(*high);
    }
    inputs.contents.push_back(contents_line(quantity == "emissivity" ? "emissivity curve" : "curve",
                                            file, inputs.diagnostics.error_count() - errors,
                                            description));
}

void check_file(const fs::path& file, LoadedInputs& inputs, const dirsig::ReadOptions& options,
                const Log& log) {
    const std::string extension = to_lower(file.extension().string());
    if (extension == ".platform") {
        load_platform_file(file, inputs, options);
        return;
    }
    if (extension == ".tasks") {
        const fs::path key = key_of(file);
        inputs.files.insert(key);
        if (inputs.task_lists.count(key) == 0) {
            inputs.task_lists.emplace(key, dirsig::read_tasks(file, options, inputs.diagnostics));
        }
        return;
    }
    if (extension == ".ppd" || extension == ".motion") {
        // Read as a render reads a BasicPlatform's motion file, with its PSD tables.
        const fs::path key = key_of(file);
        inputs.files.insert(key);
        if (inputs.motions.count(key) == 0) {
            model::PlatformMotion motion;
            try {
                motion = dirsig::read_motion(file, options, inputs.diagnostics);
                inputs::read_psd_tables(motion, options, inputs.diagnostics);
            } catch (const Error& error) {
                inputs.diagnostics.add(error);
            }
            inputs.motions.emplace(key, std::move(motion));
        }
        return;
    }
    // A file given on the command line is named by itself in messages.
    const model::FileRef ref{file.string(), file, ErrorContext{file.string(), 0, {}}};
    if (extension == ".scene") {
        load_scene_ref(ref, inputs, options);
        return;
    }
    if (extension == ".atm") {
        load_atmosphere_ref(ref, inputs, options);
        return;
    }
    if (extension == ".yaml" || extension == ".yml") {
        // A glint YAML file is an atmosphere (a top-level "model:" key) or a scene.
        if (is_yaml_atmosphere(file, options)) {
            load_atmosphere_ref(ref, inputs, options);
        } else {
            load_scene_ref(ref, inputs, options);
        }
        return;
    }
    if (extension == ".ems" || extension == ".txt") {
        check_curve_file(file, extension == ".ems" ? "emissivity" : "intensity", inputs, options);
        return;
    }
    if (extension == ".glist") {
        // Its matids name the materials of the .mat its .scene names: alone it cannot be read.
        inputs.files.insert(key_of(file));
        inputs.diagnostics.warning(
            ErrorContext{file.string(), 0, {}},
            "a .glist is not checked alone: its matids name the materials of the .mat its "
            ".scene names; check the .scene");
        return;
    }
    if (extension == ".mat") {
        inputs.files.insert(key_of(file));
        const std::size_t errors = inputs.diagnostics.error_count();
        std::vector<model::Material> materials;
        try {
            materials = dirsig::read_dirsig_materials(file, options, inputs.diagnostics);
        } catch (const Error& error) {
            inputs.diagnostics.add(error);
        }
        inputs.contents.push_back(contents_line("materials", file,
                                                inputs.diagnostics.error_count() - errors,
                                                plural(materials.size(), "material")));
        return;
    }
    check_simulation(file, inputs, options, log);
}

}  // namespace glint::app_platform2jsim
