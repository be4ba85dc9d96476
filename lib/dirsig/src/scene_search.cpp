// SPDX-License-Identifier: Apache-2.0
// Where the files a `.scene` and its glists name are looked for: the scene's geometry
// (`gdbdirectory`) and object (`odbdirectory`) database directories, the folder of the file
// that names a path, and the `search_paths="local"` attribute that keeps a bundle's paths
// beside its own glist. docs/scene.md ("Paths") has the rules as a table.
#include <algorithm>

#include "glint/core/text.h"
#include "glist_parts.h"

namespace glint::dirsig::detail {
namespace {

bool is_file(const std::filesystem::path& path) {
    std::error_code ec;
    return std::filesystem::is_regular_file(path, ec);
}

/// Warns once per load for each `kind` of guess.
void warn_once(SceneLoad& load, const std::string& kind, const ErrorContext& where,
               const std::string& message, Diagnostics& diagnostics) {
    if (!load.warned.insert(kind).second) return;
    diagnostics.warning(where, message + " (warned once per scene)");
}

}  // namespace

bool search_paths_local(const io::XmlNode& node, Diagnostics& diagnostics) {
    const auto value = node.attribute("search_paths");
    if (!value) return false;
    if (*value == "local") return true;
    diagnostics.warning(node.where_attribute("search_paths"),
                        "search_paths " + quote(*value) +
                            " is not known, expected \"local\"; the database directories are "
                            "searched");
    return false;
}

void read_database_dirs(const io::XmlNode& root, const std::filesystem::path& base_dir,
                        const ReadOptions& options, SceneLoad& load, Diagnostics& diagnostics) {
    for (const std::string_view name : {"gdbdirectory", "odbdirectory"}) {
        for (const io::XmlNode& node : root.children(name)) {
            const model::FileRef ref =
                options.paths.resolve(node.text(), base_dir, node.where(), diagnostics);
            if (ref.resolved.empty()) continue;
            std::error_code ec;
            if (!std::filesystem::is_directory(ref.resolved, ec)) {
                diagnostics.warning(node.where(), "folder " + ref.resolved.string() +
                                                      " does not exist (not searched)");
                continue;
            }
            auto& dirs = name == "gdbdirectory" ? load.gdb_dirs : load.odb_dirs;
            if (std::find(dirs.begin(), dirs.end(), ref.resolved) == dirs.end()) {
                dirs.push_back(ref.resolved);
            }
        }
    }
}

model::FileRef find_file(const std::string& text, const std::filesystem::path& base_dir, bool local,
                         FileKind kind, std::string_view what, const ErrorContext& where,
                         const ReadOptions& options, SceneLoad& load, Diagnostics& diagnostics) {
    model::FileRef ref = options.paths.resolve(text, base_dir, where, diagnostics);
    if (ref.resolved.empty()) return ref;
    const std::string label = std::string(what) + " " + std::string(trim(text));
    const std::optional<std::string> expanded = options.paths.expand(text, where, diagnostics);
    std::string relative = expanded.value_or("");
    for (char& c : relative) {
        if (c == '\\') c = '/';
    }
    const bool searched = expanded && !is_windows_absolute(*expanded) &&
                          std::filesystem::path(relative).is_relative() && !local &&
                          kind != FileKind::plain &&
                          !(load.gdb_dirs.empty() && load.odb_dirs.empty());
    if (!searched) {
        if (!is_file(ref.resolved)) {
            diagnostics.error(where, label + " not found (" + ref.resolved.string() + ")");
            ref.resolved.clear();
        }
        return ref;
    }

    // Database directories in the order of the kind, then the naming file's folder.
    std::vector<std::filesystem::path> dirs;
    const auto& first = kind == FileKind::glist ? load.odb_dirs : load.gdb_dirs;
    const auto& second = kind == FileKind::glist ? load.gdb_dirs : load.odb_dirs;
    for (const auto* list : {&first, &second}) {
        for (const std::filesystem::path& dir : *list) {
            if (std::find(dirs.begin(), dirs.end(), dir) == dirs.end()) dirs.push_back(dir);
        }
    }
    std::vector<std::filesystem::path> tried;
    for (const std::filesystem::path& dir : dirs) {
        const std::filesystem::path candidate = (dir / relative).lexically_normal();
        if (std::find(tried.begin(), tried.end(), candidate) != tried.end()) continue;
        tried.push_back(candidate);
        if (!is_file(candidate)) continue;
        if (candidate != ref.resolved && is_file(ref.resolved)) {
            warn_once(load, "shadowed", where,
                      label + " is taken from the database directory (" + candidate.string() +
                          "), not from beside this file (" + ref.resolved.string() +
                          "); search_paths=\"local\" selects the other",
                      diagnostics);
        }
        ref.resolved = candidate;
        return ref;
    }
    if (is_file(ref.resolved)) {
        warn_once(load, "fallback", where,
                  label +
                      " is not in the scene's database directories; it is taken from "
                      "beside the file that names it (" +
                      ref.resolved.string() + ")",
                  diagnostics);
        return ref;
    }
    if (std::find(tried.begin(), tried.end(), ref.resolved) == tried.end()) {
        tried.push_back(ref.resolved);
    }
    std::string places;
    for (const std::filesystem::path& p : tried)
        places += (places.empty() ? "" : ", ") + p.string();
    diagnostics.error(where, label + " not found (tried " + places + ")");
    ref.resolved.clear();
    return ref;
}

}  // namespace glint::dirsig::detail
