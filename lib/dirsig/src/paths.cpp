// SPDX-License-Identifier: Apache-2.0
// PathResolver: expands $NAME / ${NAME} variables ($SCENE_DIR from the scene being read, the
// others from the environment), keeps Windows absolute paths as written (with '/'), and makes
// every other path absolute against the folder of the file that names it.
#include <cctype>
#include <cstdlib>
#include <optional>
#include <string>

#include "glint/core/text.h"
#include "glint/dirsig/read_options.h"

namespace glint::dirsig {
namespace {

/// `path` with `mapping.from` replaced by `mapping.to` when it begins `path` in whole folders
/// (case-insensitively for a Windows path); nullopt when it does not.
std::optional<std::string> mapped_path(const PathMapping& mapping, const std::string& path) {
    const std::string& from = mapping.from;
    if (path.size() < from.size()) return std::nullopt;
    const bool windows = is_windows_absolute(from) || from.rfind("//", 0) == 0;
    for (std::size_t k = 0; k < from.size(); ++k) {
        const char a = path[k];
        const char b = from[k];
        const bool same = windows ? std::tolower(static_cast<unsigned char>(a)) ==
                                        std::tolower(static_cast<unsigned char>(b))
                                  : a == b;
        if (!same) return std::nullopt;
    }
    if (path.size() > from.size() && path[from.size()] != '/' && from.back() != '/') {
        return std::nullopt;
    }
    return mapping.to + path.substr(from.size());
}

bool is_name_start(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }

bool is_name_char(char c) { return is_name_start(c) || (c >= '0' && c <= '9'); }

}  // namespace

bool is_windows_absolute(const std::string& path) {
    if (path.size() >= 3 && is_name_start(path[0]) && path[0] != '_' && path[1] == ':' &&
        (path[2] == '\\' || path[2] == '/')) {
        return true;
    }
    return path.size() >= 3 && path[0] == '\\' && path[1] == '\\' && path[2] != '\\';
}

std::optional<std::string> PathResolver::expand(const std::string& text, const ErrorContext& where,
                                                Diagnostics& diagnostics) const {
    const std::string written(glint::trim(text));
    if (written.empty()) {
        diagnostics.error(where, "expected a file path, got an empty one");
        return std::nullopt;
    }

    // Expand variables; "$$" is not one (it appears in processing arguments) and stays.
    std::string expanded;
    bool ok = true;
    for (std::size_t i = 0; i < written.size();) {
        const char c = written[i];
        if (c != '$' || i + 1 >= written.size()) {
            expanded += c;
            ++i;
            continue;
        }
        if (written[i + 1] == '$') {
            expanded += "$$";
            i += 2;
            continue;
        }
        std::string name;
        std::size_t next = i + 1;
        if (written[next] == '{') {
            const std::size_t close = written.find('}', next + 1);
            name = close == std::string::npos ? std::string()
                                              : written.substr(next + 1, close - next - 1);
            bool valid = !name.empty() && is_name_start(name[0]);
            for (char n : name) valid = valid && is_name_char(n);
            if (!valid) {
                diagnostics.error(where, "malformed variable reference in path " + quote(written) +
                                             ": expected ${NAME} with NAME made of letters, "
                                             "digits and '_'");
                return std::nullopt;
            }
            next = close + 1;
        } else if (is_name_start(written[next])) {
            while (next < written.size() && is_name_char(written[next])) {
                name += written[next];
                ++next;
            }
        } else {
            expanded += c;  // a lone '$' is an ordinary character
            ++i;
            continue;
        }

        std::optional<std::string> value;
        if (name == "SCENE_DIR") {
            if (!scene_dir) {
                diagnostics.error(where,
                                  "$SCENE_DIR used outside a scene file in path " + quote(written));
                ok = false;
            } else {
                value = scene_dir->string();
            }
        } else if (environment) {
            value = environment(name);
        } else if (const char* env = std::getenv(name.c_str())) {
            value = std::string(env);
        }
        if (!value) {
            if (name != "SCENE_DIR") {
                diagnostics.error(where,
                                  "undefined variable $" + name + " in path " + quote(written));
            }
            ok = false;
        } else {
            expanded += *value;
        }
        i = next;
    }
    if (!ok) return std::nullopt;
    if (expanded.empty()) {
        diagnostics.error(where, "path " + quote(written) + " expands to an empty path");
        return std::nullopt;
    }
    return expanded;
}

PathMapping PathMapping::parse(const std::string& text) {
    const std::size_t eq = text.find('=');
    PathMapping mapping;
    if (eq != std::string::npos) {
        mapping.from = text.substr(0, eq);
        mapping.to = text.substr(eq + 1);
    }
    for (char& c : mapping.from) {
        if (c == '\\') c = '/';
    }
    while (mapping.from.size() > 1 && mapping.from.back() == '/') mapping.from.pop_back();
    if (eq == std::string::npos || mapping.from.empty() || mapping.to.empty()) {
        throw usage_error("--path-map " + quote(text) +
                          ": expected FROM=TO, e.g. C:/DIRSIG=/data/dirsig");
    }
    // A relative TO is relative to the folder glint runs in, as any path on its command line.
    std::error_code ec;
    const std::filesystem::path to = std::filesystem::absolute(mapping.to, ec);
    if (!ec) mapping.to = to.generic_string();
    return mapping;
}

model::FileRef PathResolver::resolve(const std::string& text, const std::filesystem::path& base_dir,
                                     const ErrorContext& where, Diagnostics& diagnostics) const {
    model::FileRef ref;
    ref.text = text;
    ref.where = where;
    std::optional<std::string> expanded = expand(text, where, diagnostics);
    if (!expanded) return ref;

    // Paths written on Windows use '\\'; glint writes '/' everywhere.
    bool windows = is_windows_absolute(*expanded);
    for (char& c : *expanded) {
        if (c == '\\') c = '/';
    }
    for (const PathMapping& mapping : path_map) {
        if (const std::optional<std::string> mapped = mapped_path(mapping, *expanded)) {
            *expanded = *mapped;
            windows = is_windows_absolute(*expanded);
            break;
        }
    }
    if (windows) {
        ref.resolved = std::filesystem::path(*expanded);
        return ref;
    }

    std::filesystem::path path(*expanded);
    if (path.is_relative()) path = base_dir / path;
    if (path.is_relative()) {
        std::error_code ec;
        std::filesystem::path absolute = std::filesystem::absolute(path, ec);
        if (!ec) path = absolute;
    }
    ref.resolved = path.lexically_normal();
    return ref;
}

std::string ReadOptions::read_text(const std::filesystem::path& file,
                                   const std::string& display_name) const {
    if (files) return files->text(file, display_name);
    return io::read_input_file(file, display_name);
}

std::optional<std::string> ReadOptions::read_text_reported(const std::filesystem::path& file,
                                                           const std::string& display_name,
                                                           Diagnostics& diagnostics) const {
    try {
        return read_text(file, display_name);
    } catch (const Error& error) {
        diagnostics.add(error);
        return std::nullopt;
    }
}

}  // namespace glint::dirsig
