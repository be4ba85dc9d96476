// SPDX-License-Identifier: Apache-2.0
// ProcessingRunner (glint/process/processing_runner.h): program lookup (PATH, then glint's
// stand-ins for DIRSIG's image_tool and demosaic), the checks made before a render starts, and
// running an event's tasks through run_process.
#include "glint/process/processing_runner.h"

#include <unistd.h>

#include <sstream>
#include <system_error>
#include <utility>

#include "glint/core/diagnostics.h"
#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/model/names.h"
#include "glint/process/process.h"

namespace glint::process {
namespace {

namespace fs = std::filesystem;

/// The glint tool standing for a DIRSIG program name, or nullptr.
const char* stand_in_for(const std::string& program) {
    if (program == "image_tool") return "glint-envi";
    if (program == "demosaic") return "glint-demosaic";
    return nullptr;
}

bool uses_basename(const model::ProcessingTask& task) {
    for (const std::string& argument : task.arguments) {
        if (argument.find(kImageBasename) != std::string::npos) return true;
    }
    return task.program.find(kImageBasename) != std::string::npos;
}

/// "task 'demosaic' (cam.platform:40)": how logs and errors name a task.
std::string task_name(const model::ProcessingTask& task) {
    std::string name = "processing task " + quote(task.program);
    if (!task.where.file.empty()) {
        name += " (" + task.where.file + ":" + std::to_string(task.where.line) + ")";
    }
    return name;
}

/// "capture_completed of Cam -> Frame (task 1, capture 3)".
std::string event_name(const model::ProcessingEvent& event) {
    return std::string(model::name_of(event.kind)) + " of " + event.focal_plane + " (task " +
           std::to_string(event.task + 1) + ", capture " + std::to_string(event.capture + 1) + ")";
}

/// Logs each line of a task's output stream, prefixed by the task's program.
void log_lines(const Log& log, const std::string& program, const std::string& text) {
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        log.info("[" + program + "] " + line);
    }
}

/// The last non-empty line of `text` (a failing program's message), or "".
std::string last_line(const std::string& text) {
    std::size_t end = text.find_last_not_of("\r\n \t");
    if (end == std::string::npos) return {};
    const std::size_t begin = text.rfind('\n', end);
    return text.substr(begin == std::string::npos ? 0 : begin + 1,
                       end + 1 - (begin == std::string::npos ? 0 : begin + 1));
}

/// Linux's limit on one argument (MAX_ARG_STRLEN: 32 pages of 4 KiB).
constexpr std::size_t kMaxArgumentBytes = 32 * 4096;

/// Why the kernel would refuse (E2BIG) or cut an argv, or nullopt: an argument holding a NUL
/// byte or longer than kMaxArgumentBytes, or all of them with the environment beyond a
/// quarter of ARG_MAX.
std::optional<std::string> argv_problem(const std::vector<std::string>& argv) {
    std::size_t total = 0;
    for (std::size_t i = 0; i < argv.size(); ++i) {
        const std::string what =
            i == 0 ? std::string("the program") : "argument " + std::to_string(i);
        if (argv[i].find('\0') != std::string::npos) {
            return what + " holds a NUL byte, which no program can be given";
        }
        if (argv[i].size() >= kMaxArgumentBytes) {
            return what + " is " + format_byte_size(static_cast<double>(argv[i].size())) +
                   "; the system passes at most 128 KiB in one argument";
        }
        total += argv[i].size() + 1 + sizeof(char*);
    }
    const long arg_max = ::sysconf(_SC_ARG_MAX);
    const std::size_t limit = arg_max > 0 ? static_cast<std::size_t>(arg_max) / 4 : 512 * 1024;
    if (total > limit) {
        return "its arguments are " + format_byte_size(static_cast<double>(total)) +
               " in all; the system passes at most " +
               format_byte_size(static_cast<double>(limit)) +
               " (a quarter of ARG_MAX, the rest left to the environment)";
    }
    return std::nullopt;
}

}  // namespace

std::string substitute_basename(const std::string& text, const std::string& basename) {
    const std::string key = kImageBasename;
    std::string out;
    std::size_t at = 0;
    for (std::size_t found = text.find(key); found != std::string::npos;
         found = text.find(key, at)) {
        out.append(text, at, found - at);
        out += basename;
        at = found + key.size();
    }
    out.append(text, at, std::string::npos);
    return out;
}

ProcessingRunner::ProcessingRunner(ProcessingOptions options, const Context& context)
    : m_options(std::move(options)), m_context(context) {}

std::optional<TaskCommand> ProcessingRunner::find(const std::string& program) {
    const char* path = m_options.path ? m_options.path->c_str() : nullptr;
    TaskCommand command;
    if (program.find('/') != std::string::npos) {
        // A path: relative to glint-render's working directory, as typed on its command line.
        std::error_code ec;
        const fs::path absolute = fs::absolute(program, ec);
        if (ec || !find_program(absolute.string())) return std::nullopt;
        command.program = absolute.lexically_normal();
        return command;
    }
    if (auto found = find_program(program, path)) {
        command.program = fs::absolute(*found).lexically_normal();
        return command;
    }
    const char* glint_tool = stand_in_for(program);
    if (glint_tool == nullptr) return std::nullopt;
    std::optional<fs::path> tool;
    if (!m_options.tools_dir.empty())
        tool = find_program((m_options.tools_dir / glint_tool).string());
    if (!tool) tool = find_program(glint_tool, path);
    if (!tool) return std::nullopt;
    command.program = fs::absolute(*tool).lexically_normal();
    command.stands_for = program;
    return command;
}

const ProcessingTrust& ProcessingRunner::trust() {
    if (!m_trust) {
        if (m_options.allow_all) {
            m_trust.emplace();
            m_trust->allow_all = true;
        } else {
            m_trust = read_allow_list(m_options.allow_list);
            for (const auto& [where, message] : m_trust->warnings) {
                m_context.log.warning(format_located(where, message));
            }
        }
    }
    return *m_trust;
}

TaskCommand ProcessingRunner::command(const model::ProcessingTask& task,
                                      const model::ProcessingEvent& event) {
    const std::string basename = event.file.stem().string();
    return build(task, basename, basename);
}

TaskCommand ProcessingRunner::command_template(const model::ProcessingTask& task) {
    // Judged with a plain stand-in name: the run's own basenames are checked at each event.
    return build(task, kImageBasename, "IMG_BASENAME");
}

TaskCommand ProcessingRunner::build(const model::ProcessingTask& task, const std::string& shown,
                                    const std::string& judged) {
    const std::string program = substitute_basename(task.program, shown);
    std::optional<TaskCommand> command = find(program);
    if (!command) {
        throw input_error(
            "program " + quote(program) +
                (program.find('/') != std::string::npos
                     ? " is not an executable file"
                     : " is not on PATH" +
                           std::string(stand_in_for(program)
                                           ? std::string(" (nor is ") + stand_in_for(program) +
                                                 ", which stands for it)"
                                           : "")),
            task.where);
    }
    command->argv.push_back(command->program.string());
    std::vector<std::string> judged_arguments;
    for (const std::string& argument : task.arguments) {
        command->argv.push_back(substitute_basename(argument, shown));
        judged_arguments.push_back(substitute_basename(argument, judged));
    }
    command->refusal = refusal(substitute_basename(task.program, judged), command->program,
                               judged_arguments, trust());
    if (!command->stands_for.empty() && m_stand_ins_said.insert(command->stands_for).second) {
        m_context.log.info("Processing: no program " + quote(command->stands_for) +
                           " on PATH; running " + command->program.string() + " in its place");
    }
    return *command;
}

void ProcessingRunner::check(const std::vector<model::ProcessingEvent>& events) {
    Diagnostics diagnostics;
    std::set<std::pair<std::string, int>> warned;   // task file:line warned about the basename
    std::set<std::pair<std::string, int>> missing;  // task file:line whose program is missing
    std::set<std::pair<std::string, int>> early_removal;  // removefile before completion
    std::set<std::pair<std::string, int>> refused;        // task file:line the user has not allowed
    for (const model::ProcessingEvent& event : events) {
        for (const model::ProcessingTask& task : event.tasks) {
            const auto key = std::make_pair(task.where.file, task.where.line);
            if (task.remove_file && !event.file_complete) {
                if (!early_removal.insert(key).second) continue;
                diagnostics.error(task.where,
                                  "<removefile> at " + std::string(model::name_of(event.kind)) +
                                      " would remove " + event.file.filename().string() +
                                      " before it is complete (its <imagefile> schedule "
                                      "writes more captures into it); run the task at the "
                                      "event that completes the file");
                continue;
            }
            if (uses_basename(task) && !event.file_complete && warned.insert(key).second) {
                diagnostics.warning(
                    task.where, std::string(kImageBasename) + " at " + model::name_of(event.kind) +
                                    " names " + event.file.stem().string() +
                                    ", whose image is not complete then (glint publishes an "
                                    "image when its last capture is written): the program "
                                    "will not find it");
            }
            try {
                const TaskCommand planned = command(task, event);
                if (planned.refusal && refused.insert(key).second) {
                    diagnostics.error(task.where, *planned.refusal);
                }
                if (auto problem = argv_problem(planned.argv);
                    problem && refused.insert(key).second) {
                    diagnostics.error(task.where, *problem);
                }
            } catch (const Error& e) {
                if (!missing.insert(key).second) continue;
                if (m_options.keep_going) {
                    diagnostics.warning(e.context(), e.message() + " (--keep-going: skipped)");
                } else {
                    diagnostics.error(e.context(), e.message());
                }
            }
        }
    }
    diagnostics.log_to(m_context.log);
    if (diagnostics.has_errors()) {
        throw input_error(nothing_written_message(diagnostics.error_count()));
    }
}

void ProcessingRunner::run_task(const model::ProcessingTask& task,
                                const model::ProcessingEvent& event) {
    std::optional<TaskCommand> command;
    try {
        command = this->command(task, event);
    } catch (const Error&) {
        if (!m_options.keep_going) throw;
        ++m_failed;  // check() warned that it is skipped
        return;
    }
    if (command->refusal) {  // check() refused it before the render began
        throw input_error(*command->refusal, task.where);
    }
    // DIRSIG prints a task's <message> as it runs: so does glint, at normal verbosity.
    if (!task.message.empty()) m_context.log.notice(task.message);
    ProcessOptions options;
    options.argv = command->argv;
    // Tasks run in the image's folder, which a *_started event may find not yet created.
    options.working_directory = event.file.parent_path();
    if (!options.working_directory.empty()) {
        std::error_code ec;
        fs::create_directories(options.working_directory, ec);
        if (ec) {
            throw io_error("cannot create the folder of " + task_name(task) + ": " + ec.message(),
                           options.working_directory.string());
        }
    }
    options.timeout = m_options.timeout;
    options.cancel = m_context.cancel;
    options.stdout_mode = OutputMode::capture;
    // Every command is shown as it starts (make's rule): what a simulation runs is never a
    // surprise.
    m_context.log.notice("Processing at " + event_name(event) + ": " +
                         format_command_line(command->argv));
    ProcessResult result;
    try {
        result = run_process(options);  // throws cancelled on an interrupt
    } catch (const Error& e) {
        if (e.category() == ErrorCategory::cancelled) throw;
        // A program that cannot be started (E2BIG, ENOEXEC, ...) is named with its task.
        throw Error(e.category(), task_name(task) + " at " + event_name(event) + ": " + e.what());
    }
    ++m_run;
    const std::string program = fs::path(task.program).filename().string();
    log_lines(m_context.log, program, result.stdout_text);
    log_lines(m_context.log, program, result.stderr_text);
    if (result.success()) return;
    ++m_failed;
    std::string message = task_name(task) + " at " + event_name(event) + ": " +
                          command->program.string() + " " + result.describe();
    if (const std::string said = last_line(result.stderr_text); !said.empty()) {
        message += " (its last words: " + quote(said, 200) + ")";
    }
    if (!m_options.keep_going) throw runtime_error(message);
    m_context.log.warning(message + "; --keep-going: the render goes on");
}

void ProcessingRunner::run(const model::ProcessingEvent& event) {
    const std::size_t failed = m_failed;
    bool remove = false;
    for (const model::ProcessingTask& task : event.tasks) {
        run_task(task, event);
        remove = remove || task.remove_file;
    }
    if (!remove) return;
    if (m_failed != failed) {
        m_context.log.warning("Processing at " + event_name(event) + ": " +
                              event.file.filename().string() +
                              " is kept, since a task failed (<removefile> not applied)");
        return;
    }
    for (const fs::path& file : {event.file, fs::path(event.file.string() + ".hdr")}) {
        std::error_code ec;
        fs::remove(file, ec);
        if (ec) throw io_error("cannot remove (<removefile>): " + ec.message(), file.string());
    }
    m_removed.insert(event.file);
    m_context.log.info("Processing: removed " + event.file.string() + " (<removefile>)");
}

}  // namespace glint::process
