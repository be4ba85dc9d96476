// SPDX-License-Identifier: Apache-2.0
// Which programs a simulation's processing tasks may start. A .platform is data someone may
// hand you, and a <program> in it would run as you: so glint runs by default only the
// programs the BasicPlatform manual's examples need (DIRSIG's image_tool and demosaic, or
// glint-envi and glint-demosaic standing for them, and ffmpeg), and only with arguments that
// stay in the output folder; any other program, or those with other arguments, runs only
// when the user allows it — --allow-processing for one run, or an entry in an allow-list
// file that lives outside every simulation (in the user's configuration folder).
// docs/processing.md ("Which programs run") is the reference.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "glint/core/error.h"

namespace glint::process {

/// The name of the allow-list file in glint's configuration folder.
inline constexpr const char* kAllowListName = "allowed-programs";

/// One entry of the allow-list file.
struct AllowedProgram {
    std::string entry;  ///< a program name as <program> writes it ("convert"), or an absolute path
    /// For a path: its canonical form (symbolic links resolved); empty when it does not exist.
    std::filesystem::path canonical;
    ErrorContext where;  ///< the entry's file:line
};

/// What the user allows processing tasks to run.
struct ProcessingTrust {
    /// --allow-processing: every program, with any arguments.
    bool allow_all = false;
    /// The allow-list file looked for (named in refusals), empty when none applies.
    std::filesystem::path allow_list;
    /// Its entries: each program runs with any arguments.
    std::vector<AllowedProgram> allowed;
    /// What the file holds that allows nothing (a path naming no file here), each with its
    /// file:line, for the caller to log as warnings.
    std::vector<std::pair<ErrorContext, std::string>> warnings;
};

/// True for the program names that run without the user's permission: image_tool,
/// demosaic, ffmpeg, glint-envi and glint-demosaic, written as a bare name (found on PATH,
/// or glint's tool standing for the DIRSIG name).
bool is_default_program(const std::string& program);

/// "image_tool, demosaic, ffmpeg, glint-envi and glint-demosaic", for messages and docs.
std::string default_programs_text();

/// Why an argument of a default program is not run without permission — it holds a
/// character other than letters, digits and `_ . / = : , + % @ -` (a filter graph, a shell
/// word, a control), an absolute path, a `..` component or a URL or protocol (`scheme:`), in
/// the whole argument or any of its `=`- or `,`-separated parts — or nullopt when it stays in
/// the folder the task runs in.
std::optional<std::string> argument_problem(const std::string& argument);

/// Where the allow-list is looked for, from the environment's values (nullptr when unset or
/// empty): $GLINT_ALLOWED_PROGRAMS, else $XDG_CONFIG_HOME/glint/allowed-programs, else
/// $HOME/.config/glint/allowed-programs; empty when none of the three is set.
std::filesystem::path allow_list_path(const char* glint_allowed_programs,
                                      const char* xdg_config_home, const char* home);

/// allow_list_path of this process's environment (for the tools' entry points).
std::filesystem::path allow_list_from_environment();

/// Reads the allow-list `file`: one program per line, a bare name or an absolute path; blank
/// lines and text after '#' ignored. No file there is an empty list. A path that names no
/// file here allows nothing and is a warning (ProcessingTrust::warnings). Throws glint::Error
/// (input) at file:line for a relative path entry, and for a file others could have written
/// (not a regular file; owned by another user than the one running glint or root; writable
/// by its group or by anyone), as ssh refuses such a configuration.
ProcessingTrust read_allow_list(const std::filesystem::path& file);

/// Why a task may not run its command under `trust`, or nullopt when it may. `program` is the
/// <program> as written (after $$IMG_BASENAME$$), `resolved` the file that would run, and
/// `arguments` the arguments after substitution.
std::optional<std::string> refusal(const std::string& program,
                                   const std::filesystem::path& resolved,
                                   const std::vector<std::string>& arguments,
                                   const ProcessingTrust& trust);

}  // namespace glint::process
