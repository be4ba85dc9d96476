// SPDX-License-Identifier: Apache-2.0
// The streaming loop of glint-detect: blocks of lines read in order, converted by the
// detection chain on several threads, written in order. Memory is bounded by the block.
#pragma once

#include "glint/core/context.h"
#include "glint/detect/chain.h"
#include "glint/io/envi.h"
#include "input.h"

namespace glint::app_detect::internal {

/// Reads every line of `reader`, converts it with `chain` (its LineKey from `map`) on
/// `threads` threads (0 = all cores) and appends it to `writer`. Output bytes do not depend
/// on the thread count. Rethrows the error of the earliest failing line; checks the cancel
/// flag between blocks.
void stream_lines(io::EnviReader& reader, io::EnviWriter& writer,
                  const detect::DetectionChain& chain, const CaptureMap& map, unsigned threads,
                  Context& ctx);

}  // namespace glint::app_detect::internal
