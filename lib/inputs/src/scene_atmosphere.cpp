// SPDX-License-Identifier: Apache-2.0
// A simulation's atmosphere and merged scene (glint/inputs/scene_atmosphere.h): the first
// BasicAtmosphere plugin's file or the embedded parametric default, and every scene_list
// entry read with read_scene and merged (origin, materials by id, objects, instances).
#include "glint/inputs/scene_atmosphere.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/text.h"
#include "glint/dirsig/readers.h"
#include "glint/dirsig/scene_reader.h"
#include "glint/io/xml.h"
#include "glint/yaml/atmosphere_reader.h"

namespace glint::inputs {
namespace {

/// For a path written on Windows, what to do about it: " (a Windows path: --path-map
/// C:/DIRSIG=DIR reads C:/DIRSIG/… from DIR)", FROM being its drive and first folder; ""
/// for any other path.
std::string windows_path_hint(const std::string& text) {
    if (!dirsig::is_windows_absolute(text)) return "";
    std::string path = text;
    for (char& c : path) {
        if (c == '\\') c = '/';
    }
    std::size_t end = path.find('/', path.rfind(':') == 1 ? 3 : 2);  // after "C:/" or "//server/"
    if (path.rfind("//", 0) == 0) end = path.find('/', end + 1);
    const std::string from = end == std::string::npos ? path : path.substr(0, end);
    return " (a Windows path: --path-map " + from + "=DIR reads " + from + "/... from DIR)";
}

namespace fs = std::filesystem;

/// Origins closer than this are the same (about 0.1 mm on the ground).
constexpr double kOriginTolerance_deg = 1e-9;
constexpr double kOriginTolerance_m = 1e-4;

std::string describe(const model::SceneOrigin& origin) {
    return "latitude " + format_shortest(origin.latitude_deg) + " deg, longitude " +
           format_shortest(origin.longitude_deg) + " deg, altitude " +
           format_shortest(origin.altitude_m) + " m";
}

bool same_origin(const model::SceneOrigin& a, const model::SceneOrigin& b) {
    return std::abs(a.latitude_deg - b.latitude_deg) <= kOriginTolerance_deg &&
           std::abs(a.longitude_deg - b.longitude_deg) <= kOriginTolerance_deg &&
           std::abs(a.altitude_m - b.altitude_m) <= kOriginTolerance_m;
}

std::string located(const ErrorContext& where) {
    return where.line > 0 ? where.file + ":" + std::to_string(where.line) : where.file;
}

/// True when the scene_list offset is empty or every component is zero.
bool zero_offset(const std::string& offset) {
    std::string text = offset;
    for (char& c : text) {
        if (c == ' ' || c == '\t') c = ',';
    }
    for (const std::string& item : split_list(text)) {
        const auto value = parse_double(item);
        if (!value || *value != 0.0) return false;
    }
    return true;
}

}  // namespace

bool existing_file(const model::FileRef& ref, const std::string& role, Diagnostics& diagnostics) {
    if (ref.resolved.empty()) return false;  // the reader of the simulation reported it
    const auto& items = diagnostics.items();
    if (std::any_of(items.begin(), items.end(), [&](const Diagnostic& d) {
            return d.severity == Diagnostic::Severity::error && d.where.file == ref.where.file &&
                   d.where.line == ref.where.line && d.where.element == ref.where.element;
        })) {
        return false;  // the reader of the simulation checked it, and reported it
    }
    std::error_code ec;
    const fs::file_status status = fs::status(ref.resolved, ec);
    if (!fs::exists(status)) {
        diagnostics.error(ref.where, role + " file does not exist: " + ref.resolved.string() +
                                         windows_path_hint(ref.text));
        return false;
    }
    if (fs::is_directory(status)) {
        diagnostics.error(ref.where,
                          role + " path is a folder, expected a file: " + ref.resolved.string());
        return false;
    }
    return true;
}

model::Atmosphere default_atmosphere() {
    model::Atmosphere atmosphere;
    atmosphere.kind = model::AtmosphereKind::parametric;
    atmosphere.parametric = model::ParametricAtmosphere{};
    return atmosphere;
}

const model::Plugin* unsupported_atmosphere_plugin(const model::Simulation& simulation) {
    for (const model::Plugin& plugin : simulation.plugins) {
        if (dirsig::plugin_kind(plugin.name) == dirsig::PluginKind::atmosphere) return &plugin;
    }
    return nullptr;
}

std::string default_atmosphere_reason(const model::Simulation& simulation) {
    if (const model::Plugin* plugin = unsupported_atmosphere_plugin(simulation)) {
        return simulation.file + "'s " + plugin->name + " plugin is not supported";
    }
    return simulation.file + " names none";
}

AtmosphereOverride parse_atmosphere_override(const std::string& text) {
    if (text.empty() || text == "-") {
        throw usage_error("--atmosphere: expected none, parametric or an atmosphere file, got " +
                          quote(text) + (text == "-" ? " (stdin cannot be an atmosphere)" : ""));
    }
    if (text == "none") return {AtmosphereOverride::Kind::none, {}};
    if (text == "parametric") return {AtmosphereOverride::Kind::parametric, {}};
    return {AtmosphereOverride::Kind::file, text};
}

model::Atmosphere read_atmosphere_override(const AtmosphereOverride& choice,
                                           const ReadOptions& options, Diagnostics& diagnostics) {
    model::Atmosphere atmosphere = default_atmosphere();
    atmosphere.where = ErrorContext{"--atmosphere", 0, {}};
    if (choice.kind == AtmosphereOverride::Kind::none) {
        atmosphere.kind = model::AtmosphereKind::none;
        atmosphere.source = "--atmosphere none";
        return atmosphere;
    }
    atmosphere.source = "--atmosphere parametric";
    if (choice.kind == AtmosphereOverride::Kind::parametric) return atmosphere;
    model::FileRef ref;
    ref.text = choice.file.string();
    std::error_code ec;
    ref.resolved = fs::absolute(choice.file, ec).lexically_normal();
    if (ec) ref.resolved = choice.file;
    ref.where = atmosphere.where;
    if (!existing_file(ref, "atmosphere", diagnostics)) return atmosphere;
    try {
        return read_atmosphere(ref.resolved, options, diagnostics, ref.text);
    } catch (const Error& error) {
        diagnostics.add(error);
    }
    return atmosphere;
}

const model::Plugin* used_atmosphere_plugin(const model::Simulation& simulation,
                                            Diagnostics& diagnostics) {
    const model::Plugin* first = nullptr;
    for (std::size_t i = 0; i < simulation.plugins.size(); ++i) {
        const model::Plugin& plugin = simulation.plugins[i];
        if (!plugin.basic_atmosphere) continue;
        if (first == nullptr) {
            first = &plugin;
        } else {
            diagnostics.warning(plugin.where, "plugin_list[" + std::to_string(i) +
                                                  "] is another BasicAtmosphere: only the "
                                                  "first one is used (ignored)");
        }
    }
    return first;
}

model::Atmosphere read_simulation_atmosphere(const model::Simulation& simulation,
                                             const ReadOptions& options, Diagnostics& diagnostics,
                                             const Log& log) {
    model::Atmosphere fallback = default_atmosphere();
    fallback.where = ErrorContext{simulation.file, 0, {}};
    const model::Plugin* first = used_atmosphere_plugin(simulation, diagnostics);
    if (first == nullptr) {
        const model::Plugin* unsupported = unsupported_atmosphere_plugin(simulation);
        log.debug(simulation.file + ": no BasicAtmosphere plugin" +
                  (unsupported ? " (its " + unsupported->name + " plugin is not supported)"
                               : std::string()) +
                  ": using the default atmosphere (parametric, default parameters)");
        return fallback;
    }
    const model::FileRef& ref = first->basic_atmosphere->atmosphere_file;
    if (!existing_file(ref, "atmosphere", diagnostics)) return fallback;
    try {
        return read_atmosphere(ref.resolved, options, diagnostics, ref.resolved.string());
    } catch (const Error& error) {
        diagnostics.add(error);
    }
    return fallback;
}

void merge_scene(model::Scene& scene, model::Scene part, Diagnostics& diagnostics) {
    if (scene.file.empty()) scene.file = part.file;
    if (part.origin) {
        if (!scene.origin) {
            scene.origin = part.origin;
        } else if (!same_origin(*scene.origin, *part.origin)) {
            diagnostics.warning(part.origin->where, "scene origin (" + describe(*part.origin) +
                                                        ") differs from the origin set by " +
                                                        located(scene.origin->where) + " (" +
                                                        describe(*scene.origin) +
                                                        "), which is used");
        }
    }

    // Where each of part's materials ends up in the merged list.
    const std::size_t merged_before = scene.materials.size();
    std::vector<std::uint32_t> index_of(part.materials.size(), 0);
    for (std::size_t i = 0; i < part.materials.size(); ++i) {
        model::Material& material = part.materials[i];
        std::optional<std::size_t> existing;
        for (std::size_t j = 0; j < scene.materials.size() && !existing && !material.id.empty();
             ++j) {
            if (scene.materials[j].id == material.id) existing = j;
        }
        if (!existing) {
            index_of[i] = static_cast<std::uint32_t>(scene.materials.size());
            scene.materials.push_back(std::move(material));
            continue;
        }
        const model::Material& first = scene.materials[*existing];
        index_of[i] = static_cast<std::uint32_t>(*existing);
        const bool same_definition =
            first.where.file == material.where.file && first.where.line == material.where.line;
        if (!same_definition) {
            diagnostics.error(material.where, "material id \"" + material.id +
                                                  "\" is already defined at " +
                                                  located(first.where));
        }
    }

    // A texture class names the material it is a class of by index.
    for (std::size_t j = merged_before; j < scene.materials.size(); ++j) {
        std::optional<std::uint32_t>& parent = scene.materials[j].texture_parent;
        if (parent && *parent < index_of.size()) parent = index_of[*parent];
    }
    const std::size_t object_offset = scene.objects.size();
    for (model::GeometryObject& object : part.objects) {
        for (std::uint32_t& m : object.mesh.triangle_materials) {
            if (m < index_of.size()) m = index_of[m];
        }
        scene.objects.push_back(std::move(object));
    }
    for (model::Instance& instance : part.instances) {
        instance.object_index += object_offset;
        scene.instances.push_back(std::move(instance));
    }
    for (model::PointSource& source : part.point_sources) {
        if (source.material < index_of.size()) source.material = index_of[source.material];
        scene.point_sources.push_back(std::move(source));
    }
    // A part's maps apply to its own materials, wherever they landed; they come after the
    // maps merged before them.
    for (model::PropertyMap& map : part.maps) {
        for (auto* list : {&map.applies_to, &map.band_materials, &map.slot_materials}) {
            for (std::uint32_t& m : *list) {
                if (m < index_of.size()) m = index_of[m];
            }
        }
        for (auto& entry : map.dc_materials) {
            if (entry.second < index_of.size()) entry.second = index_of[entry.second];
        }
        for (model::TextureClasses& classes : map.texture_classes) {
            for (std::uint32_t& m : classes.materials) {
                if (m < index_of.size()) m = index_of[m];
            }
        }
        scene.maps.push_back(std::move(map));
    }
}

void check_scene_offset(const model::SceneEntry& entry, Diagnostics& diagnostics) {
    if (entry.offset.empty() || zero_offset(entry.offset)) return;
    diagnostics.warning(entry.offset_where.file.empty() ? entry.file.where : entry.offset_where,
                        "scene offset \"" + entry.offset +
                            "\" is read, not applied: the scene "
                            "is placed at its own origin");
}

model::Scene read_simulation_scene(const model::Simulation& simulation, const ReadOptions& options,
                                   Diagnostics& diagnostics, ReadObserver* observer) {
    model::Scene scene;
    for (const model::SceneEntry& entry : simulation.scenes) {
        check_scene_offset(entry, diagnostics);
        if (!existing_file(entry.file, "scene", diagnostics)) continue;
        const std::size_t errors = diagnostics.error_count();
        model::Scene part;
        bool read = true;
        try {
            part = read_scene(entry.file.resolved, options, diagnostics);
        } catch (const Error& error) {
            diagnostics.add(error);
            read = false;
        }
        if (observer != nullptr) {
            observer->scene_read(entry.file.resolved, diagnostics.error_count() - errors, part);
        }
        if (!read) continue;
        merge_scene(scene, std::move(part), diagnostics);
    }
    return scene;
}

}  // namespace glint::inputs
