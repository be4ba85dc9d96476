// SPDX-License-Identifier: Apache-2.0
// What a simulation (.jsim or .sim, glint/model/simulation.h) renders with: its atmosphere
// (the file of its BasicAtmosphere plugin, or the embedded default when it names none) and
// its scene (every scene_list entry read with read_scene and merged into one). Like every
// reader these report each problem to `diagnostics` and carry on; the caller fails
// when diagnostics has errors.
//
// Merging scenes (merge_scene), in scene_list order:
//
// clang-format off
// | part | rule |
// |---|---|
// | origin | the first scene with an origin sets it; a later, different origin is a warning (the first is kept) |
// | materials | appended; an id already merged is an error at the later definition, naming the earlier one's file:line ("material id \"1\" is already defined at a.mat:2") (the same definition — one `.mat` shared by two scenes — is merged once, silently) |
// | objects | appended; their triangles' material indices follow the merged material list |
// | instances | appended; object indices follow the merged object list |
// | property maps | appended after the earlier scenes' maps; their material indices follow the merged material list |
// | scene_list offset | not applied: a warning unless empty or all zeros |
// clang-format on
#pragma once

#include <filesystem>
#include <string>

#include "glint/core/diagnostics.h"
#include "glint/core/log.h"
#include "glint/dirsig/read_options.h"
#include "glint/model/atmosphere.h"
#include "glint/model/scene.h"
#include "glint/model/simulation.h"

namespace glint::inputs {

using dirsig::ReadOptions;

/// Reads a scene of either kind: a DIRSIG `.scene` (extension `.scene`, or text whose first
/// non-blank character is `<`) or a glint YAML scene (anything else).
model::Scene read_scene(const std::filesystem::path& file, const ReadOptions& options,
                        Diagnostics& diagnostics);

/// Reads an atmosphere file of either kind: a DIRSIG `.atm` (text starting with `<` after
/// blanks and a BOM) or a glint YAML atmosphere. Problems go to `diagnostics` with file:line;
/// a file that cannot be read throws glint::Error (io). `display_name` names the file in
/// messages (default: the path).
model::Atmosphere read_atmosphere(const std::filesystem::path& path, const ReadOptions& options,
                                  Diagnostics& diagnostics, const std::string& display_name = {});

/// The embedded default atmosphere: model parametric with its default parameters
/// (glint/model/atmosphere.h), used when a simulation names no atmosphere.
model::Atmosphere default_atmosphere();

/// The first plugin of `simulation` that glint does not run and whose name says atmosphere
/// (dirsig::plugin_kind: "NewAtmosphere"); nullptr when there is none.
const model::Plugin* unsupported_atmosphere_plugin(const model::Simulation& simulation);

/// Why `simulation` gets the default atmosphere, for a message: "demo.jsim names none", or,
/// when it has a plugin glint does not run whose name says atmosphere, "demo.jsim's
/// NewAtmosphere plugin is not supported".
std::string default_atmosphere_reason(const model::Simulation& simulation);

/// An atmosphere given in place of the simulation's (glint-render --atmosphere).
struct AtmosphereOverride {
    enum class Kind {
        none,        ///< model none: exo-atmospheric sun, black sky
        parametric,  ///< default_atmosphere()
        file,        ///< an atmosphere file (read_atmosphere), relative to the working folder
    };
    Kind kind = Kind::parametric;
    std::filesystem::path file;  ///< Kind::file
};

/// Parses --atmosphere's value: "none", "parametric" or an atmosphere file (a file named
/// "none" or "parametric" is written "./none"). Throws glint::Error (usage) for "" and "-".
AtmosphereOverride parse_atmosphere_override(const std::string& text);

/// The atmosphere `choice` gives: model none, the default, or its file read with
/// read_atmosphere. A file that does not exist or is a folder is an error at "--atmosphere";
/// its problems go to `diagnostics` at their file:line; on error the default is returned.
model::Atmosphere read_atmosphere_override(const AtmosphereOverride& choice,
                                           const ReadOptions& options, Diagnostics& diagnostics);

/// The BasicAtmosphere plugin whose file `simulation` uses: the first one; each further one
/// is a warning at its plugin entry (it is ignored). nullptr when there is none.
const model::Plugin* used_atmosphere_plugin(const model::Simulation& simulation,
                                            Diagnostics& diagnostics);

/// Reads the atmosphere of `simulation`: the file named by the `atmosphere_filename` of its
/// first BasicAtmosphere plugin (read_atmosphere: YAML or DIRSIG `.atm`). When it has no
/// BasicAtmosphere plugin, default_atmosphere() (a debug message on `log`, no diagnostic).
/// A file that does not exist, is a folder or cannot be read is an error at the plugin's
/// `atmosphere_filename`; further BasicAtmosphere plugins are a warning (not read). On
/// error the default is returned alongside the diagnostics.
model::Atmosphere read_simulation_atmosphere(const model::Simulation& simulation,
                                             const ReadOptions& options, Diagnostics& diagnostics,
                                             const Log& log = {});

/// Appends `part` to `scene` by the rules in the table above. `scene.file` becomes
/// `part.file` when it is empty.
void merge_scene(model::Scene& scene, model::Scene part, Diagnostics& diagnostics);

/// A warning at the entry when its `offset` is neither empty nor all zeros (offsets are not
/// applied).
void check_scene_offset(const model::SceneEntry& entry, Diagnostics& diagnostics);

/// Told what a simulation's scene and atmosphere files held as they are read (glint-platform2jsim
/// --check reports it file by file).
class ReadObserver {
public:
    virtual ~ReadObserver() = default;
    /// A scene_list file that exists was read: the errors found in it (and in the files it
    /// names) and the scene it holds (partial when `errors` > 0).
    virtual void scene_read(const std::filesystem::path& file, std::size_t errors,
                            const model::Scene& scene) = 0;
    /// The atmosphere of `simulation`: its file (nullptr: the default, no BasicAtmosphere
    /// file) and the errors found in it. Not called when the file does not exist.
    virtual void atmosphere_read(const model::Simulation& simulation, const model::FileRef* file,
                                 std::size_t errors, const model::Atmosphere& atmosphere) = 0;
};

/// Whether `ref` names an existing file; otherwise an error at `ref.where`, "<role> file does
/// not exist: PATH" (or "<role> path is a folder ..."), unless an error is reported there
/// already (the reader of a `.sim` checks its references itself). `role`: "scene", "motion"...
bool existing_file(const model::FileRef& ref, const std::string& role, Diagnostics& diagnostics);

/// Reads every scene_list entry of `simulation` with read_scene and merges them in order
/// (merge_scene). A file that does not exist or is a folder is an error at its entry. An
/// empty scene_list gives an empty scene (no origin, no objects). `observer`, when given, is
/// told each file read.
model::Scene read_simulation_scene(const model::Simulation& simulation, const ReadOptions& options,
                                   Diagnostics& diagnostics, ReadObserver* observer = nullptr);

}  // namespace glint::inputs
