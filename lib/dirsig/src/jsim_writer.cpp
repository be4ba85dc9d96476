// SPDX-License-Identifier: Apache-2.0
// The `.jsim` writer: simulations as DIRSIG5 JSON, with file paths rewritten relative to the
// folder the .jsim will be written to (so that reading it back resolves them to the same
// files), Windows paths and unresolved paths kept as written. Other plugins are kept as read
// but for their relative paths, rewritten the same way (relativize_paths says which).
#include <nlohmann/json.hpp>

#include "glint/core/json_text.h"
#include "glint/core/text.h"
#include "glint/dirsig/readers.h"
#include "jsim_keys.h"

namespace glint::dirsig {
namespace {

using OrderedJson = nlohmann::ordered_json;

/// `path` relative to `folder` when they share more than the root (e.g. "../data/x.ppd"),
/// else absolute. Both are absolute and lexically normal.
std::string relative_or_absolute(const std::filesystem::path& path,
                                 const std::filesystem::path& folder) {
    std::size_t common = 0;
    auto a = path.begin();
    auto b = folder.begin();
    for (; a != path.end() && b != folder.end() && *a == *b; ++a, ++b) ++common;
    if (common <= 1 || path.root_path() != folder.root_path()) return path.generic_string();
    const std::filesystem::path relative = path.lexically_relative(folder);
    if (relative.empty()) return path.generic_string();
    return relative.generic_string();
}

std::string write_path(const model::FileRef& ref, const std::filesystem::path& folder) {
    std::string text;
    if (ref.resolved.empty() || is_windows_absolute(ref.resolved.generic_string()) ||
        ref.resolved.is_relative()) {
        text = ref.text;  // unresolved (e.g. undefined variable), or kept as written
    } else {
        text = relative_or_absolute(ref.resolved.lexically_normal(), folder);
    }
    // JSON holds UTF-8 only: a name in another encoding (a Latin-1 "é" from an old .sim)
    // cannot be written so that it reads back as the same file.
    if (!is_valid_utf8(text)) {
        throw input_error("the file name " + quote(ref.text) +
                              " is not UTF-8, and a .jsim (JSON) can only name files in UTF-8: "
                              "rename the file (e.g. convmv -f latin1 -t utf8) or run the .sim "
                              "directly",
                          ref.where);
    }
    return text;
}

OrderedJson parse_kept(const std::string& json, const char* what) {
    if (json.empty()) return OrderedJson::object();
    try {
        return OrderedJson::parse(json);
    } catch (const nlohmann::json::exception& error) {
        throw internal_error(std::string("kept ") + what + " is not valid JSON: " + error.what());
    }
}

OrderedJson platform_inputs(const model::Plugin& plugin, const std::filesystem::path& folder) {
    const model::BasicPlatformInputs& in = *plugin.basic_platform;
    OrderedJson out = OrderedJson::object();
    out[kPlatformFilename] = write_path(in.platform_file, folder);
    out[kMotionFilename] = write_path(in.motion_file, folder);
    out[kTasksFilename] = write_path(in.tasks_file, folder);
    if (in.output_folder) out[kOutputFolder] = *in.output_folder;
    if (in.output_prefix) out[kOutputPrefix] = *in.output_prefix;
    out[kSplitChannels] = in.split_channels.value_or(false);
    // Keys glint does not know (warned about when read) are carried over unchanged.
    const OrderedJson kept = parse_kept(plugin.inputs_json, "plugin inputs");
    if (kept.is_object()) {
        for (const auto& [key, value] : kept.items()) {
            if (!out.contains(key)) out[key] = value;
        }
    }
    return out;
}

OrderedJson atmosphere_inputs(const model::Plugin& plugin, const std::filesystem::path& folder) {
    OrderedJson out = OrderedJson::object();
    out[kAtmosphereFilename] = write_path(plugin.basic_atmosphere->atmosphere_file, folder);
    const OrderedJson kept = parse_kept(plugin.inputs_json, "plugin inputs");
    if (kept.is_object()) {
        for (const auto& [key, value] : kept.items()) {
            if (!out.contains(key)) out[key] = value;
        }
    }
    return out;
}

/// Whether a key of another plugin's inputs names files: it ends in "filename", "filenames",
/// "_file" or "_files" (any case), as DIRSIG's own keys do ("atmosphere_filename").
bool is_path_key(const std::string& key) {
    const std::string lower = to_lower(key);
    for (const std::string_view ending : {"filename", "filenames", "_file", "_files"}) {
        if (lower.size() >= ending.size() &&
            lower.compare(lower.size() - ending.size(), ending.size(), ending) == 0) {
            return true;
        }
    }
    return false;
}

/// A path as written that is relative to the file naming it: not empty, not absolute (POSIX
/// or Windows), no variable (`$`), one line.
bool is_plain_relative(const std::string& text) {
    return !text.empty() && text.size() < 4096 && text.find('$') == std::string::npos &&
           text.find('\n') == std::string::npos && !is_windows_absolute(text) &&
           std::filesystem::path(text).is_relative();
}

/// Rewrites, in another plugin's inputs, every relative path (is_plain_relative) that is the
/// value of a path key (is_path_key; in an array under one too) or names an existing file
/// from `base` (the folder of the .jsim read), relative to `folder` (relative_or_absolute).
/// Absolute paths, variables and other values are kept as written.
void relativize_paths(OrderedJson& value, bool path_key, const std::filesystem::path& base,
                      const std::filesystem::path& folder) {
    if (value.is_object()) {
        for (auto& [key, member] : value.items()) {
            relativize_paths(member, is_path_key(key), base, folder);
        }
    } else if (value.is_array()) {
        for (OrderedJson& element : value) relativize_paths(element, path_key, base, folder);
    } else if (value.is_string()) {
        const std::string text = value.get<std::string>();
        if (!is_plain_relative(text)) return;
        const std::filesystem::path resolved = (base / text).lexically_normal();
        std::error_code ec;
        if (!path_key && !std::filesystem::is_regular_file(resolved, ec)) return;
        value = relative_or_absolute(resolved, folder);
    }
}

/// The absolute folder of the file a simulation was read from (its relative paths count from
/// there); empty when the simulation names no file.
std::filesystem::path base_folder(const model::Simulation& simulation) {
    if (simulation.file.empty()) return {};
    std::error_code ec;
    const std::filesystem::path file = std::filesystem::absolute(simulation.file, ec);
    if (ec) return {};
    return file.lexically_normal().parent_path();
}

OrderedJson other_inputs(const model::Plugin& plugin, const std::filesystem::path& base,
                         const std::filesystem::path& folder) {
    OrderedJson out = parse_kept(plugin.inputs_json, "plugin inputs");
    if (!base.empty()) relativize_paths(out, false, base, folder);
    return out;
}

}  // namespace

std::string format_jsim(const std::vector<model::Simulation>& simulations,
                        const std::filesystem::path& output_folder) {
    std::filesystem::path folder =
        output_folder.empty() ? std::filesystem::path(".") : output_folder;
    std::error_code ec;
    if (const std::filesystem::path absolute = std::filesystem::absolute(folder, ec); !ec) {
        folder = absolute;
    }
    folder = folder.lexically_normal();
    if (folder.has_relative_path() && folder.filename().empty()) folder = folder.parent_path();

    OrderedJson document = OrderedJson::array();
    for (const model::Simulation& simulation : simulations) {
        OrderedJson scenes = OrderedJson::array();
        for (const model::SceneEntry& scene : simulation.scenes) {
            OrderedJson entry = {{"inputs", write_path(scene.file, folder)}};
            if (!scene.offset.empty()) entry["offset"] = scene.offset;
            scenes.push_back(std::move(entry));
        }
        const std::filesystem::path base = base_folder(simulation);
        OrderedJson plugins = OrderedJson::array();
        for (const model::Plugin& plugin : simulation.plugins) {
            OrderedJson entry = OrderedJson::object();
            entry["name"] = plugin.name;
            if (plugin.basic_platform) {
                entry["inputs"] = platform_inputs(plugin, folder);
            } else if (plugin.basic_atmosphere) {
                entry["inputs"] = atmosphere_inputs(plugin, folder);
            } else {
                entry["inputs"] = other_inputs(plugin, base, folder);
            }
            plugins.push_back(std::move(entry));
        }
        OrderedJson object = OrderedJson::object();
        object["scene_list"] = std::move(scenes);
        object["plugin_list"] = std::move(plugins);
        object["medium_list"] = simulation.medium_list_json.empty()
                                    ? OrderedJson::array()
                                    : parse_kept(simulation.medium_list_json, "medium_list");
        document.push_back(std::move(object));
    }
    return json_text(document, 2) + "\n";
}

}  // namespace glint::dirsig
