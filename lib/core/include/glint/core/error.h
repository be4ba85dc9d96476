// SPDX-License-Identifier: Apache-2.0
// glint::Error, the one exception type of the project. Library code throws it for every
// failure; the tool runner turns it into a one-line diagnostic and an exit status.
#pragma once

#include <stdexcept>
#include <string>

namespace glint {

/// What kind of failure an Error reports; the tool runner maps it to an exit status.
enum class ErrorCategory {
    usage,      ///< the command line is wrong (exit 2)
    input,      ///< an input file or value is malformed or inconsistent (exit 1)
    io,         ///< the file system or an external program failed (exit 1)
    runtime,    ///< a computation could not be carried out (exit 1)
    cancelled,  ///< the user interrupted the run (exit 130)
    internal,   ///< a bug in glint (exit 1)
};

/// Where in an input an error was found. Every field is optional; empty/zero means unknown.
struct ErrorContext {
    std::string file;     ///< path as the user named it
    int line = 0;         ///< 1-based line number in `file`, 0 if unknown
    std::string element;  ///< element path or key, e.g. "<instance>" or "data type"
};

/// The project's exception: a category, a message, and where in the input it happened.
/// `what()` reads "file:line: element: message" with the unknown parts left out.
class Error : public std::runtime_error {
public:
    Error(ErrorCategory category, const std::string& message, ErrorContext context = {});

    ErrorCategory category() const noexcept { return m_category; }
    /// The message without its location prefix.
    const std::string& message() const noexcept { return m_message; }
    const ErrorContext& context() const noexcept { return m_context; }

    /// A copy of this error with the file (and line, if given) filled in where unknown.
    /// Used at component boundaries to add context to an error raised deeper down.
    Error with_file(const std::string& file, int line = 0) const;

private:
    ErrorCategory m_category;
    std::string m_message;
    ErrorContext m_context;
};

/// Shorthands for the common categories.
Error usage_error(const std::string& message);
Error input_error(const std::string& message, ErrorContext context = {});
Error io_error(const std::string& message, const std::string& file = {});
Error runtime_error(const std::string& message);
Error internal_error(const std::string& message);

/// Formats a location and message as "file:line: element: message".
std::string format_located(const ErrorContext& context, const std::string& message);

/// The text of errno `code`, e.g. "No such file or directory".
std::string errno_text(int code);

}  // namespace glint
