// SPDX-License-Identifier: Apache-2.0
// Runs a focal plane's processing tasks (the DIRSIG5 BasicPlatform manual's "Inline
// Processing") at the events glint-render fires (glint/model/processing.h): each task's
// program with its arguments, $$IMG_BASENAME$$ replaced by the name of the event's image file
// without its extension, in the image file's folder, through run_process (an argv vector, no
// shell, stdin from /dev/null, its own process group, a timeout, killed with the render on an
// interrupt); its output goes to the log under the task's name; `<removefile>` deletes the
// image (data file and header) after the event's tasks have run. DIRSIG's `image_tool` and
// `demosaic` stand for glint-envi and glint-demosaic when no program of that name is on PATH.
// Which programs may run at all is the user's to allow (glint/process/trust.h); each command
// is logged at notice level (shown at normal verbosity) as it starts.
// docs/processing.md is the reference.
#pragma once

#include <chrono>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "glint/core/context.h"
#include "glint/model/processing.h"
#include "glint/process/trust.h"

namespace glint::process {

/// The placeholder the manual defines: the radiometric image file's name without extension.
inline constexpr const char* kImageBasename = "$$IMG_BASENAME$$";

/// Default --processing-timeout: an hour per task.
inline constexpr std::chrono::seconds kDefaultTaskTimeout{3600};

/// How processing tasks run.
struct ProcessingOptions {
    /// Wall-clock limit of one task (--processing-timeout); nullopt: none.
    std::optional<std::chrono::milliseconds> timeout = kDefaultTaskTimeout;
    /// --keep-going: a task that fails is a warning and the render goes on.
    bool keep_going = false;
    /// Where glint-envi and glint-demosaic are looked for first (glint-render's own folder);
    /// empty: PATH only.
    std::filesystem::path tools_dir;
    /// The PATH searched for programs; nullopt: the environment's.
    std::optional<std::string> path;
    /// --allow-processing: every program a task names may run, with any arguments.
    bool allow_all = false;
    /// The allow-list file (allow_list_path; empty: none), read when a task is first
    /// checked. Without either, only glint's default programs run, with arguments that stay
    /// in the output folder (glint/process/trust.h).
    std::filesystem::path allow_list;
};

/// `text` with every $$IMG_BASENAME$$ replaced by `basename` (as one argument, whatever it
/// holds: nothing is split or interpreted).
std::string substitute_basename(const std::string& text, const std::string& basename);

/// A task's command at one event: the program found and the whole argv.
struct TaskCommand {
    std::filesystem::path program;  ///< absolute path of what runs
    std::vector<std::string> argv;  ///< argv[0] = program's path, then the arguments
    /// Set when a DIRSIG program name was replaced by a glint tool ("image_tool" →
    /// glint-envi): the name written in the task.
    std::string stands_for;
    /// Why the user's trust does not cover this command (glint/process/trust.h); it is not
    /// run. nullopt: it may run.
    std::optional<std::string> refusal;
};

/// Runs the processing tasks of a render.
class ProcessingRunner {
public:
    ProcessingRunner(ProcessingOptions options, const Context& context);

    /// Checks the events a render will fire before it starts: a program found nowhere, a
    /// program the user has not allowed (even with keep_going), a `<removefile>` at an event whose
    /// image is not complete then (e.g. capture_completed of a file holding every capture) are
    /// errors at the task's file:line (with keep_going a missing program is a warning and its task
    /// is skipped); $$IMG_BASENAME$$ at such an event is one warning per task. Throws glint::Error
    /// (input) after logging every problem.
    void check(const std::vector<model::ProcessingEvent>& events);

    /// Runs the event's tasks in order, then removes its image when one of them asks to.
    /// Throws glint::Error (runtime) for a task that fails (unless keep_going: a warning),
    /// (cancelled) when the render is interrupted meanwhile (the task is killed).
    void run(const model::ProcessingEvent& event);

    /// The command a task runs at an event (for --dry-run), with its refusal when the user
    /// has not allowed it. Throws glint::Error (input) when its program is found nowhere.
    TaskCommand command(const model::ProcessingTask& task, const model::ProcessingEvent& event);

    /// The command a task would run at any event, $$IMG_BASENAME$$ left in place (for
    /// glint-platform2jsim --check); its refusal judged with a plain name in its place.
    /// Throws glint::Error (input) when its program is found nowhere.
    TaskCommand command_template(const model::ProcessingTask& task);

    /// The image files removed by `<removefile>` so far.
    const std::set<std::filesystem::path>& removed() const noexcept { return m_removed; }
    /// Tasks run so far, and those that failed (keep_going).
    std::size_t tasks_run() const noexcept { return m_run; }
    std::size_t tasks_failed() const noexcept { return m_failed; }

private:
    ProcessingOptions m_options;
    Context m_context;
    std::set<std::string> m_stand_ins_said;  ///< DIRSIG names whose stand-in was logged
    std::set<std::filesystem::path> m_removed;
    std::size_t m_run = 0;
    std::size_t m_failed = 0;

    std::optional<ProcessingTrust> m_trust;  ///< read on first use

    std::optional<TaskCommand> find(const std::string& program);
    const ProcessingTrust& trust();
    TaskCommand build(const model::ProcessingTask& task, const std::string& shown_basename,
                      const std::string& judged_basename);
    void run_task(const model::ProcessingTask& task, const model::ProcessingEvent& event);
};

}  // namespace glint::process
