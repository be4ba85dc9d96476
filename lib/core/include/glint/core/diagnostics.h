// SPDX-License-Identifier: Apache-2.0
// Diagnostics: the errors and warnings found while reading an input, collected so that a
// reader can report every problem of a file at once instead of stopping at the first.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "glint/core/error.h"
#include "glint/core/log.h"

namespace glint {

/// One problem found in an input, with where it was found.
struct Diagnostic {
    enum class Severity { error, warning };
    Severity severity = Severity::error;
    ErrorContext where;
    std::string message;
    /// For the line that stands for diagnostics left off (Diagnostics::append_capped): how
    /// many errors and warnings it stands for; 0 and 0 for any other diagnostic, which counts
    /// as one of its severity.
    std::size_t errors_left_off = 0;
    std::size_t warnings_left_off = 0;

    /// "file:line: element: message".
    std::string text() const { return format_located(where, message); }
};

/// The one-line summary of a run stopped by its inputs: "nothing written: N error(s) in the
/// inputs".
std::string nothing_written_message(std::size_t errors);

/// The most diagnostics a reader reports for one file (append_capped); the rest are counted.
inline constexpr std::size_t kMaxDiagnosticsPerFile = 20;

/// An ordered list of diagnostics. Readers add to it and go on; the caller decides when
/// errors are fatal (throw_if_errors) and where warnings go (log_to).
class Diagnostics {
public:
    void error(ErrorContext where, std::string message);
    void warning(ErrorContext where, std::string message);
    /// Records a glint::Error raised by a nested reader as an error diagnostic.
    void add(const Error& error);
    /// Appends a diagnostic of another list as it is (counted as it was there), at `where`
    /// when given.
    void copy(const Diagnostic& d);
    void copy(const Diagnostic& d, ErrorContext where);
    /// Appends the diagnostics of `other` in order, keeping at most `per_file` of each file
    /// (Diagnostic::where.file); those left off become one diagnostic per file at its end,
    /// "… and N more (E errors, W warnings)", an error when any left off is one. The counts
    /// below count those left off, not the line that stands for them.
    void append_capped(const Diagnostics& other, std::size_t per_file = kMaxDiagnosticsPerFile);

    const std::vector<Diagnostic>& items() const { return m_items; }
    /// Every error and warning found, those append_capped left off included.
    std::size_t error_count() const { return m_errors; }
    std::size_t warning_count() const { return m_warnings; }
    bool has_errors() const { return m_errors > 0; }

    /// Writes every diagnostic to `log` (errors at error level, warnings at warning level).
    void log_to(const Log& log) const;
    /// Throws glint::Error(input) carrying the first error (and how many more there are)
    /// when there is any error.
    void throw_if_errors() const;
    /// For a catch block around a load that filled these diagnostics: logs them all, then
    /// throws. An input error when errors were logged becomes one summary ("nothing
    /// written: N errors in the inputs"; `error` itself is logged first unless it is the
    /// first logged error that throw_if_errors raised), so no problem is printed twice;
    /// anything else is rethrown as it is.
    [[noreturn]] void log_and_rethrow(const Error& error, const Log& log) const;

private:
    std::vector<Diagnostic> m_items;
    std::size_t m_errors = 0;
    std::size_t m_warnings = 0;
};

}  // namespace glint
