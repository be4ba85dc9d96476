// SPDX-License-Identifier: Apache-2.0
// How the readers resolve and read files: variables ($SCENE_DIR, $DIRSIG_HOME, ${NAME}),
// Windows absolute paths, and paths relative to the file that names them.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/diagnostics.h"
#include "glint/io/input_files.h"
#include "glint/model/common.h"

namespace glint::dirsig {

/// Resolves the paths written in input files.
///   - `$NAME` and `${NAME}` are variables. `$SCENE_DIR` is the folder holding the `.scene`
///     file being read (`scene_dir`; an error where no scene is being read); any other comes
///     from `environment`; an unset variable is an error naming it.
///   - A Windows absolute path (`C:\…`, `C:/…`, `\\server\…`) is kept as written (with `\`
///     turned into `/`) and counts as absolute: it will not exist here, which the caller
///     reports when it needs the file.
///   - Anything else relative is taken relative to `base_dir` (the folder of the file that
///     names it); the result is absolute and lexically normalised.
///   - Before that, the first `path_map` entry whose `from` begins the expanded path (whole
///     folders; case-insensitive for a Windows path) replaces it with its `to`: a simulation
///     written on Windows (`C:/DIRSIG/scenes/a.scene`) runs here with
///     `--path-map C:/DIRSIG=/data/dirsig`.
struct PathMapping {
    std::string from;  ///< '/' separators, no trailing '/'
    std::string to;

    /// "FROM=TO" (the tools' --path-map); a backslash in FROM is read as '/', a relative TO
    /// is made absolute against the current folder. Throws glint::Error (usage) without '='
    /// or with an empty FROM or TO.
    static PathMapping parse(const std::string& text);
};

struct PathResolver {
    /// Variable lookup; defaults to the process environment.
    std::function<std::optional<std::string>(const std::string&)> environment;
    /// Value of $SCENE_DIR, when a scene file is being read.
    std::optional<std::filesystem::path> scene_dir;
    /// Folder prefixes replaced before a path is resolved (PathMapping), first match wins.
    std::vector<PathMapping> path_map;

    /// A FileRef for `text` named at `where` in a file whose folder is `base_dir`. Problems
    /// (unset variable, empty path) go to `diagnostics` and give an empty `resolved`.
    model::FileRef resolve(const std::string& text, const std::filesystem::path& base_dir,
                           const ErrorContext& where, Diagnostics& diagnostics) const;

    /// `text` trimmed, with its variables expanded (separators left as written); nullopt
    /// after reporting an empty path or an unset or malformed variable. resolve() starts here.
    std::optional<std::string> expand(const std::string& text, const ErrorContext& where,
                                      Diagnostics& diagnostics) const;
};

/// Default ReadOptions::max_instances: 10⁶ instances (about 0.6 GB while a glist expands).
inline constexpr std::uint64_t kDefaultMaxInstances = 1'000'000;

/// What every reader takes besides the file.
struct ReadOptions {
    PathResolver paths;
    /// The record of the load these options serve, shared by every copy (sub-readers copy
    /// the options): each file is opened once and every open is logged. Null: files are read
    /// directly, unrecorded.
    std::shared_ptr<io::InputFiles> files;
    /// The most instances a glist may expand to once nested glists are placed (each
    /// including instance places every instance of the glist it names, so a few small files
    /// can describe 10⁷): counted before any is built; more is an error. The tools'
    /// --max-instances sets it.
    std::uint64_t max_instances = kDefaultMaxInstances;

    /// The whole text of `file` (through `files` when set), named `display_name` in errors.
    /// Throws glint::Error as io::read_input_file does.
    std::string read_text(const std::filesystem::path& file,
                          const std::string& display_name = {}) const;
    /// read_text, with the error it would throw added to `diagnostics` instead (nullopt).
    std::optional<std::string> read_text_reported(const std::filesystem::path& file,
                                                  const std::string& display_name,
                                                  Diagnostics& diagnostics) const;
};

/// True for `C:\x`, `C:/x`, `\\server\x`.
bool is_windows_absolute(const std::string& path);

}  // namespace glint::dirsig
