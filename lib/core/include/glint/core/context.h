// SPDX-License-Identifier: Apache-2.0
// The per-run context every tool entry point receives: log, progress, cancellation and the
// common options (threads, seed). No state lives anywhere else.
#pragma once

#include <cstdint>

#include "glint/core/cancel.h"
#include "glint/core/log.h"
#include "glint/core/progress.h"

namespace glint {

/// Default `--seed` of every tool: fixed, so that two runs without --seed are identical.
inline constexpr std::uint64_t kDefaultSeed = 1;

/// What a library entry point needs besides its options.
struct Context {
    Log log;
    Progress progress;
    CancelToken cancel;
    unsigned threads = 0;  ///< 0 = all hardware threads
    std::uint64_t seed = kDefaultSeed;
};

}  // namespace glint
