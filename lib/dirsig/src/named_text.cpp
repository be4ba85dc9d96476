// SPDX-License-Identifier: Apache-2.0
// Small named text files (named_text.h).
#include "named_text.h"

#include "glint/core/error.h"

namespace glint::dirsig::detail {

std::optional<std::string> read_named_text(const std::filesystem::path& file,
                                           const std::string& name, const std::string& what,
                                           const ReadOptions& options, Diagnostics& diagnostics) {
    try {
        return options.read_text(file, name);
    } catch (const Error& error) {
        // "cannot open file: <reason>" from the reader, said of the file's role.
        const std::string prefix = "cannot open file: ";
        const std::string& message = error.message();
        diagnostics.error(ErrorContext{name, 0, ""},
                          message.rfind(prefix, 0) == 0
                              ? "cannot open " + what + ": " + message.substr(prefix.size())
                              : message);
        return std::nullopt;
    }
}

}  // namespace glint::dirsig::detail
