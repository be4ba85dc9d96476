// SPDX-License-Identifier: Apache-2.0
// Reader of DIRSIG4 `.sim` files (a list of `externalfile` references) into the Simulation a
// DIRSIG5 `.jsim` would hold: the scene, a BasicAtmosphere plugin and one BasicPlatform plugin.
// Every referenced file must exist. Also read_simulation, which tells `.sim` from `.jsim` by
// content.
#include <map>
#include <nlohmann/json.hpp>

#include "glint/core/json_text.h"
#include "glint/dirsig/readers.h"
#include "glint/io/xml.h"

namespace glint::dirsig {
namespace {

/// Resolves the `externalfile` of `node` and checks that the file exists.
std::optional<model::FileRef> read_reference(const io::XmlNode& node,
                                             const std::filesystem::path& base_dir,
                                             const ReadOptions& options, Diagnostics& diagnostics) {
    const std::optional<std::string> text = node.attribute("externalfile");
    if (!text) {
        diagnostics.error(node.where(), "missing required attribute externalfile");
        return std::nullopt;
    }
    const std::size_t errors_before = diagnostics.error_count();
    model::FileRef ref = options.paths.resolve(*text, base_dir, node.where(), diagnostics);
    if (diagnostics.error_count() != errors_before || ref.resolved.empty()) return ref;
    std::error_code ec;
    const auto status = std::filesystem::status(ref.resolved, ec);
    if (!std::filesystem::exists(status)) {
        diagnostics.error(node.where(), "referenced file does not exist: " + ref.resolved.string());
    } else if (std::filesystem::is_directory(status)) {
        diagnostics.error(node.where(),
                          "referenced path is a folder, expected a file: " + ref.resolved.string());
    }
    return ref;
}

/// Content sniffing for read_simulation: the first character that is not blank (or a BOM).
char first_significant(const std::string& text) {
    std::size_t i = text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;
    while (i < text.size() &&
           (text[i] == ' ' || text[i] == '\t' || text[i] == '\n' || text[i] == '\r')) {
        ++i;
    }
    return i < text.size() ? text[i] : '\0';
}

}  // namespace

model::Simulation read_sim(const std::filesystem::path& file, const ReadOptions& options,
                           Diagnostics& diagnostics) {
    model::Simulation simulation;
    simulation.file = file.string();
    try {
        const io::XmlDocument document =
            io::XmlDocument::parse(options.read_text(file, simulation.file), simulation.file);
        const io::XmlNode root = document.root("simulation");
        const std::filesystem::path base_dir = file.parent_path();

        std::map<std::string, io::XmlNode> single;  // elements that may appear once
        for (const io::XmlNode& node : root.children()) {
            const std::string& name = node.name();
            if (name == "scene") {
                if (auto ref = read_reference(node, base_dir, options, diagnostics)) {
                    simulation.scenes.push_back(model::SceneEntry{std::move(*ref), {}, {}});
                }
            } else if (name == "options") {
                diagnostics.warning(node.where(),
                                    "element <options> ignored: glint does not use DIRSIG4 "
                                    "simulation options");
            } else if (name == "atmosphericconditions" || name == "platform" ||
                       name == "platformmotion" || name == "tasklist") {
                const auto [it, inserted] = single.emplace(name, node);
                if (!inserted) {
                    diagnostics.error(node.where(), "element <" + name +
                                                        "> given more than once (first at line " +
                                                        std::to_string(it->second.line()) + ")");
                }
            } else {
                diagnostics.warning(node.where(), "unknown element <" + name + "> ignored");
            }
        }

        if (const auto it = single.find("atmosphericconditions"); it != single.end()) {
            if (auto ref = read_reference(it->second, base_dir, options, diagnostics)) {
                model::Plugin plugin;
                plugin.name = "BasicAtmosphere";
                plugin.where = it->second.where();
                plugin.inputs_json = json_text(nlohmann::json{{"atmosphere_filename", ref->text}});
                plugin.basic_atmosphere = model::BasicAtmosphereInputs{std::move(*ref)};
                simulation.plugins.push_back(std::move(plugin));
            }
        }

        model::BasicPlatformInputs inputs;
        bool complete = true;
        const std::pair<const char*, model::FileRef*> parts[] = {
            {"platform", &inputs.platform_file},
            {"platformmotion", &inputs.motion_file},
            {"tasklist", &inputs.tasks_file},
        };
        for (const auto& [name, target] : parts) {
            const auto it = single.find(name);
            if (it == single.end()) {
                diagnostics.error(root.where(),
                                  "missing required element <" + std::string(name) + ">");
                complete = false;
                continue;
            }
            if (auto ref = read_reference(it->second, base_dir, options, diagnostics)) {
                *target = std::move(*ref);
            } else {
                complete = false;
            }
        }
        if (complete) {
            model::Plugin plugin;
            plugin.name = "BasicPlatform";
            plugin.where = single.at("platform").where();
            plugin.inputs_json =
                json_text(nlohmann::json{{"platform_filename", inputs.platform_file.text},
                                         {"motion_filename", inputs.motion_file.text},
                                         {"tasks_filename", inputs.tasks_file.text}});
            plugin.basic_platform = std::move(inputs);
            simulation.plugins.push_back(std::move(plugin));
        }
        document.warn_unread(diagnostics);
    } catch (const Error& error) {
        diagnostics.add(error);
    }
    return simulation;
}

std::vector<model::Simulation> read_simulation(const std::filesystem::path& file,
                                               const ReadOptions& options,
                                               Diagnostics& diagnostics) {
    const std::optional<std::string> read =
        options.read_text_reported(file, file.string(), diagnostics);
    if (!read) return {};
    const std::string& text = *read;
    const char first = first_significant(text);
    if (first == '[' || first == '{') return read_jsim(file, options, diagnostics);
    if (first == '<') return {read_sim(file, options, diagnostics)};
    diagnostics.error(ErrorContext{file.string(), 1, {}},
                      "cannot tell whether this is a .jsim (JSON) or a .sim (XML): expected "
                      "'[', '{' or '<' as the first character");
    return {};
}

}  // namespace glint::dirsig
