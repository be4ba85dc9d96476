// SPDX-License-Identifier: Apache-2.0
// glint::Error and its formatting.
#include "glint/core/error.h"

#include <cstring>

namespace glint {

std::string format_located(const ErrorContext& context, const std::string& message) {
    std::string out;
    if (!context.file.empty()) {
        out += context.file;
        if (context.line > 0) out += ":" + std::to_string(context.line);
        out += ": ";
    }
    if (!context.element.empty()) out += context.element + ": ";
    out += message;
    return out;
}

Error::Error(ErrorCategory category, const std::string& message, ErrorContext context)
    : std::runtime_error(format_located(context, message)),
      m_category(category),
      m_message(message),
      m_context(std::move(context)) {}

Error Error::with_file(const std::string& file, int line) const {
    ErrorContext context = m_context;
    if (context.file.empty()) {
        context.file = file;
        if (context.line == 0) context.line = line;
    }
    return Error(m_category, m_message, std::move(context));
}

Error usage_error(const std::string& message) { return Error(ErrorCategory::usage, message); }

Error input_error(const std::string& message, ErrorContext context) {
    return Error(ErrorCategory::input, message, std::move(context));
}

Error io_error(const std::string& message, const std::string& file) {
    return Error(ErrorCategory::io, message, ErrorContext{file, 0, {}});
}

Error runtime_error(const std::string& message) { return Error(ErrorCategory::runtime, message); }

Error internal_error(const std::string& message) {
    return Error(ErrorCategory::internal, "internal error: " + message);
}

std::string errno_text(int code) {
    char buffer[256];
    // GNU strerror_r returns the message pointer (which may or may not be `buffer`).
    return std::string(strerror_r(code, buffer, sizeof buffer));
}

}  // namespace glint
