// SPDX-License-Identifier: Apache-2.0
// Reader of DIRSIG5 `.jsim` files: a JSON array of simulation objects (scene_list,
// plugin_list, medium_list). BasicPlatform and BasicAtmosphere inputs are read into the model
// with their paths resolved against the .jsim's folder; other plugins and medium_list are kept
// verbatim. Problems name the JSON path ("[0].plugin_list[1].inputs.platform_filename") and
// its line, which the JSON layer (json_lines.h) records for every value.
#include <algorithm>
#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>
#include <utility>

#include "glint/core/text.h"
#include "glint/dirsig/readers.h"
#include "glint/io/xml.h"
#include "glint/model/output_name.h"
#include "jsim_keys.h"
#include "json_lines.h"

namespace glint::dirsig {
namespace {

using detail::index_path;
using detail::Json;
using detail::key_path;
using detail::LineTable;
using detail::shorten;

/// What the reading functions share: where messages point and where paths resolve from.
class JsimReader {
public:
    JsimReader(std::string file, LineTable lines, std::filesystem::path base_dir,
               const ReadOptions& options, Diagnostics& diagnostics)
        : m_file(std::move(file)),
          m_lines(std::move(lines)),
          m_base_dir(std::move(base_dir)),
          m_options(options),
          m_diagnostics(diagnostics) {}

    model::Simulation read_simulation(const Json& value, const std::string& path) const;

private:
    ErrorContext at(const std::string& path) const {
        // A path that is not in the text (a missing key) is placed at its parent's line.
        return ErrorContext{m_file, m_lines.line_of(path), shorten(path)};
    }

    static std::string describe(const Json& value) {
        std::string out = value.type_name();
        if (value.is_primitive()) {
            std::string text = value.dump();
            if (text.size() > 64) text = to_valid_utf8(text.substr(0, 64)) + "...";
            out += " " + text;
        }
        return out;
    }

    void wrong_type(const std::string& path, const char* expected, const Json& value) const {
        m_diagnostics.error(at(path),
                            std::string("expected ") + expected + ", got " + describe(value));
    }

    void warn_unknown_keys(const Json& object, const std::string& path,
                           std::initializer_list<std::string_view> known,
                           const std::string& what) const {
        for (const auto& [key, value] : object.items()) {
            if (std::find(known.begin(), known.end(), key) != known.end()) continue;
            m_diagnostics.warning(at(key_path(path, key)),
                                  "unknown key " + quote(key) + what + " ignored");
        }
    }

    /// The string at `object[key]`; nullopt (and an error when `required` or mistyped)
    /// otherwise.
    std::optional<std::string> string_at(const Json& object, const std::string& path,
                                         const char* key, bool required) const {
        const auto it = object.find(key);
        if (it == object.end()) {
            if (required) {
                m_diagnostics.error(at(path), std::string("missing required key \"") + key + "\"");
            }
            return std::nullopt;
        }
        if (!it->is_string()) {
            wrong_type(key_path(path, key), "a string", *it);
            return std::nullopt;
        }
        return it->get<std::string>();
    }

    /// A required path-valued string resolved against the .jsim's folder.
    model::FileRef file_at(const Json& object, const std::string& path, const char* key) const {
        const std::optional<std::string> text = string_at(object, path, key, true);
        if (!text) return {};
        return m_options.paths.resolve(*text, m_base_dir, at(key_path(path, key)), m_diagnostics);
    }

    void read_scenes(const Json& list, const std::string& path, model::Simulation& out) const;
    model::Plugin read_plugin(const Json& value, const std::string& path) const;
    model::BasicPlatformInputs read_basic_platform(const Json& inputs,
                                                   const std::string& path) const;

    std::string m_file;
    LineTable m_lines;
    std::filesystem::path m_base_dir;
    const ReadOptions& m_options;
    Diagnostics& m_diagnostics;
};

model::Simulation JsimReader::read_simulation(const Json& value, const std::string& path) const {
    model::Simulation simulation;
    simulation.file = m_file;
    if (!value.is_object()) {
        wrong_type(path, "a simulation object", value);
        return simulation;
    }
    warn_unknown_keys(value, path, {"scene_list", "plugin_list", "medium_list"}, "");

    if (const auto it = value.find("scene_list"); it != value.end()) {
        read_scenes(*it, key_path(path, "scene_list"), simulation);
    }

    const std::string plugins_path = key_path(path, "plugin_list");
    if (const auto it = value.find("plugin_list"); it == value.end()) {
        m_diagnostics.error(at(path), "missing required key \"plugin_list\"");
    } else if (!it->is_array()) {
        wrong_type(plugins_path, "an array of plugins", *it);
    } else {
        for (std::size_t i = 0; i < it->size(); ++i) {
            simulation.plugins.push_back(read_plugin((*it)[i], index_path(plugins_path, i)));
        }
    }
    // One warning per plugin glint does not run, saying what it does instead (known once
    // every plugin is read: an atmosphere plugin beside a BasicAtmosphere changes nothing).
    const bool has_basic_atmosphere = simulation.atmosphere() != nullptr;
    for (const model::Plugin& plugin : simulation.plugins) {
        // ThermWeather's weather drives THERM (glint/inputs/weather.h).
        if (plugin.basic_platform || plugin.basic_atmosphere || plugin.name.empty() ||
            plugin.name == "ThermWeather") {
            continue;
        }
        m_diagnostics.warning(plugin.where,
                              "plugin \"" + plugin.name + "\" is not run: " +
                                  unsupported_plugin_fallback(plugin.name, has_basic_atmosphere) +
                                  " (kept in a rewritten .jsim)");
    }

    if (const auto it = value.find("medium_list"); it != value.end()) {
        if (it->is_array()) {
            simulation.medium_list_json = it->dump();
            if (!it->empty()) {
                m_diagnostics.warning(at(key_path(path, "medium_list")),
                                      "medium_list is not applied: glint models no "
                                      "participating media (kept in a rewritten .jsim)");
            }
        } else {
            wrong_type(key_path(path, "medium_list"), "an array", *it);
        }
    }
    return simulation;
}

void JsimReader::read_scenes(const Json& list, const std::string& path,
                             model::Simulation& out) const {
    if (!list.is_array()) {
        wrong_type(path, "an array of scenes", list);
        return;
    }
    for (std::size_t i = 0; i < list.size(); ++i) {
        const Json& entry = list[i];
        const std::string entry_path = index_path(path, i);
        if (!entry.is_object()) {
            wrong_type(entry_path, "a scene object", entry);
            continue;
        }
        warn_unknown_keys(entry, entry_path, {"inputs", "offset"}, " in a scene_list entry");
        model::SceneEntry scene;
        scene.file = file_at(entry, entry_path, "inputs");
        scene.offset = string_at(entry, entry_path, "offset", false).value_or("");
        if (entry.contains("offset")) scene.offset_where = at(key_path(entry_path, "offset"));
        out.scenes.push_back(std::move(scene));
    }
}

model::Plugin JsimReader::read_plugin(const Json& value, const std::string& path) const {
    model::Plugin plugin;
    plugin.where = at(path);
    plugin.inputs_json = "{}";
    if (!value.is_object()) {
        wrong_type(path, "a plugin object", value);
        return plugin;
    }
    warn_unknown_keys(value, path, {"name", "inputs"}, " in a plugin_list entry");
    plugin.name = string_at(value, path, "name", true).value_or("");

    const std::string inputs_path = key_path(path, "inputs");
    Json inputs = Json::object();
    if (const auto it = value.find("inputs"); it != value.end()) {
        if (it->is_object()) {
            inputs = *it;
        } else {
            wrong_type(inputs_path, "an object", *it);
        }
    }
    plugin.inputs_json = inputs.dump();

    if (plugin.name == kBasicPlatform) {
        plugin.basic_platform = read_basic_platform(inputs, inputs_path);
    } else if (plugin.name == kBasicAtmosphere) {
        warn_unknown_keys(inputs, inputs_path, {kAtmosphereFilename}, " in BasicAtmosphere inputs");
        plugin.basic_atmosphere =
            model::BasicAtmosphereInputs{file_at(inputs, inputs_path, kAtmosphereFilename)};
    }
    return plugin;
}

model::BasicPlatformInputs JsimReader::read_basic_platform(const Json& inputs,
                                                           const std::string& path) const {
    warn_unknown_keys(inputs, path,
                      {kPlatformFilename, kMotionFilename, kTasksFilename, kOutputFolder,
                       kOutputPrefix, kSplitChannels},
                      " in BasicPlatform inputs");
    model::BasicPlatformInputs out;
    out.platform_file = file_at(inputs, path, kPlatformFilename);
    out.motion_file = file_at(inputs, path, kMotionFilename);
    out.tasks_file = file_at(inputs, path, kTasksFilename);
    out.output_folder = string_at(inputs, path, kOutputFolder, false);
    out.output_prefix = string_at(inputs, path, kOutputPrefix, false);
    if (out.output_prefix) {
        if (const auto problem = model::output_name_problem(*out.output_prefix)) {
            m_diagnostics.error(at(key_path(path, kOutputPrefix)),
                                "output_prefix " + quote(*out.output_prefix) + " " + *problem);
            out.output_prefix.reset();
        }
    }
    if (const auto it = inputs.find(kSplitChannels); it != inputs.end()) {
        std::optional<bool> value;
        if (it->is_boolean()) {
            value = it->get<bool>();
        } else if (it->is_string()) {
            std::string text = it->get<std::string>();
            for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            if (text == "true") value = true;
            if (text == "false") value = false;
        }
        if (value) {
            out.split_channels = *value;
        } else {
            wrong_type(key_path(path, kSplitChannels), "true or false", *it);
        }
    }
    return out;
}

}  // namespace

PluginKind plugin_kind(std::string_view name) {
    if (name == kBasicPlatform) return PluginKind::basic_platform;
    if (name == kBasicAtmosphere) return PluginKind::basic_atmosphere;
    const std::string lower = to_lower(std::string(name));
    const auto has = [&](std::string_view word) { return lower.find(word) != std::string::npos; };
    if (has("atmosphere")) return PluginKind::atmosphere;
    if (has("ephemeris")) return PluginKind::ephemeris;
    if (has("weather") || has("therm") || has("temperature")) return PluginKind::thermal;
    return PluginKind::other;
}

std::string unsupported_plugin_fallback(std::string_view name, bool has_basic_atmosphere) {
    switch (plugin_kind(name)) {
        case PluginKind::atmosphere:
            return has_basic_atmosphere
                       ? std::string("the BasicAtmosphere entry's atmosphere is used")
                       : std::string(
                             "glint's default atmosphere is used (--atmosphere picks "
                             "another)");
        case PluginKind::ephemeris:
            return "glint places the sun and moon itself";
        case PluginKind::thermal:
            return "materials keep their own temperatures (a ThermWeather plugin's weather "
                   "drives THERM)";
        case PluginKind::basic_platform:
        case PluginKind::basic_atmosphere:
        case PluginKind::other:
            break;
    }
    return "it has no effect";
}

std::vector<model::Simulation> read_jsim(const std::filesystem::path& file,
                                         const ReadOptions& options, Diagnostics& diagnostics) {
    const std::string name = file.string();
    std::string text;
    try {
        text = options.read_text(file, name);
    } catch (const Error& error) {
        diagnostics.add(error);
        return {};
    }
    std::optional<detail::LinedJson> parsed = detail::parse_lined_json(text, name, diagnostics);
    if (!parsed) return {};
    const Json& document = parsed->document;

    const JsimReader reader(name, std::move(parsed->lines), file.parent_path(), options,
                            diagnostics);
    std::vector<model::Simulation> simulations;
    if (document.is_object()) {
        simulations.push_back(reader.read_simulation(document, ""));
    } else if (!document.is_array()) {
        diagnostics.error(
            ErrorContext{name, 1, {}},
            std::string("expected an array of simulation objects, got ") + document.type_name());
    } else if (document.empty()) {
        diagnostics.error(ErrorContext{name, 1, {}},
                          "expected at least one simulation object, got an empty array");
    } else {
        for (std::size_t i = 0; i < document.size(); ++i) {
            simulations.push_back(reader.read_simulation(document[i], index_path("", i)));
        }
    }
    return simulations;
}

}  // namespace glint::dirsig
