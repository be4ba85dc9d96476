// SPDX-License-Identifier: Apache-2.0
// Fuzz target: the DIRSIG4 .sim reader (dirsig::read_sim), the input served from memory as a .sim
// file.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "glint/dirsig/readers.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glint;
    const dirsig::ReadOptions options =
        fuzz::memory_options("input.sim", fuzz::as_text(data, size));
    return fuzz::run([&](Diagnostics& diagnostics) {
        (void)dirsig::read_sim(fuzz::kFolder / "input.sim", options, diagnostics);
    });
}
