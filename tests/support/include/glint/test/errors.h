// SPDX-License-Identifier: Apache-2.0
// The message of the glint::Error a callable throws, for bad-input assertions.
#pragma once

#include <string>

#include "glint/core/error.h"

namespace glint::test {

/// Runs `f` and returns what() of the glint::Error it throws ("" when it throws none).
template <typename F>
std::string error_text(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace glint::test
