// SPDX-License-Identifier: Apache-2.0
// gtest helpers for readers that report to glint::Diagnostics: all messages as text, and the
// one error a bad-input case must produce.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "glint/core/diagnostics.h"

namespace glint::test {

/// Every diagnostic, one "file:line: element: message" per line (for failure output).
inline std::string diagnostics_text(const Diagnostics& diagnostics) {
    std::string text;
    for (const Diagnostic& d : diagnostics.items()) text += d.text() + "\n";
    return text;
}

/// The single error of `diagnostics`; a test failure when there is not exactly one.
inline Diagnostic only_error(const Diagnostics& diagnostics) {
    EXPECT_EQ(diagnostics.error_count(), 1u) << diagnostics_text(diagnostics);
    for (const Diagnostic& d : diagnostics.items()) {
        if (d.severity == Diagnostic::Severity::error) return d;
    }
    ADD_FAILURE() << "no error";
    return {};
}

}  // namespace glint::test
