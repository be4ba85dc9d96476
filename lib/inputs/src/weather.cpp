// SPDX-License-Identifier: Apache-2.0
// The simulation's weather history (glint/inputs/weather.h).
#include "glint/inputs/weather.h"

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "glint/core/text.h"
#include "glint/dirsig/wth_reader.h"

namespace glint::inputs {

namespace {

/// An error when the weather is needed, else a warning.
void report(bool needed, const ErrorContext& where, const std::string& message,
            Diagnostics& diagnostics) {
    if (needed) {
        diagnostics.error(where, message);
    } else {
        diagnostics.warning(where, message + " (not needed: no material uses THERM)");
    }
}

/// The `filename` input of a ThermWeather plugin; empty (after its report) when it has none.
std::string plugin_filename(const model::Plugin& plugin, bool needed, Diagnostics& diagnostics) {
    const nlohmann::json inputs = nlohmann::json::parse(plugin.inputs_json, nullptr, false);
    if (inputs.is_object()) {
        for (const auto& [key, value] : inputs.items()) {
            if (key != "filename") {
                diagnostics.warning(plugin.where, "unknown key \"" + key + "\" in " + plugin.name +
                                                      " inputs ignored (glint reads \"filename\")");
            }
        }
        if (const auto it = inputs.find("filename"); it != inputs.end() && it->is_string()) {
            return it->get<std::string>();
        }
    }
    report(needed, plugin.where,
           "plugin \"" + plugin.name + "\" has no \"filename\" input (the .wth weather history)",
           diagnostics);
    return {};
}

model::Weather read_named(const std::string& text, const std::filesystem::path& base,
                          const ErrorContext& where, const dirsig::ReadOptions& options,
                          bool needed, Diagnostics& diagnostics) {
    const model::FileRef ref = options.paths.resolve(text, base, where, diagnostics);
    model::Weather weather;
    if (ref.resolved.empty()) return weather;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(ref.resolved, ec)) {
        report(needed, where, "weather file " + ref.resolved.string() + " does not exist",
               diagnostics);
        return weather;
    }
    weather = dirsig::read_wth(ref.resolved, options, diagnostics);
    weather.where = where;
    return weather;
}

}  // namespace

bool needs_weather(const model::Scene& scene) noexcept {
    for (const model::Material& m : scene.materials) {
        if (m.therm) return true;
    }
    return false;
}

model::Weather read_simulation_weather(const model::Simulation& simulation,
                                       const model::Atmosphere& atmosphere,
                                       const dirsig::ReadOptions& options, bool needed,
                                       Diagnostics& diagnostics, const Log& log) {
    const model::Plugin* plugin = nullptr;
    for (const model::Plugin& p : simulation.plugins) {
        if (to_lower(p.name) == "thermweather") {
            plugin = &p;
            break;
        }
    }
    model::Weather weather;
    if (plugin != nullptr) {
        const std::string name = plugin_filename(*plugin, needed, diagnostics);
        if (name.empty()) return weather;
        if (!atmosphere.weather_file.empty()) {
            diagnostics.warning(atmosphere.weather_where,
                                "weather file " + atmosphere.weather_file +
                                    " is not read: the ThermWeather plugin's " + name + " is");
        }
        weather = read_named(name, std::filesystem::path(simulation.file).parent_path(),
                             plugin->where, options, needed, diagnostics);
    } else if (!atmosphere.weather_file.empty()) {
        weather = read_named(atmosphere.weather_file,
                             std::filesystem::path(atmosphere.source).parent_path(),
                             atmosphere.weather_where, options, needed, diagnostics);
    }
    if (needed && plugin == nullptr && atmosphere.weather_file.empty()) {
        diagnostics.error(ErrorContext{simulation.file, 0, {}},
                          "a material uses THERM (TEMP_SOLVER_NAME = Therm) but the simulation "
                          "names no weather: add a ThermWeather plugin with the .wth as its "
                          "filename, or name it in the atmosphere (a .atm's "
                          "<uniformweather><classicdata><filename>, a YAML atmosphere's "
                          "'weather')");
    }
    if (!weather.empty()) {
        log.debug("Weather: " + weather.file + ", " + std::to_string(weather.records.size()) +
                  " rows every " + format_shortest(weather.step_h) + " h");
    }
    return weather;
}

}  // namespace glint::inputs
