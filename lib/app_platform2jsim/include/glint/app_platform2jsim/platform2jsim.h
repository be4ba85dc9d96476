// SPDX-License-Identifier: Apache-2.0
// `glint-platform2jsim`: converts DIRSIG4 inputs into a DIRSIG5 `.jsim`, checks a simulation
// and every file it references, and dumps platforms as normalized JSON. Modes:
//   convert   INPUT.sim (or .jsim) -o OUT.jsim        the simulation, paths rewritten
//   parts     --platform P --motion M --tasks T [--scene S] [--atmosphere A] -o OUT.jsim
//   append    the same parts, added as another BasicPlatform to the existing -o OUT.jsim
//   check     --check FILE...                        every error and warning, a summary line
//   dump      --dump-platform FILE [-o OUT.json]      the "glint-platform" JSON
// Every mode reads all its inputs first and reports every problem through ctx.log; any
// error means exit status 1 and nothing written. Outputs are written atomically; `-o -` is
// stdout; an output naming one of the inputs is refused (usage error).
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "glint/core/context.h"
#include "glint/dirsig/read_options.h"

namespace glint::app_platform2jsim {

/// What the tool does.
enum class Mode { convert, parts, append, check, dump_platform };

/// Options of every mode (each mode uses the fields its comment names).
struct Options {
    Mode mode = Mode::convert;
    /// convert: the `.sim`/`.jsim`; dump_platform: a `.platform`, `.sim` or `.jsim`.
    std::filesystem::path input;
    /// check: `.sim`, `.jsim`, `.platform` or `.tasks` files (told apart by extension; other
    /// extensions are read as simulations, whose format is told by content).
    std::vector<std::filesystem::path> check_files;
    /// parts, append: the BasicPlatform's files (relative to the working folder).
    std::filesystem::path platform;
    std::filesystem::path motion;
    std::filesystem::path tasks;
    /// parts: the scene_list entry and the BasicAtmosphere plugin, when given.
    std::optional<std::filesystem::path> scene;
    std::optional<std::filesystem::path> atmosphere;
    /// convert, parts, append: BasicPlatform inputs written as given (convert: on every
    /// BasicPlatform entry of the input).
    std::optional<std::string> output_folder;
    std::optional<std::string> output_prefix;
    bool split_channels = false;
    /// The output file; "-" is `out`. Required for convert, parts and append (append: the
    /// existing `.jsim`, rewritten); dump_platform: empty also means `out`; check: unused.
    std::string output;
    /// check: --allow-processing, as glint-render's: every processing program counts as
    /// allowed. Otherwise a task glint-render would refuse is an error of the check.
    bool allow_processing = false;
    /// How referenced paths are resolved ($VARIABLES from the environment by default).
    dirsig::ReadOptions read_options;
};

/// Runs the mode. Data goes to `out` (`-o -`, the dump without -o, the check summary);
/// diagnostics go to ctx.log as "file:line: element: message". Returns 0 on success and 1
/// when an input has errors (after logging all of them). Throws glint::Error (usage) for
/// options that do not fit the mode or an output that names an input, (io) when the
/// output cannot be written.
int run(const Options& options, Context& ctx, std::ostream& out);

}  // namespace glint::app_platform2jsim
