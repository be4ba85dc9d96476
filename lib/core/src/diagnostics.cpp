// SPDX-License-Identifier: Apache-2.0
// Diagnostics: collecting, logging and summarising the problems found in an input.
#include "glint/core/diagnostics.h"

#include <algorithm>
#include <map>

#include "glint/core/text.h"

namespace glint {

void Diagnostics::error(ErrorContext where, std::string message) {
    m_items.push_back(
        Diagnostic{Diagnostic::Severity::error, std::move(where), std::move(message), 0, 0});
    ++m_errors;
}

void Diagnostics::warning(ErrorContext where, std::string message) {
    m_items.push_back(
        Diagnostic{Diagnostic::Severity::warning, std::move(where), std::move(message), 0, 0});
    ++m_warnings;
}

void Diagnostics::add(const Error& error) { this->error(error.context(), error.message()); }

void Diagnostics::copy(const Diagnostic& d) { copy(d, d.where); }

void Diagnostics::copy(const Diagnostic& d, ErrorContext where) {
    Diagnostic copied = d;
    copied.where = std::move(where);
    if (d.errors_left_off + d.warnings_left_off > 0) {
        m_errors += d.errors_left_off;
        m_warnings += d.warnings_left_off;
    } else {
        ++(d.severity == Diagnostic::Severity::error ? m_errors : m_warnings);
    }
    m_items.push_back(std::move(copied));
}

void Diagnostics::append_capped(const Diagnostics& other, std::size_t per_file) {
    struct Count {
        std::size_t kept = 0;
        std::size_t errors = 0;    ///< left off
        std::size_t warnings = 0;  ///< left off
    };
    std::map<std::string, Count> counts;
    std::vector<std::string> order;  // files with diagnostics left off, as first met
    for (const Diagnostic& d : other.m_items) {
        Count& count = counts[d.where.file];
        const bool is_error = d.severity == Diagnostic::Severity::error;
        if (count.kept < per_file) {
            ++count.kept;
            copy(d);
            continue;
        }
        if (count.errors + count.warnings == 0) order.push_back(d.where.file);
        ++(is_error ? count.errors : count.warnings);
    }
    for (const std::string& file : order) {
        const Count& count = counts[file];
        const std::string message = "… and " + std::to_string(count.errors + count.warnings) +
                                    " more (" + plural(count.errors, "error") + ", " +
                                    plural(count.warnings, "warning") + ") not shown";
        // The line stands for what it counts: those are counted, it is not.
        copy(Diagnostic{
            count.errors > 0 ? Diagnostic::Severity::error : Diagnostic::Severity::warning,
            ErrorContext{file, 0, {}}, message, count.errors, count.warnings});
    }
}

void Diagnostics::log_to(const Log& log) const {
    for (const Diagnostic& d : m_items) {
        if (d.severity == Diagnostic::Severity::error) {
            log.error(d.text());
        } else {
            log.warning(d.text());
        }
    }
}

void Diagnostics::throw_if_errors() const {
    if (m_errors == 0) return;
    for (const Diagnostic& d : m_items) {
        if (d.severity != Diagnostic::Severity::error) continue;
        std::string message = d.message;
        if (m_errors > 1) {
            message += " (and " + std::to_string(m_errors - 1) + " more error" +
                       (m_errors > 2 ? "s" : "") + ")";
        }
        throw input_error(message, d.where);
    }
}

std::string nothing_written_message(std::size_t errors) {
    return "nothing written: " + std::to_string(errors) + " error" + (errors == 1 ? "" : "s") +
           " in the inputs";
}

void Diagnostics::log_and_rethrow(const Error& error, const Log& log) const {
    log_to(log);
    if (error.category() != ErrorCategory::input || m_errors == 0) throw error;
    const auto first = std::find_if(m_items.begin(), m_items.end(), [](const Diagnostic& d) {
        return d.severity == Diagnostic::Severity::error;
    });
    const bool raised_here = first != m_items.end() && first->where.file == error.context().file &&
                             first->where.line == error.context().line &&
                             error.message().rfind(first->message, 0) == 0;
    std::size_t count = m_errors;
    if (!raised_here) {
        log.error(error.what());
        ++count;
    }
    throw input_error(nothing_written_message(count));
}

}  // namespace glint
