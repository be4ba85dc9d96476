// SPDX-License-Identifier: Apache-2.0
// Fuzz target: the platform motion reader (dirsig::read_motion), GenericMotion `.ppd` and
// FlexMotion `.motion` (told apart by the root element; the corpus holds both), the input
// served from memory.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "glint/dirsig/motion_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glint;
    const dirsig::ReadOptions options =
        fuzz::memory_options("input.motion", fuzz::as_text(data, size));
    return fuzz::run([&](Diagnostics& diagnostics) {
        (void)dirsig::read_motion(fuzz::kFolder / "input.motion", options, diagnostics);
    });
}
