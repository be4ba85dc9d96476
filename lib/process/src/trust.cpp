// SPDX-License-Identifier: Apache-2.0
// Which programs processing tasks may start (glint/process/trust.h): the default programs and
// their argument rule, the allow-list file and the decision for one command.
#include "glint/process/trust.h"

#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string_view>
#include <system_error>

#include "glint/core/text.h"

namespace glint::process {
namespace {

namespace fs = std::filesystem;

constexpr std::array<std::string_view, 5> kDefaultPrograms = {
    "image_tool", "demosaic", "ffmpeg", "glint-envi", "glint-demosaic"};

/// An allow-list is a few lines; a bigger file is not one.
constexpr std::uintmax_t kMaxAllowListBytes = 1 << 20;

constexpr std::string_view kPlainCharacters =
    "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_./=:,+%@-";

bool is_scheme_character(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
           c == '+' || c == '.' || c == '-';
}

/// True when `part` starts with a URL scheme or an ffmpeg protocol: a letter, at least one
/// more of letters, digits, '+', '.', '-', then ':' ("http:", "file:", "concat:").
bool starts_with_scheme(std::string_view part) {
    if (part.empty() || !((part[0] >= 'a' && part[0] <= 'z') || (part[0] >= 'A' && part[0] <= 'Z'))) {
        return false;
    }
    std::size_t i = 1;
    while (i < part.size() && is_scheme_character(part[i])) ++i;
    return i >= 2 && i < part.size() && part[i] == ':';
}

/// True when a '/'- or ':'-separated component of `part` is "..".
bool has_parent_component(std::string_view part) {
    std::size_t start = 0;
    while (start <= part.size()) {
        std::size_t end = part.find_first_of("/:", start);
        if (end == std::string_view::npos) end = part.size();
        if (part.substr(start, end - start) == "..") return true;
        start = end + 1;
    }
    return false;
}

/// The problem of one part of an argument, or nullopt.
std::optional<std::string> part_problem(std::string_view part) {
    if (!part.empty() && part.front() == '/') return "an absolute path";
    if (starts_with_scheme(part)) return "a URL or protocol (" + std::string(part.substr(0, part.find(':') + 1)) + ")";
    if (has_parent_component(part)) return "a '..' component (a file outside the output folder)";
    return std::nullopt;
}

std::string allow_hint(const std::string& entry, const ProcessingTrust& trust) {
    std::string hint = "allow it with --allow-processing for this run";
    if (!trust.allow_list.empty()) {
        hint += ", or with the line " + quote(entry) + " in " + trust.allow_list.string();
    }
    return hint + " (docs/processing.md, \"Which programs run\")";
}

bool allowed_by_list(const std::string& program, const fs::path& resolved,
                     const ProcessingTrust& trust) {
    std::error_code ec;
    const fs::path canonical = fs::canonical(resolved, ec);
    for (const AllowedProgram& allowed : trust.allowed) {
        if (allowed.canonical.empty()) {
            if (allowed.entry == program && program.find('/') == std::string::npos) return true;
        } else if (!ec && allowed.canonical == canonical) {
            return true;
        }
    }
    return false;
}

}  // namespace

bool is_default_program(const std::string& program) {
    for (std::string_view name : kDefaultPrograms) {
        if (program == name) return true;
    }
    return false;
}

std::string default_programs_text() {
    std::vector<std::string_view> names(kDefaultPrograms.begin(), kDefaultPrograms.end());
    return join(names, ", ", " and ");
}

std::optional<std::string> argument_problem(const std::string& argument) {
    const std::size_t odd = argument.find_first_not_of(kPlainCharacters);
    if (odd != std::string::npos) {
        return "holds " + quote(argument.substr(odd, 1)) +
               " (only letters, digits and _ . / = : , + % @ - are given to a default program)";
    }
    if (auto problem = part_problem(argument)) return "is " + *problem;
    std::size_t start = 0;
    while (start <= argument.size()) {
        std::size_t end = argument.find_first_of("=,", start);
        if (end == std::string::npos) end = argument.size();
        if (auto problem = part_problem(std::string_view(argument).substr(start, end - start))) {
            return "holds " + *problem;
        }
        start = end + 1;
    }
    return std::nullopt;
}

fs::path allow_list_path(const char* glint_allowed_programs, const char* xdg_config_home,
                         const char* home) {
    const auto set = [](const char* value) { return value != nullptr && *value != '\0'; };
    if (set(glint_allowed_programs)) return fs::path(glint_allowed_programs);
    if (set(xdg_config_home)) return fs::path(xdg_config_home) / "glint" / kAllowListName;
    if (set(home)) return fs::path(home) / ".config" / "glint" / kAllowListName;
    return {};
}

fs::path allow_list_from_environment() {
    return allow_list_path(std::getenv("GLINT_ALLOWED_PROGRAMS"), std::getenv("XDG_CONFIG_HOME"),
                           std::getenv("HOME"));
}

ProcessingTrust read_allow_list(const fs::path& file) {
    ProcessingTrust trust;
    trust.allow_list = file;
    if (file.empty()) return trust;
    struct stat info {};
    if (::stat(file.c_str(), &info) != 0) {
        if (errno == ENOENT || errno == ENOTDIR) return trust;  // no list: nothing allowed
        throw io_error("cannot read the processing allow-list: " + errno_text(errno),
                       file.string());
    }
    const ErrorContext whole{file.string(), 0, {}};
    if (!S_ISREG(info.st_mode)) {
        throw input_error("the processing allow-list is not a regular file", whole);
    }
    if (info.st_uid != ::geteuid() && info.st_uid != 0) {
        throw input_error("the processing allow-list belongs to another user (uid " +
                              std::to_string(info.st_uid) +
                              "), who could allow any program; it must be yours (or root's)",
                          whole);
    }
    if ((info.st_mode & (S_IWGRP | S_IWOTH)) != 0) {
        throw input_error("the processing allow-list is writable by " +
                              std::string((info.st_mode & S_IWOTH) != 0 ? "anyone" : "its group") +
                              ", who could allow any program; make it yours alone (chmod go-w)",
                          whole);
    }
    if (static_cast<std::uintmax_t>(info.st_size) > kMaxAllowListBytes) {
        throw input_error("the processing allow-list is " +
                              format_byte_size(static_cast<double>(info.st_size)) +
                              "; an allow-list of programs is at most 1 MiB",
                          whole);
    }
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in.good() && !in.eof()) {
        throw io_error("cannot read the processing allow-list", file.string());
    }
    const std::string content = text.str();
    const std::vector<std::string_view> lines = split_lines(content);
    for (std::size_t i = 0; i < lines.size(); ++i) {
        std::string_view line = lines[i];
        if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) {
            line = line.substr(0, hash);
        }
        line = trim(line);
        if (line.empty()) continue;
        AllowedProgram allowed;
        allowed.entry = std::string(line);
        allowed.where = ErrorContext{file.string(), static_cast<int>(i + 1), {}};
        if (allowed.entry.find('/') != std::string::npos) {
            if (allowed.entry.front() != '/') {
                throw input_error("allow-list entry " + quote(allowed.entry) +
                                      " is a relative path; give a program name (found on PATH) "
                                      "or an absolute path",
                                  allowed.where);
            }
            std::error_code ec;
            allowed.canonical = fs::canonical(allowed.entry, ec);
            if (ec) {
                trust.warnings.emplace_back(
                    allowed.where, "allow-list entry " + quote(allowed.entry) +
                                       " names no file here: it allows nothing");
                continue;
            }
        }
        trust.allowed.push_back(std::move(allowed));
    }
    return trust;
}

std::optional<std::string> refusal(const std::string& program, const fs::path& resolved,
                                   const std::vector<std::string>& arguments,
                                   const ProcessingTrust& trust) {
    if (trust.allow_all || allowed_by_list(program, resolved, trust)) return std::nullopt;
    const bool bare = program.find('/') == std::string::npos;
    if (!bare || !is_default_program(program)) {
        // The entry that would allow it: the name, or the path (absolute, as it resolves).
        const std::string entry =
            bare || program.front() == '/' ? program : resolved.string();
        return "program " + quote(program) + (bare ? " (" + resolved.string() + ")" : "") +
               " is not one glint runs by default (" + default_programs_text() +
               "): a program a simulation names runs only when you allow it; " +
               allow_hint(entry, trust);
    }
    for (std::size_t i = 0; i < arguments.size(); ++i) {
        if (auto problem = argument_problem(arguments[i])) {
            return "argument " + std::to_string(i + 1) + " of " + program + ", " +
                   quote(arguments[i]) + ", " + *problem +
                   ": glint runs its default programs only with arguments that stay in the "
                   "output folder; " +
                   allow_hint(program, trust);
        }
    }
    return std::nullopt;
}

}  // namespace glint::process
