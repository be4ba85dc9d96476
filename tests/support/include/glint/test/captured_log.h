// SPDX-License-Identifier: Apache-2.0
// A glint::Log for tests that keeps every message with its level, for asserting what a
// component said and at which level.
#pragma once

#include <memory>
#include <string>

#include "glint/core/log.h"

namespace glint::test {

/// Keeps every message logged through log() as "level: message\n" (copies share the text).
class CapturedLog {
public:
    /// A Log writing here, with every level at or above `threshold`.
    Log log(LogLevel threshold = LogLevel::debug) const {
        auto keep = m_text;
        return Log(
            [keep](LogLevel level, const std::string& message) {
                *keep += std::string(log_level_name(level)) + ": " + message + "\n";
            },
            threshold);
    }
    /// Everything said so far.
    const std::string& text() const { return *m_text; }

private:
    std::shared_ptr<std::string> m_text = std::make_shared<std::string>();
};

}  // namespace glint::test
